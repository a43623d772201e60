// ~contacts and ~contact_markers: what touches what, with the forces
// (core::contactPairs, docs/physics.md §10.3), sleepers included
// (core::ContactLedger).
#include <algorithm>

#include "rigid_body_sim/core/contacts/contact_report.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/state_publisher.h"

namespace rigid_body_sim::node {

using core::Vec3;

Contacts contactsMessage(const core::Model& model, const std::vector<core::ContactPairReport>& pairs,
                         const std_msgs::Header& header) {
  Contacts msg;
  msg.header = header;
  msg.pairs.reserve(pairs.size());
  for (const core::ContactPairReport& p : pairs) {
    ContactPair pair;
    pair.body = model.body(p.body).name;
    pair.other = p.other >= 0 ? model.body(p.other).name : "scene[" + std::to_string(p.item) + "]";
    for (const Vec3& q : p.points_W) pair.points.push_back(toPoint(q));
    pair.normal = toVector3(p.normal_W);
    pair.depth = p.depth;
    pair.normal_force = toVector3(p.normal_force_W);
    pair.friction_force = toVector3(p.friction_force_W);
    msg.pairs.push_back(pair);
  }
  return msg;
}

visualization_msgs::MarkerArray contactMarkers(const Contacts& contacts) {
  using visualization_msgs::Marker;
  visualization_msgs::MarkerArray markers;
  Marker clear;
  clear.action = Marker::DELETEALL;
  markers.markers.push_back(clear);
  Marker points;
  points.header = contacts.header;
  points.ns = "points";
  points.type = Marker::SPHERE_LIST;
  points.scale.x = points.scale.y = points.scale.z = 0.02;
  points.color.r = 1.0f;
  points.color.a = 1.0f;
  points.pose.orientation.w = 1.0;
  for (const ContactPair& pair : contacts.pairs) {
    Vec3 centre = Vec3::Zero();
    for (const geometry_msgs::Point& q : pair.points) {
      points.points.push_back(q);
      centre += fromPoint(q) / static_cast<double>(pair.points.size());
    }
    // An arrow per force, from the pair's centre, kContactForceScale m per N.
    int id = 0;
    for (const auto& [force, g] :
         {std::pair{fromVector3(pair.normal_force), 0.2f}, std::pair{fromVector3(pair.friction_force), 0.8f}}) {
      Marker arrow;
      arrow.header = contacts.header;
      arrow.ns = pair.body + " " + pair.other;
      arrow.id = id++;
      arrow.type = Marker::ARROW;
      arrow.points = {toPoint(centre), toPoint(centre + kContactForceScale * force)};
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
  return markers;
}

void StatePublisher::contacts(const core::Simulation& sim, const ros::Time& now) {
  const bool listed = contacts_pub_.listened(), drawn = contact_markers_pub_.listened();
  if (!ros::ok() || (!listed && !drawn)) return;
  std_msgs::Header header;
  header.stamp = now;
  header.frame_id = settings_.world_frame;
  const Contacts msg = contactsMessage(
      sim.model(),
      core::contactPairs(sim.model(), sim.state, sim.contacts.touchingNow(sim.state, sim.workspace.bodies.contacts)),
      header);
  if (listed) contacts_pub_.publish(msg);
  if (drawn) contact_markers_pub_.publish(contactMarkers(msg));
}

}  // namespace rigid_body_sim::node
