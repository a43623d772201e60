// Common Eigen aliases and small helpers of the core. Eigen only.
//
// Frame names follow Drake's monogram notation, shortened: p_WB is the
// position of B in W, q_WB the orientation of B in W, v_WB the velocity of B
// in W (all expressed in W); a single frame letter says only the frame a
// vector is expressed in: w_B is B's angular velocity in W expressed in B
// (Drake's w_WB_B), force_W a force in world axes. Frames used throughout:
//   W  the world (inertial) frame, z up (REP 103)
//   L  the URDF root link frame: what users see and what is reported
//   B  the body frame: origin at the centre of mass, axes along the
//      principal axes of inertia, so the inertia tensor is diagonal in B
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace rigid_body_sim::core {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

/// The cross-product matrix [r]×: r × q = skew(r) q (docs/physics.md §5.5).
inline Mat3 skew(const Vec3& r) {
  Mat3 s;
  s << 0.0, -r.z(), r.y(),  //
      r.z(), 0.0, -r.x(),   //
      -r.y(), r.x(), 0.0;
  return s;
}

}  // namespace rigid_body_sim::core
