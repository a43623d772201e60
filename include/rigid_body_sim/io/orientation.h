// How the files this package reads write an orientation, in one place:
// quaternions in (x, y, z, w) order, as URDF's urdf::Rotation and the
// config's `quaternion: [x, y, z, w]` (and geometry_msgs) give them, while
// Eigen's constructor takes (w, x, y, z); roll-pitch-yaw as URDF's `rpy`.
// (The ROS messages' own conversion is ros/conversions.h.)
#pragma once

#include <algorithm>
#include <cmath>

#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::io {

/// The quaternion x i + y j + z k + w, as given (not normalized).
inline core::Quat quaternionFromXyzw(double x, double y, double z, double w) { return core::Quat(w, x, y, z); }

/// URDF's roll-pitch-yaw: about the fixed axes X (roll), then Y (pitch),
/// then Z (yaw), so R = Rz(yaw) Ry(pitch) Rx(roll) (rad).
inline core::Quat quaternionFromRpy(const core::Vec3& rpy) {
  return core::Quat(Eigen::AngleAxisd(rpy.z(), core::Vec3::UnitZ()) * Eigen::AngleAxisd(rpy.y(), core::Vec3::UnitY()) *
                    Eigen::AngleAxisd(rpy.x(), core::Vec3::UnitX()));
}

/// The inverse: roll, pitch, yaw (rad) of a unit quaternion, pitch within
/// [−π/2, π/2] (what rbsim prints).
inline core::Vec3 rpyFromQuaternion(const core::Quat& q) {
  const double roll = std::atan2(2 * (q.w() * q.x() + q.y() * q.z()), 1 - 2 * (q.x() * q.x() + q.y() * q.y()));
  const double sin_pitch = std::clamp(2 * (q.w() * q.y() - q.z() * q.x()), -1.0, 1.0);
  const double yaw = std::atan2(2 * (q.w() * q.z() + q.x() * q.y()), 1 - 2 * (q.y() * q.y() + q.z() * q.z()));
  return {roll, std::asin(sin_pitch), yaw};
}

}  // namespace rigid_body_sim::io
