// An inertial measurement unit fixed to a body (docs/physics.md §10.1): what
// it reads over each sample period from the body's motion, with seeded
// white noise, bias random walks and orientation noise. ROS-free; the node
// turns readings into sensor_msgs/Imu (REP 145).
#pragma once

#include <cstdint>
#include <random>

#include "rigid_body_sim/core/bodies/geometry.h"
#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"

namespace rigid_body_sim::core {

/// An IMU's settings (config `imu`, `bodies[i].imu`). Noise σs are per
/// sample (as Gazebo's <noise><stddev>); a bias walk σ_b makes the bias's
/// variance grow as σ_b² t.
struct ImuSettings {
  Pose X_LS;                       ///< the sensor frame S in the body's root link frame L (m)
  double rate = 100.0;             ///< samples per second of sim time (Hz)
  std::uint64_t seed = 0;          ///< of the noise: the same seed, the same readings
  double gyro_noise = 0.0;         ///< rad/s, σ of each axis of each sample
  double accel_noise = 0.0;        ///< m/s², σ of each axis of each sample
  double gyro_bias_walk = 0.0;     ///< rad/s/√s
  double accel_bias_walk = 0.0;    ///< m/s²/√s
  double orientation_noise = 0.0;  ///< rad, σ of each axis of a small rotation
};

/// Throws std::invalid_argument naming `key`.FIELD: a rate above 1/dt or
/// not positive, a negative or non-finite σ, a mount beyond the model's reach.
void validateImu(const ImuSettings& s, double dt, const std::string& key);

/// One sample, over the period that ends at its time.
struct ImuReading {
  Quat q_WS = Quat::Identity();  ///< orientation of S in the world
  Vec3 w_S = Vec3::Zero();       ///< angular velocity, S axes (rad/s)
  Vec3 f_S = Vec3::Zero();       ///< specific force (acceleration − gravity), S axes (m/s²): +g up at rest
};

/// The exact reading over [previous, now] (period s) of a sensor at X_LS in
/// a link L, from the sensor point's velocity change (impulses included)
/// and the rotation between: ω_S = log(q_WS(prev)⁻¹ q_WS(now)) / period;
/// f = Δv_WS / period − g, expressed in S halfway through the rotation. A
/// free body's root link, or any link of a robot.
ImuReading exactImuReading(const LinkState& previous, const LinkState& now, const Pose& X_LS, const Vec3& gravity_W,
                           double period);
/// The same for a body's root link.
ImuReading exactImuReading(const BodyModel& body, const BodyState& previous, const BodyState& now, const Pose& X_LS,
                           const Vec3& gravity_W, double period);

/// An IMU's noise and memory: its link's state at its last sample, its
/// biases, its random numbers.
class Imu {
 public:
  /// Starts at `now` (its link's): the first sample covers the period after it.
  explicit Imu(const ImuSettings& settings, const LinkState& now = {});

  /// The reading of the period ending at `now` (settings().rate apart),
  /// with noise; then `now` is the start of the next period.
  ImuReading sample(const LinkState& now, const Vec3& gravity_W, double period);
  /// The same on a body's root link.
  ImuReading sample(const BodyModel& body, const BodyState& now, const Vec3& gravity_W, double period) {
    return sample(linkState(body, now), gravity_W, period);
  }

  /// Forgets the last sample (after the link was put somewhere, a reset or
  /// set_state): the next period starts at `now`.
  void restart(const LinkState& now) { previous_ = now; }

  const ImuSettings& settings() const { return settings_; }
  const Vec3& gyroBias() const { return gyro_bias_; }
  const Vec3& accelBias() const { return accel_bias_; }

 private:
  Vec3 gaussian(double sigma);

  ImuSettings settings_;
  LinkState previous_;
  Vec3 gyro_bias_ = Vec3::Zero(), accel_bias_ = Vec3::Zero();
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_;
};

}  // namespace rigid_body_sim::core
