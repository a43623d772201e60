// ~delete_body, and what follows any edit of the world (a fresh workspace,
// the markers and fixed frames again). A body goes between two steps: the
// model is edited in place (core::Model::removeBody), never
// changed during a step. Spawning is in spawn_requests.cpp.
#include <chrono>

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
  const auto start = std::chrono::steady_clock::now();
  core::removeBody(model_, state_, i);  // wakes what may touch it
  core::removeBody(model_, initial_, i);
  world_.model.removeBody(static_cast<std::size_t>(i));  // in place: the others are not copied
  const std::size_t dropped = schedule_.removeBody(i);   // and those held in its axes
  contacts_.removeBody(i);
  closeLater(std::move(ports_[i]));  // its topics, off the loop
  ports_.erase(ports_.begin() + i);
  afterDelete(i, req.name);
  if (settings_.report_timing) {
    pacer_.recordDelete(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  res.success = true;
  res.message = "body '" + req.name + "' deleted at t = " + now() + " (" + std::to_string(dropped) +
                " timed wrenches went with it); " + std::to_string(model_.bodyCount()) + " bodies left";
  ROS_INFO("sim_node: %s", res.message.c_str());
  return true;
}

void SimNode::freshWorkspace() { workspace_ = workspace_.forEditedModel(); }

// Each edit touches what the body it adds or removes has: a spawn at
// N = 1000 rebuilt every body's markers and names, and opened its topics
// (round trips to the master), and cost the loop 5-6 ms (bench/spawn_memory.sh).
void SimNode::afterSpawn() {
  const std::size_t last = model_.bodyCount() - 1;
  freshWorkspace();
  directory_.add(directoryEntry(last));
  appendBodyMarkers(model_.body(last), ports_[last].frame, ports_[last].colour, body_markers_);
  body_pub_.publish(body_markers_);  // latched: the whole set, for a subscriber who comes later
  publishFixedFrames(last);
}

void SimNode::afterDelete(int body, const std::string& name) {
  freshWorkspace();
  directory_.erase(static_cast<std::size_t>(body));
  // rviz forgets every body marker, then draws those left.
  eraseBodyMarkers(name, body_markers_);
  body_pub_.publish(body_markers_);
  publishFixedFrames();
}

}  // namespace rigid_body_sim::node
