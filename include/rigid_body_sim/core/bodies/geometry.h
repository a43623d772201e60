// Geometry types shared by shapes, signed distances and meshes: a rigid
// transform and a triangle mesh. Eigen only.
#pragma once

#include <array>
#include <vector>

#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

/// A rigid transform X_AB: the pose of a frame B in a frame A. The fields
/// carry no frame names; the variable holding the pose does (X_LS, X_BS,
/// X_PK), as in Drake's RigidTransform.
struct Pose {
  Quat rotation = Quat::Identity();  ///< orientation of B in A (unit)
  Vec3 translation = Vec3::Zero();   ///< B's origin in A (m)

  Pose operator*(const Pose& X_BC) const {
    return {rotation * X_BC.rotation, translation + rotation * X_BC.translation};
  }
  Vec3 operator*(const Vec3& p_B) const { return translation + rotation * p_B; }
  Pose inverse() const { return {rotation.conjugate(), -(rotation.conjugate() * translation)}; }
};

/// A triangle mesh: vertices and the triangles over them (indices).
struct TriangleMesh {
  std::vector<Vec3> vertices;                 ///< m
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside
};

}  // namespace rigid_body_sim::core
