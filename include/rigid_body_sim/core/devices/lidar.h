// A scanning range sensor (docs/physics.md §10.6): a fan of rays, or
// several fans one above the other (a multi-beam lidar), cast from a
// sensor frame S against the world (ray_cast.h), as Gazebo's ray sensor
// and sensor_msgs/LaserScan lay them out. Ranges follow REP 117: +inf where
// nothing is met within max_range, −inf where something is nearer than
// min_range; a met range gets seeded Gaussian noise, held within
// [min_range, max_range]. ROS-free; the node publishes the scans.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "rigid_body_sim/core/bodies/geometry.h"
#include "rigid_body_sim/core/devices/ray_cast.h"
#include "rigid_body_sim/core/devices/sample_seed.h"

namespace rigid_body_sim::core {

struct LidarSettings {
  int samples = 360;                ///< rays per fan
  double min_angle = -M_PI;         ///< rad about S's z, 0 along S's x (LaserScan's angle_min)
  double max_angle = M_PI;          ///< rad (angle_max); the rays are evenly spaced from min to max
  int vertical_samples = 1;         ///< fans
  double vertical_min_angle = 0.0;  ///< rad of elevation above S's xy plane, the lowest fan's
  double vertical_max_angle = 0.0;  ///< rad, the highest fan's
  double min_range = 0.1;           ///< m
  double max_range = 30.0;          ///< m
  double noise = 0.0;               ///< m, σ of each met range's noise
  std::uint64_t seed = 0;           ///< of the noise: the same seed, the same scans
};

/// Throws std::invalid_argument naming the field: samples or fans < 1 or
/// more than 10⁶ rays in all, angles not finite or min > max, horizontal
/// ones beyond ±4π, vertical ones beyond ±π/2, ranges not 0 ≤ min < max ≤
/// 10⁵ m, noise not finite ≥ 0 (core/bodies/ranges.h).
void checkLidar(const LidarSettings& s);

/// Bytes a lidar of `s` may hold at once, counted before it is built (the
/// node's device budget): per ray its direction and range, and the scan's
/// message with its serialized copy (a LaserScan's float, or a
/// PointCloud2's 22-byte point when it has several fans).
std::uintmax_t lidarBytes(const LidarSettings& s);

class Lidar {
 public:
  explicit Lidar(const LidarSettings& settings);
  const LidarSettings& settings() const { return settings_; }
  /// rad between neighbouring rays of a fan, and between fans (0 for one).
  double angleIncrement() const { return increment_; }
  double verticalIncrement() const { return vertical_increment_; }
  /// The unit direction of ray k (fan k / samples, ray k % samples) in S.
  const Vec3& direction(std::size_t k) const { return directions_[k]; }
  std::size_t rayCount() const { return directions_.size(); }

  /// One scan from S at X_WS in `state`: `ranges` (m, one per ray, fan by
  /// fan, REP 117's ±inf), the bodies `skip` marks unseen (its own links).
  /// Scan k's noise is its own (sampleSeed(seed, k)), whatever came before.
  void scan(const Model& model, const State& state, const Pose& X_WS, const std::vector<char>& skip,
            std::vector<double>& ranges);
  /// A scan due but not cast (nobody reads it): the next one is scan k + 1 all the same.
  void pass() { ++scans_; }
  /// The next scan is scan 0 again: the noise from its seed (a world reset).
  void restart() { scans_ = 0; }

 private:
  LidarSettings settings_;
  double increment_ = 0.0, vertical_increment_ = 0.0;
  std::vector<Vec3> directions_;  ///< per ray, in S
  /// Each group of kGroup consecutive rays' cone: the bodies they can meet
  /// are culled once for all of them (RayWorld::cull).
  static constexpr std::size_t kGroup = 16;
  std::vector<RayCone> cones_;
  std::vector<int> among_;   ///< one group's bodies, reused
  std::uint64_t scans_ = 0;  ///< scans so far, cast or passed
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace rigid_body_sim::core
