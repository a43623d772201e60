// Sensors that read where on the Earth a link is (docs/physics.md §10.9):
// a GNSS receiver's fix and velocity and a magnetometer's field, as
// hector_gazebo_plugins' gazebo_ros_gps and gazebo_ros_magnetic define
// them, each with hector's error model (an offset, a drift, white noise).
// ROS-free.
#pragma once

#include <cstdint>
#include <random>
#include <string>

#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

/// The error of a three-axis reading, per axis of the reading: a constant
/// `offset`, a `drift` (first-order Gauss-Markov: σ `drift` once settled,
/// its memory fading at `drift_frequency`, 1/s) and white noise of σ
/// `gaussian_noise` on each sample. Units: the reading's.
struct SensorErrorSettings {
  Vec3 offset = Vec3::Zero();
  Vec3 drift = Vec3::Zero();
  Vec3 drift_frequency = Vec3::Constant(1.0 / 3600.0);
  Vec3 gaussian_noise = Vec3::Zero();
};

/// Throws std::invalid_argument naming `key`.FIELD: a value not finite, a
/// σ or a frequency below 0.
void validateSensorError(const SensorErrorSettings& s, const std::string& key);

/// A reading's error as it evolves: its drift and its random numbers.
class SensorError {
 public:
  SensorError(const SensorErrorSettings& settings, std::uint64_t seed);

  /// The error of a sample `elapsed` s after the last: the drift moves
  /// (exactly, whatever the interval), then offset + drift + white noise.
  Vec3 sample(double elapsed);
  /// The drift now, and a shift of it (a GNSS's velocity drift moves its position's).
  const Vec3& drift() const { return drift_; }
  void shiftDrift(const Vec3& by) { drift_ += by; }
  /// drift² + gaussian_noise² per axis: the variance hector reports.
  Vec3 variance() const;
  /// The drift from zero and the random numbers from the seed (a reset).
  void restart();

 private:
  double gaussian(double sigma);

  SensorErrorSettings settings_;
  std::uint64_t seed_;
  Vec3 drift_ = Vec3::Zero();
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

/// Where the world frame is on the Earth: its origin's WGS84 latitude and
/// longitude (deg), its altitude (m), and the heading of its x axis (deg
/// clockwise from north: 0 puts x north and y west, 90 x east and y north).
struct GeoReference {
  double latitude = 49.9;
  double longitude = 8.9;
  double altitude = 0.0;
  double heading = 0.0;
};

/// Throws std::invalid_argument naming `key`.FIELD: a latitude beyond
/// ±89°, a longitude beyond ±180°, a value not finite.
void validateGeoReference(const GeoReference& r, const std::string& key);

struct GnssSettings {
  GeoReference reference;
  SensorErrorSettings position;  ///< m, world axes
  SensorErrorSettings velocity;  ///< m/s, world axes; its drift moves the position's
  std::uint64_t seed = 0;
};

/// Throws std::invalid_argument naming `key`.FIELD (validateGeoReference,
/// validateSensorError of each).
void validateGnss(const GnssSettings& s, const std::string& key);

struct GnssFix {
  double latitude = 0.0, longitude = 0.0;       ///< deg
  double altitude = 0.0;                        ///< m
  Vec3 v_NWU = Vec3::Zero();                    ///< m/s: north, west, up (hector's axes)
  Mat3 position_covariance_ENU = Mat3::Zero();  ///< m², east, north, up (sensor_msgs/NavSatFix's)
};

/// The fix of a point at p_W moving at v_W, on the plane tangent to the
/// WGS84 ellipsoid at the reference (hector's model): north and east
/// over the meridian and the prime-vertical radii there.
GnssFix exactGnssFix(const GeoReference& reference, const Vec3& p_W, const Vec3& v_W);

class Gnss {
 public:
  explicit Gnss(const GnssSettings& settings);
  /// The fix of p_W moving at v_W, `elapsed` s after the last.
  GnssFix report(const Vec3& p_W, const Vec3& v_W, double elapsed);
  void restart();
  const GnssSettings& settings() const { return settings_; }

 private:
  GnssSettings settings_;
  SensorError position_, velocity_;
};

struct MagnetometerSettings {
  double magnitude = 1.0;     ///< the field's strength, in what the messages carry (hector's default 1)
  double heading = 90.0;      ///< deg: the world's x axis, clockwise from north
  double declination = 0.0;   ///< deg: magnetic north, east of true north
  double inclination = 60.0;  ///< deg: the field below the horizon
  SensorErrorSettings error;  ///< in the sensor's axes
  std::uint64_t seed = 0;
};

/// Throws std::invalid_argument naming `key`.FIELD.
void validateMagnetometer(const MagnetometerSettings& s, const std::string& key);

/// The Earth's field in the world frame.
Vec3 magneticField_W(const MagnetometerSettings& s);

class Magnetometer {
 public:
  explicit Magnetometer(const MagnetometerSettings& settings);
  /// The field in the axes of a sensor at q_WS, `elapsed` s after the last sample.
  Vec3 report(const Quat& q_WS, double elapsed);
  void restart() { error_.restart(); }

 private:
  Vec3 field_W_;
  SensorError error_;
};

}  // namespace rigid_body_sim::core
