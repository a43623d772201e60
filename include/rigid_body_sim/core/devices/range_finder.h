// A range finder (a sonar or an infrared ranger): one reading from the
// cone of rays a lidar casts, as gazebo_ros_range makes it, docs/physics.md
// §10.8.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

namespace rigid_body_sim::core {

struct RangeFinderSettings {
  double noise = 0.0;      ///< m, σ of the reading's noise
  std::uint64_t seed = 0;  ///< of the noise: the same seed, the same readings
};

/// Throws std::invalid_argument naming the field: noise not finite ≥ 0.
void checkRangeFinder(const RangeFinderSettings& s);

class RangeFinder {
 public:
  explicit RangeFinder(const RangeFinderSettings& settings);
  const RangeFinderSettings& settings() const { return settings_; }

  /// The nearest of a scan's `ranges` (REP 117's, m): −∞ if a ray met
  /// something nearer than `min_range`, else the least met range with
  /// Gaussian noise of σ `noise`, held within [min_range, max_range], else
  /// +∞ (nothing met within max_range).
  /// Reading k's noise is its own (sampleSeed(seed, k)).
  double reading(const std::vector<double>& ranges, double min_range, double max_range);
  /// A reading due but not taken: the next one is reading k + 1 all the same.
  void pass() { ++readings_; }
  /// The next reading is reading 0 again: the noise from its seed (a world reset).
  void restart() { readings_ = 0; }

 private:
  RangeFinderSettings settings_;
  std::uint64_t readings_ = 0;  ///< readings so far, taken or passed
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace rigid_body_sim::core
