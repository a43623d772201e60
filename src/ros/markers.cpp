#include "rigid_body_sim/ros/markers.h"

#include <algorithm>
#include <array>
#include <utility>

#include "rigid_body_sim/core/bodies/sdf_surface.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim::node {
namespace {

using core::Quat;
using core::Vec3;
using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

/// A marker in `frame`, to be added, with unit scale, no offset and `rgba`.
Marker newMarker(const std::string& frame, const std::string& ns, const std::array<float, 4>& rgba) {
  Marker m;
  m.header.frame_id = frame;
  m.ns = ns;
  m.action = Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color.r = rgba[0];
  m.color.g = rgba[1];
  m.color.b = rgba[2];
  m.color.a = rgba[3];
  return m;
}

/// Appends markers drawing the solid `sdf`, whose pose is given in a frame
/// P placed at X_FP in the marker frame F: rviz's own box, sphere and
/// cylinder for those shapes (through unions), and the surface φ = 0 as
/// triangles for anything else (`fallback_size` m across when unbounded).
void appendSolidMarkers(const core::Sdf& sdf, const core::Pose& X_FP, const Marker& base, double fallback_size,
                        MarkerArray& out) {
  using Kind = core::Sdf::Kind;
  const core::Pose X_FS = X_FP * sdf.pose();
  Marker m = base;
  m.id = static_cast<int>(out.markers.size());
  m.pose = toPose(X_FS.translation, X_FS.rotation);
  switch (sdf.kind()) {
    case Kind::kUnion:
      for (const core::Sdf& child : sdf.children()) appendSolidMarkers(child, X_FS, base, fallback_size, out);
      return;
    case Kind::kBox:  // full size
      m.type = Marker::CUBE;
      m.scale = toVector3(sdf.size());
      break;
    case Kind::kSphere:  // radius
      m.type = Marker::SPHERE;
      m.scale.x = m.scale.y = m.scale.z = 2.0 * sdf.radius();
      break;
    case Kind::kCylinder:  // radius, length along z
      m.type = Marker::CYLINDER;
      m.scale.x = m.scale.y = 2.0 * sdf.radius();
      m.scale.z = sdf.length();
      break;
    default: {
      core::Bounds bounds;
      if (const auto b = core::solidBounds(sdf)) {
        bounds = *b;
      } else {
        bounds = {Vec3::Constant(-0.5 * fallback_size), Vec3::Constant(0.5 * fallback_size)};
      }
      const Vec3 margin = Vec3::Constant(1e-3 + 0.02 * (bounds.hi - bounds.lo).maxCoeff());
      bounds.lo -= margin;
      bounds.hi += margin;
      const double cell = (bounds.hi - bounds.lo).maxCoeff() / 64.0;
      m.type = Marker::TRIANGLE_LIST;
      m.pose = toPose(X_FP.translation, X_FP.rotation);  // the triangles are in P, where sdf's pose applies
      for (const Vec3& p : core::surfaceTriangles(sdf, bounds, cell)) m.points.push_back(toPoint(p));
    }
  }
  out.markers.push_back(m);
}

/// A <collision> shape as a marker, posed in its link frame.
Marker shapeMarker(const core::CollisionShape& shape, const Marker& base) {
  using Kind = core::CollisionShape::Kind;
  Marker m = base;
  m.pose = toPose(shape.X_LS.translation, shape.X_LS.rotation);
  switch (shape.kind) {
    case Kind::kBox:  // full size
      m.type = Marker::CUBE;
      m.scale = toVector3(shape.size);
      break;
    case Kind::kSphere:  // radius
      m.type = Marker::SPHERE;
      m.scale.x = m.scale.y = m.scale.z = 2.0 * shape.radius;
      break;
    case Kind::kCylinder:  // radius, length along z
      m.type = Marker::CYLINDER;
      m.scale.x = m.scale.y = 2.0 * shape.radius;
      m.scale.z = shape.length;
      break;
    case Kind::kCapsule: {  // rviz has no capsule: its surface as triangles, 1/32 of its length a cell
      const Vec3 half(shape.radius, shape.radius, shape.radius + 0.5 * shape.length);
      m.type = Marker::TRIANGLE_LIST;
      const core::Bounds bounds{-1.05 * half, 1.05 * half};
      for (const Vec3& p :
           core::surfaceTriangles(core::Sdf::capsule(shape.radius, shape.length), bounds, 2.1 * half.z() / 32.0)) {
        m.points.push_back(toPoint(p));
      }
      break;
    }
    case Kind::kPoints:
      if (shape.mesh.triangles.empty()) {  // a point cloud: its points, 5 mm across
        m.type = Marker::POINTS;
        m.scale.x = m.scale.y = 0.005;
        for (const Vec3& v : shape.mesh.vertices) m.points.push_back(toPoint(v));
      } else {
        m.type = Marker::TRIANGLE_LIST;
        for (const auto& t : shape.mesh.triangles) {
          for (const int i : t) m.points.push_back(toPoint(shape.mesh.vertices[i]));
        }
      }
      break;
  }
  return m;
}

}  // namespace

