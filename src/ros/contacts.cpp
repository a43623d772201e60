// ~contacts and ~contact_markers: what touches what, with the forces
// (core::contactPairs, docs/physics.md §10.3), sleepers included
// (core::ContactLedger).
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>

#include "rigid_body_sim/core/contact_report.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {
namespace {

using core::Vec3;

constexpr double kForceScale = 0.01;  ///< m of arrow per N in ~contact_markers

}  // namespace

void SimNode::publishContacts() {
  const bool listed = contacts_pub_.listened(), drawn = contact_markers_pub_.listened();
  if (!ros::ok() || (!listed && !drawn)) return;
  const std::vector<core::ContactPairReport> pairs =
      core::contactPairs(model_, state_, sim_.contacts.touchingNow(state_, workspace_.contacts));
  Contacts msg;
  msg.header.stamp = stamp();
  msg.header.frame_id = settings_.world_frame;
  visualization_msgs::MarkerArray markers;
  visualization_msgs::Marker clear;
  clear.action = visualization_msgs::Marker::DELETEALL;
  markers.markers.push_back(clear);
  visualization_msgs::Marker points;
  points.header = msg.header;
  points.ns = "points";
  points.type = visualization_msgs::Marker::SPHERE_LIST;
  points.scale.x = points.scale.y = points.scale.z = 0.02;
  points.color.r = 1.0f;
  points.color.a = 1.0f;
  points.pose.orientation.w = 1.0;
  for (const core::ContactPairReport& p : pairs) {
    ContactPair pair;
    pair.body = model_.body(p.body).name;
    pair.other = p.other >= 0 ? model_.body(p.other).name : "scene[" + std::to_string(p.item) + "]";
    Vec3 centre = Vec3::Zero();
    for (const Vec3& q : p.points_W) {
      pair.points.push_back(toPoint(q));
      points.points.push_back(pair.points.back());
      centre += q / static_cast<double>(p.points_W.size());
    }
    pair.normal = toVector3(p.normal_W);
    pair.depth = p.depth;
    pair.normal_force = toVector3(p.normal_force_W);
    pair.friction_force = toVector3(p.friction_force_W);
    msg.pairs.push_back(pair);
    // An arrow per force, from the pair's centre, kForceScale m per N.
    int id = 0;
    for (const auto& [force, g] : {std::pair{p.normal_force_W, 0.2f}, std::pair{p.friction_force_W, 0.8f}}) {
      visualization_msgs::Marker arrow;
      arrow.header = msg.header;
      arrow.ns = pair.body + " " + pair.other;
      arrow.id = id++;
      arrow.type = visualization_msgs::Marker::ARROW;
      arrow.points = {toPoint(centre), toPoint(centre + kForceScale * force)};
      arrow.scale.x = 0.01;
      arrow.scale.y = 0.02;
      arrow.color.g = g;
      arrow.color.b = 1.0f;
      arrow.color.a = 1.0f;
      arrow.pose.orientation.w = 1.0;
      markers.markers.push_back(arrow);
    }
  }
  if (!points.points.empty()) markers.markers.push_back(points);
  if (listed) contacts_pub_.publish(msg);
  if (drawn) contact_markers_pub_.publish(markers);
}

}  // namespace rigid_body_sim::node
