// geometry_msgs ↔ Eigen, the node's one place for them. geometry_msgs
// quaternions are (x, y, z, w); Eigen's constructor takes (w, x, y, z).
// (Files: io/orientation.h.)
#pragma once

#include <geometry_msgs/Point.h>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/Vector3.h>

#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::node {

inline core::Vec3 fromVector3(const geometry_msgs::Vector3& v) { return {v.x, v.y, v.z}; }
inline core::Vec3 fromPoint(const geometry_msgs::Point& p) { return {p.x, p.y, p.z}; }
/// As given: not normalized (a request's norm is checked, not hidden).
inline core::Quat fromQuaternion(const geometry_msgs::Quaternion& q) { return core::Quat(q.w, q.x, q.y, q.z); }

/// A geometry_msgs type with fields x, y, z (Vector3, Point) from a vector.
template <class Msg>
Msg toXyz(const core::Vec3& v) {
  Msg m;
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
  return m;
}
inline geometry_msgs::Vector3 toVector3(const core::Vec3& v) { return toXyz<geometry_msgs::Vector3>(v); }
inline geometry_msgs::Point toPoint(const core::Vec3& v) { return toXyz<geometry_msgs::Point>(v); }

inline geometry_msgs::Quaternion toQuaternion(const core::Quat& q) {
  geometry_msgs::Quaternion m;
  m.x = q.x();
  m.y = q.y();
  m.z = q.z();
  m.w = q.w();
  return m;
}

inline geometry_msgs::Pose toPose(const core::Vec3& p, const core::Quat& q) {
  geometry_msgs::Pose m;
  m.position = toPoint(p);
  m.orientation = toQuaternion(q);
  return m;
}

inline geometry_msgs::Transform toTransform(const core::Vec3& p, const core::Quat& q) {
  geometry_msgs::Transform m;
  m.translation = toVector3(p);
  m.rotation = toQuaternion(q);
  return m;
}

}  // namespace rigid_body_sim::node