MarkerArray sceneMarkers(const std::vector<core::Sdf>& scene, const std::string& world_frame, double scene_size) {
  MarkerArray markers;
  const Marker base = newMarker(world_frame, "scene", {0.6f, 0.6f, 0.65f, 0.8f});
  for (const core::Sdf& item : scene) {
    if (item.kind() == core::Sdf::Kind::kPlane) {
      // A thin square slab standing for the half-space's surface.
      Marker m = base;
      m.id = static_cast<int>(markers.markers.size());
      m.type = Marker::CUBE;
      const Vec3 n = item.pose().rotation * item.normal();
      m.pose = toPose(item.pose().translation - 0.0005 * n, Quat::FromTwoVectors(Vec3::UnitZ(), n));
      m.scale.x = m.scale.y = scene_size;
      m.scale.z = 0.001;
      markers.markers.push_back(m);
      continue;
    }
    appendSolidMarkers(item, core::Pose{}, base, scene_size, markers);
  }
  return markers;
}

void appendBodyMarkers(const core::BodyModel& body, const std::string& frame, std::size_t colour,
                       MarkerArray& markers) {
  static const std::array<std::array<float, 4>, 4> kColours = {
      {{0.85f, 0.45f, 0.2f, 1.0f}, {0.25f, 0.55f, 0.85f, 1.0f}, {0.4f, 0.7f, 0.3f, 1.0f}, {0.75f, 0.3f, 0.6f, 1.0f}}};
  Marker base = newMarker(frame, body.name, kColours[colour % kColours.size()]);
  base.frame_locked = true;
  for (const core::CollisionShape& shape : body.collision) {
    markers.markers.push_back(shapeMarker(shape, base));
    markers.markers.back().id = base.id++;
  }
}

void eraseBodyMarkers(const std::string& body, MarkerArray& markers) {
  std::vector<Marker>& m = markers.markers;
  m.erase(std::remove_if(m.begin(), m.end(), [&](const Marker& x) { return x.ns == body && x.action == Marker::ADD; }),
          m.end());
  if (m.empty() || m.front().action != Marker::DELETEALL) {
    Marker clear;
    clear.action = Marker::DELETEALL;
    m.insert(m.begin(), clear);
  }
}

MarkerArray bodyMarkers(const core::Model& model, const std::vector<std::string>& frames,
                        const std::vector<std::size_t>& colours) {
  MarkerArray markers;
  for (std::size_t i = 0; i < frames.size(); ++i) appendBodyMarkers(model.body(i), frames[i], colours[i], markers);
  return markers;
}

MarkerPublisher::MarkerPublisher(ros::NodeHandle& pnh, MarkerArray scene, MarkerArray bodies)
    : scene_(std::move(scene)), bodies_(std::move(bodies)) {
  const auto on_subscriber = [this](const ros::SingleSubscriberPublisher&) {
    resend_ = Resend{ros::WallTime::now(), 0};
  };
  scene_pub_ = pnh.advertise<MarkerArray>("scene_markers", 1, on_subscriber, {}, {}, true);
  body_pub_ = pnh.advertise<MarkerArray>("body_markers", 1, on_subscriber, {}, {}, true);
  scene_pub_.publish(scene_);
  body_pub_.publish(bodies_);
}

void MarkerPublisher::added(const core::BodyModel& body, const std::string& frame, std::size_t colour) {
  appendBodyMarkers(body, frame, colour, bodies_);
  body_pub_.publish(bodies_);  // latched: the whole set, for a subscriber who comes later
}

void MarkerPublisher::removed(const std::string& name) {
  eraseBodyMarkers(name, bodies_);
  body_pub_.publish(bodies_);
}

void MarkerPublisher::afterTf() {
  // rviz passes each marker through a tf2 MessageFilter. A marker stamped 0
  // that arrives before its frame's first transform is failed for good when
  // that transform is stamped more than the buffer's 10 s after 0 (always
  // on the wall-anchored clock, after 10 s on sim time), and the latched
  // copy a new subscriber gets on connecting can beat tf. So the markers go
  // again once the subscriber has had tf for a second: by then rviz knows
  // every frame, and a marker for a known frame passes at once.
  if (!resend_ || ++resend_->updates < 2 || (ros::WallTime::now() - resend_->connected).toSec() < 1.0) return;
  resend_.reset();
  scene_pub_.publish(scene_);
  body_pub_.publish(bodies_);
}

}  // namespace rigid_body_sim::node
