// The mass properties of a link's collision shapes filled with a uniform
// density: what a moving link without mass is given (docs/physics.md §2.1),
// as MuJoCo's compiler gives a body without an inertial from its geoms.
#pragma once

#include <vector>

#include "rigid_body_sim/core/bodies/collision.h"
#include "rigid_body_sim/core/bodies/inertia.h"

namespace rigid_body_sim::core {

/// Water's density (kg/m³): MuJoCo's default for a geom's mass.
inline constexpr double kWaterDensity = 1000.0;

/// The mass, centre of mass and inertia of `shape` filled at `density`
/// (kg/m³), in the link frame L: closed forms for a box, sphere, cylinder and
/// capsule; a mesh by the divergence theorem over its triangles (each with
/// the origin a signed tetrahedron), its volume's sign taken as it comes
/// (a mesh wound inside out has the same solid). A mesh enclosing no
/// volume (open, or flat) is taken as its bounding box.
MassProperties shapeMassProperties(const CollisionShape& shape, double density);

/// The shapes together (their overlaps counted twice, as MuJoCo's geoms).
MassProperties shapesMassProperties(const std::vector<CollisionShape>& shapes, double density);

}  // namespace rigid_body_sim::core
