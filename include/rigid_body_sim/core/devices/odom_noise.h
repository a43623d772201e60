// Noisy odometry (docs/physics.md §10.2): a body's pose and twist as a
// wheel or visual odometry would report them, with seeded white noise and
// an optional drift (a random walk of x, y and yaw), and the covariances
// that go with them. ROS-free; the node publishes the result on `odom` and
// the exact state on `ground_truth`.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>

#include "rigid_body_sim/core/bodies/state.h"

namespace rigid_body_sim::core {

/// Config `odom_noise` (`bodies[i].odom_noise`). σs per report and axis.
struct OdomNoiseSettings {
  double position = 0.0;          ///< m
  double orientation = 0.0;       ///< rad, each axis of a small rotation
  double linear_velocity = 0.0;   ///< m/s, body axes
  double angular_velocity = 0.0;  ///< rad/s, body axes
  double drift_x = 0.0;           ///< m/√s: the x offset's variance grows as σ² t
  double drift_y = 0.0;           ///< m/√s
  double drift_yaw = 0.0;         ///< rad/√s, about the world z
  std::uint64_t seed = 0;
};

/// Throws std::invalid_argument naming `key`.FIELD for a negative or non-finite σ.
void validateOdomNoise(const OdomNoiseSettings& s, const std::string& key);

/// One report: the link's pose in the world and its twist in its own axes,
/// and the diagonal variances (x, y, z, roll, pitch, yaw of the pose; the
/// twist's six), as nav_msgs/Odometry carries them.
struct OdomReport {
  Vec3 p_WL = Vec3::Zero();
  Quat q_WL = Quat::Identity();
  Vec3 v_L = Vec3::Zero();  ///< m/s, link axes
  Vec3 w_L = Vec3::Zero();  ///< rad/s, link axes
  std::array<double, 6> pose_variance{}, twist_variance{};
};

/// The exact report of a link state: variances 0.
OdomReport exactOdom(const LinkState& link);

class OdomNoise {
 public:
  explicit OdomNoise(const OdomNoiseSettings& settings) : settings_(settings), rng_(settings.seed) {}

  /// The report of `link` after `elapsed` s more of drift (the time since
  /// the last report): the drift walks, then every component gets its
  /// white noise. The pose variances include the drift's σ² t so far.
  OdomReport report(const LinkState& link, double elapsed);

  /// Starts the drift again from zero (reset).
  void restart() { drift_ = Vec3::Zero(), drift_time_ = 0.0; }

  const OdomNoiseSettings& settings() const { return settings_; }
  /// x (m), y (m), yaw (rad) of the drift so far.
  const Vec3& drift() const { return drift_; }

 private:
  double gaussian(double sigma);

  OdomNoiseSettings settings_;
  Vec3 drift_ = Vec3::Zero();
  double drift_time_ = 0.0;  ///< s the drift has walked
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_;
};

}  // namespace rigid_body_sim::core
