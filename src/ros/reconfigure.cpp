// Live tuning: the dynamic_reconfigure server ~physics (cfg/Physics.cfg).
// Its callbacks run in the loop's spinOnce, between steps: what a request
// changes is applyTuning's (live_tuning.h), as Gazebo's
// set_physics_properties does; the node then paces, publishes and pauses
// as the new settings say.
#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "rigid_body_sim/ros/live_tuning.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {

void SimNode::startReconfigure() {
  reconfigure_ = std::make_unique<dynamic_reconfigure::Server<PhysicsConfig>>(reconfigure_mutex_,
                                                                              ros::NodeHandle(pnh_, "physics"));
  // What is in force, not the cfg's defaults or a previous run's parameters.
  reconfigure_->updateConfig(physicsNow(model_, settings_, paused_));
  reconfigure_->setCallback(std::bind(&SimNode::onReconfigure, this, std::placeholders::_1, std::placeholders::_2));
}

void SimNode::showPhysics() {
  if (reconfigure_) reconfigure_->updateConfig(physicsNow(model_, settings_, paused_));
}

void SimNode::setPaused(bool paused) {
  paused_ = paused;
  if (!paused) rebaseClock();  // do not make up for the paused time
}

void SimNode::onReconfigure(PhysicsConfig& config, uint32_t) {
  const TuningResult r = applyTuning(config, sim_, params_.node, paused_);
  for (const std::string& why : r.refused) ROS_WARN("sim_node: ~physics refused: %s", why.c_str());
  if (r.model) {
    const core::Tuning t = model_.tuning();
    ROS_INFO("sim_node: ~physics: gravity (%g, %g, %g) m/s^2, friction %g, restitution %g, damping %g %g 1/s",
             t.gravity_W.x(), t.gravity_W.y(), t.gravity_W.z(), t.friction, t.restitution, t.damping.linear,
             t.damping.angular);
  }
  if (r.realtime_factor) rebaseClock();
  if (r.publish_rate) publish_every_ = std::max(1LL, std::llround(1.0 / (settings_.publish_rate * model_.dt())));
  if (config.paused != paused_) setPaused(config.paused);
}

}  // namespace rigid_body_sim::node
