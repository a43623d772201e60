// The surface φ = 0 of a signed distance function as triangles, for display
// (rviz shows the scene the bodies collide with).
#pragma once

#include <optional>
#include <vector>

#include "rigid_body_sim/core/bodies/sdf.h"

namespace rigid_body_sim::core {

/// An axis-aligned box in the world (m).
struct Bounds {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
};

/// A box that contains the solid of `sdf` (where φ ≤ 0), or nothing if the
/// solid is unbounded (a plane, or a union with one).
std::optional<Bounds> solidBounds(const Sdf& sdf);

/// Triangles (three vertices each, world frame) approximating φ = 0 inside
/// `bounds`, by marching tetrahedra on a grid of cells of at most `cell` m:
/// every vertex lies on a grid edge where φ changes sign, at the linear
/// interpolation of φ along it.
std::vector<Vec3> surfaceTriangles(const Sdf& sdf, const Bounds& bounds, double cell);

}  // namespace rigid_body_sim::core
