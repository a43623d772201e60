// ~delete_body, and what follows any edit of the world (the markers and
// fixed frames again). A body goes between two steps, in place
// (core::Simulation::removeBody), never during a step. Spawning is in
// spawn_requests.cpp.
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
  const auto found = address_.body(req.name, why);
  if (!found) {
    res.message = "name: " + why;
    return true;
  }
  const int i = *found;
  const auto start = std::chrono::steady_clock::now();
  // In place, the others not copied; wakes what may touch it; its wrenches
  // and those in its axes go.
  const std::size_t dropped = sim_.removeBody(i);
  ports_.erase(static_cast<std::size_t>(i));  // its topics closed off the loop
  afterDelete(req.name);
  if (settings_.report_timing) {
    pacer_.recordDelete(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  res.success = true;
  res.message = "body '" + req.name + "' deleted at t = " + now() + " (" + std::to_string(dropped) +
                " timed wrenches went with it); " + std::to_string(model_.bodyCount()) + " bodies left";
  ROS_INFO("sim_node: %s", res.message.c_str());
  return true;
}

// Each edit touches what the body it adds or removes has: a spawn at
// N = 1000 rebuilt every body's markers and names, and opened its topics
// (round trips to the master), and cost the loop 5-6 ms (bench/spawn_memory.sh).
void SimNode::afterSpawn() {
  const std::size_t last = model_.bodyCount() - 1;
  markers_->added(model_.body(last), ports_[last].frame, ports_[last].colour);
  publisher_->fixedFrames(model_, ports_, stamp(), last);
}

void SimNode::afterDelete(const std::string& name) {
  markers_->removed(name);
  publisher_->fixedFrames(model_, ports_, stamp());
}

}  // namespace rigid_body_sim::node
