// A signed distance sampled on a grid, for meshes (body-body contact needs
// the distance to the other body, and a mesh has no closed form).
#pragma once

#include <memory>
#include <vector>

#include "rigid_body_sim/core/bodies/geometry.h"
#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

class SdfGrid {
 public:
  /// Samples a closed mesh's signed distance on a grid covering it with two
  /// cells to spare, `resolution` cells along its longest side: the distance
  /// to the nearest triangle (found through a bounding-volume hierarchy),
  /// negative inside, by the parity of the triangles crossed along each
  /// axis, the three axes voting (robust to flipped triangles and to a small
  /// hole one axis's rays pass through). What meshSignedDistance gives at
  /// every sample of a closed mesh, in a hundredth of the time or less
  /// (docs/physics.md §5.1).
  static std::shared_ptr<const SdfGrid> fromMesh(const TriangleMesh& mesh, int resolution);

  /// The resolution to build a grid of `triangles` at: `wanted`, or less so
  /// that resolution³ × triangles stays within ranges::kMaxGridWork (the
  /// build's cost); 0 when even ranges::kMinGridResolution does not fit.
  static int resolutionWithin(double triangles, int wanted);

  /// Whether some triangle of the mesh has an area: a mesh of none (no
  /// triangles, or only degenerate ones) has no inside and no grid.
  static bool hasArea(const TriangleMesh& mesh);

  /// φ at p (grid frame, m), trilinear between the samples, and its gradient
  /// (normalized). Beyond the grid: the value at the nearest grid point plus
  /// the distance to it. Any input is safe: a point with a NaN or infinite
  /// coordinate gives +∞ (and the gradient +z).
  double eval(const Vec3& p, Vec3* gradient) const;

  const Vec3& lo() const { return lo_; }
  /// The sample (i, j, k): φ at lo + cell (i, j, k).
  double sample(int i, int j, int k) const { return at(i, j, k); }
  int samples(int axis) const { return n_[axis]; }
  Vec3 hi() const { return lo_ + cell_ * Vec3(n_[0] - 1, n_[1] - 1, n_[2] - 1); }
  double cell() const { return cell_; }

 private:
  double at(int i, int j, int k) const { return values_[(static_cast<std::size_t>(k) * n_[1] + j) * n_[0] + i]; }

  Vec3 lo_ = Vec3::Zero();  ///< the first sample (m)
  double cell_ = 1.0;       ///< m between samples
  int n_[3] = {0, 0, 0};    ///< samples along x, y, z
  std::vector<double> values_;
};

/// A mesh's signed distance at p, the long way: the distance to the nearest
/// of all its triangles, negative where the generalized winding number (the
/// triangles' solid angles summed) says inside. The oracle of SdfGrid's
/// samples in the tests.
double meshSignedDistance(const TriangleMesh& mesh, const Vec3& p);

/// Distance from p to the triangle (a, b, c) (m).
double pointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace rigid_body_sim::core
