// ~delete_body, and what follows any edit of the world (a fresh workspace,
// the markers and fixed frames again). A body goes between two steps: the
// model is replaced by an edited copy (core::Model::withoutBody), never
// changed during a step. Spawning is in spawn_requests.cpp.
#include "rigid_body_sim/ros/markers.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {

bool SimNode::deleteBody(DeleteBody::Request& req, DeleteBody::Response& res) {
  res.success = false;
  if (req.name.empty()) {
    res.message = "name is empty: give the name of the body to delete";
    return true;
  }
  std::string why;
  const auto found = findBody(req.name, why);
  if (!found) {
    res.message = "name: " + why;
    return true;
  }
  const int i = *found;
  core::Model edited = model_.withoutBody(static_cast<std::size_t>(i));
  core::removeBody(model_, state_, i);  // wakes what may touch it
  core::removeBody(model_, initial_, i);
  world_.model = std::move(edited);
  const std::size_t dropped = schedule_.removeBody(i);
  forgetContactsOf(i);
  ports_.erase(ports_.begin() + i);  // its publisher and subscriber go with it
  for (BodyPorts& p : ports_) {      // wrenches held in its axes go too
    if (!p.held || p.held->axes.other < i) continue;
    if (p.held->axes.other == i) {
      p.held.reset();
    } else {
      --p.held->axes.other;
    }
  }
  afterEdit(true);
  res.success = true;
  res.message = "body '" + req.name + "' deleted at t = " + now() + " (" + std::to_string(dropped) +
                " timed wrenches went with it); " + std::to_string(model_.bodyCount()) + " bodies left";
  ROS_INFO("sim_node: %s", res.message.c_str());
  return true;
}

void SimNode::freshWorkspace() {
  core::Workspace fresh;
  fresh.threads = workspace_.threads;
  fresh.min_parallel_work = workspace_.min_parallel_work;
  fresh.skip_fixed_points = workspace_.skip_fixed_points;
  workspace_ = std::move(fresh);
}

void SimNode::afterEdit(bool deleted) {
  freshWorkspace();
  indexBodies();
  body_markers_ = bodyMarkers(model_, frames(), colours());
  if (deleted) {
    // rviz forgets every body marker, then draws those left. tf2_ros's
    // static broadcaster keeps all it was sent: a new one sends the rest.
    visualization_msgs::Marker clear;
    clear.action = visualization_msgs::Marker::DELETEALL;
    body_markers_.markers.insert(body_markers_.markers.begin(), clear);
    static_tf_.emplace();
  }
  body_pub_.publish(body_markers_);
  publishFixedFrames();
}

}  // namespace rigid_body_sim::node
