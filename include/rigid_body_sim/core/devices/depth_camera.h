// A depth camera (docs/physics.md §10.7): one ray per pixel of a pinhole
// camera cast against the world (ray_cast.h), each pixel the depth of what
// it meets along the optical axis. The camera looks along its frame S's x,
// as Gazebo's sensors do; its image is laid out as ROS's optical frames
// are (REP 103): u to the right (S's −y), v down (S's −z), depth along S's x.
// Depths follow REP 117's ranges: +inf where nothing is met within
// max_depth, −inf nearer than min_depth; a met depth gets seeded Gaussian
// noise, held within [min_depth, max_depth]. ROS-free.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "rigid_body_sim/core/bodies/geometry.h"
#include "rigid_body_sim/core/devices/ray_cast.h"
#include "rigid_body_sim/core/devices/sample_seed.h"

namespace rigid_body_sim::core {

struct DepthCameraSettings {
  int width = 320;          ///< pixels
  int height = 240;         ///< pixels
  double hfov = M_PI / 3;   ///< rad across the image's width
  double min_depth = 0.1;   ///< m (near clip)
  double max_depth = 10.0;  ///< m (far clip)
  double noise = 0.0;       ///< m, σ of each met depth's noise
  std::uint64_t seed = 0;   ///< of the noise
};

/// Throws std::invalid_argument naming the field: a size < 1 or more than
/// 4·10⁶ pixels, hfov not in [10⁻³, π), depths not 0 ≤ min < max ≤ 10⁵ m,
/// noise not finite ≥ 0 (core/bodies/ranges.h).
void checkDepthCamera(const DepthCameraSettings& s);

/// Bytes a depth camera of `s` may hold at once, counted before it is built
/// (the node's device budget): per pixel its ray, its depth, and its image
/// (32FC1) and point cloud (16-byte points) messages with their serialized
/// copies.
std::uintmax_t depthCameraBytes(const DepthCameraSettings& s);

class DepthCamera {
 public:
  explicit DepthCamera(const DepthCameraSettings& settings);
  const DepthCameraSettings& settings() const { return settings_; }
  /// The pinhole's focal length in pixels (fx = fy) and principal point
  /// (pixel centres at whole numbers: cx = (width − 1)/2, cy = (height − 1)/2).
  double focal() const { return focal_; }
  double cx() const { return 0.5 * (settings_.width - 1); }
  double cy() const { return 0.5 * (settings_.height - 1); }

  /// One image from S at X_WS in `state`: `depth` (m, row by row from the
  /// top-left), the bodies `skip` marks unseen.
  /// Image k's noise is its own (sampleSeed(seed, k)), whatever came before.
  void capture(const Model& model, const State& state, const Pose& X_WS, const std::vector<char>& skip,
               std::vector<double>& depth);
  /// An image due but not cast (nobody reads it): the next one is image k + 1 all the same.
  void pass() { ++images_; }
  /// The next image is image 0 again: the noise from its seed.
  void restart() { images_ = 0; }

 private:
  DepthCameraSettings settings_;
  double focal_ = 0.0;
  std::vector<Vec3> rays_;         ///< per pixel, its unit direction in S
  std::vector<double> per_depth_;  ///< per pixel, range per unit depth (1 / the direction's x)
  /// A square of pixels whose rays share one cone: the bodies they can meet
  /// are culled once for all of them (RayWorld::cull).
  struct Tile {
    int u0, v0, u1, v1;  ///< its pixels: u0 <= u < u1, v0 <= v < v1
    RayCone cone;        ///< its rays' in S
    double reach;        ///< m per m of max_depth: its longest ray's range per unit depth
  };
  std::vector<Tile> tiles_;
  std::vector<int> among_;    ///< one tile's bodies, reused
  std::uint64_t images_ = 0;  ///< images so far, cast or passed
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace rigid_body_sim::core
