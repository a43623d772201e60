// ~contacts and ~contact_markers: what touches what, with the forces
// (core::contactPairs, docs/physics.md §10.3). The step reports only awake
// bodies' contacts; a sleeping body keeps those it fell asleep with.
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>

#include "rigid_body_sim/core/contact_report.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {
namespace {

using core::Vec3;

constexpr double kForceScale = 0.01;  ///< m of arrow per N in ~contact_markers

/// A contact that touches: it pushed, or it penetrates.
bool touching(const core::Contact& c) { return c.normal_impulse > 0.0 || c.separation <= 0.0; }

}  // namespace

void SimNode::keepContacts() {
  // contacts_ holds the sleeping bodies' contacts, which the step no longer
  // reports: taken once, from the step in which the body fell asleep. They
  // change only when a body falls asleep or wakes: a step that changed no
  // body's sleep leaves them as they are (a resting pile of 1,000 boxes
  // keeps about 4,000, which a scan per step cost the loop).
  const std::size_t n = model_.bodyCount();
  bool changed = was_asleep_.size() != n;
  was_asleep_.resize(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const char asleep = state_.bodies[i].asleep ? 1 : 0;
    changed = changed || asleep != was_asleep_[i];
    was_asleep_[i] = asleep;
  }
  if (!changed) return;
  kept_for_.resize(n, 0);
  const auto asleep = [&](int b) { return b < 0 || state_.bodies[b].asleep; };
  contacts_.erase(std::remove_if(contacts_.begin(), contacts_.end(),
                                 [&](const core::Contact& c) { return !asleep(c.body) || !asleep(c.other); }),
                  contacts_.end());
  for (std::size_t i = 0; i < n; ++i) {
    if (!state_.bodies[i].asleep) kept_for_[i] = 0;
  }
  for (const core::Contact& c : workspace_.contacts) {
    if (!kept_for_[c.body] && asleep(c.body) && asleep(c.other) && touching(c)) contacts_.push_back(c);
  }
  for (const core::Contact& c : contacts_) kept_for_[c.body] = 1;
}

void SimNode::forgetContactsOf(int body) {
  std::vector<core::Contact> kept;
  for (core::Contact c : contacts_) {
    if (c.body == body || c.other == body) continue;
    if (c.body > body) --c.body;
    if (c.other > body) --c.other;
    kept.push_back(c);
  }
  contacts_ = std::move(kept);
  if (static_cast<std::size_t>(body) < kept_for_.size()) kept_for_.erase(kept_for_.begin() + body);
  if (static_cast<std::size_t>(body) < was_asleep_.size()) was_asleep_.erase(was_asleep_.begin() + body);
}

void SimNode::publishContacts() {
  const bool listed = contacts_pub_.listened(), drawn = contact_markers_pub_.listened();
  if (!ros::ok() || (!listed && !drawn)) return;
  // The awake bodies' contacts from the step, the sleepers' kept.
  std::vector<core::Contact> touching_now = contacts_;
  for (const core::Contact& c : workspace_.contacts) {
    const bool awake = !state_.bodies[c.body].asleep || (c.other >= 0 && !state_.bodies[c.other].asleep);
    if (awake && touching(c)) touching_now.push_back(c);
  }
  const std::vector<core::ContactPairReport> pairs = core::contactPairs(model_, state_, touching_now);
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
