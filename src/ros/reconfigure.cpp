// Live tuning: the dynamic_reconfigure server ~physics (cfg/Physics.cfg).
// Its callbacks run in the loop's spinOnce, between steps: a new model
// (core::Model::retuned, validated as a config is) replaces the old one
// there, as Gazebo's set_physics_properties does, and every body wakes.
#include <functional>
#include <utility>

#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {

void SimNode::startReconfigure() {
  reconfigure_ = std::make_unique<dynamic_reconfigure::Server<PhysicsConfig>>(reconfigure_mutex_,
                                                                              ros::NodeHandle(pnh_, "physics"));
  // What is in force, not the cfg's defaults or a previous run's parameters.
  reconfigure_->updateConfig(physicsNow());
  reconfigure_->setCallback(std::bind(&SimNode::onReconfigure, this, std::placeholders::_1, std::placeholders::_2));
}

PhysicsConfig SimNode::physicsNow() const {
  const core::Tuning t = model_.tuning();
  // From the cfg's defaults, so that every member is set (a default-built
  // PhysicsConfig leaves its groups' bools uninitialized; UBSan saw them copied).
  PhysicsConfig c = PhysicsConfig::__getDefault__();
  c.gravity_x = t.gravity_W.x();
  c.gravity_y = t.gravity_W.y();
  c.gravity_z = t.gravity_W.z();
  c.contact_friction = t.friction;
  c.contact_restitution = t.restitution;
  c.damping_linear = t.damping.linear;
  c.damping_angular = t.damping.angular;
  c.realtime_factor = settings_.realtime_factor;
  c.publish_rate = settings_.publish_rate;
  c.paused = paused_;
  return c;
}

void SimNode::showPhysics() {
  if (reconfigure_) reconfigure_->updateConfig(physicsNow());
}

void SimNode::setPaused(bool paused) {
  paused_ = paused;
  if (!paused) rebaseClock();  // do not make up for the paused time
}

void SimNode::onReconfigure(PhysicsConfig& config, uint32_t) {
  const PhysicsConfig now = physicsNow();
  // The model's settings: all or none (gravity's magnitude is one check).
  core::Tuning t = model_.tuning();
  t.gravity_W = core::Vec3(config.gravity_x, config.gravity_y, config.gravity_z);
  t.friction = config.contact_friction;
  t.restitution = config.contact_restitution;
  t.damping.linear = config.damping_linear;
  t.damping.angular = config.damping_angular;
  const core::Tuning was = model_.tuning();
  const bool changed = t.gravity_W != was.gravity_W || t.friction != was.friction || t.restitution != was.restitution ||
                       t.damping.linear != was.damping.linear || t.damping.angular != was.damping.angular;
  if (changed) {
    try {
      sim_.retune(t);  // every body awake: what rested must move under the new settings
      ROS_INFO("sim_node: ~physics: gravity (%g, %g, %g) m/s^2, friction %g, restitution %g, damping %g %g 1/s",
               t.gravity_W.x(), t.gravity_W.y(), t.gravity_W.z(), t.friction, t.restitution, t.damping.linear,
               t.damping.angular);
    } catch (const std::exception& e) {
      ROS_WARN("sim_node: ~physics refused: %s; the model keeps its settings", e.what());
      config.gravity_x = now.gravity_x;
      config.gravity_y = now.gravity_y;
      config.gravity_z = now.gravity_z;
      config.contact_friction = now.contact_friction;
      config.contact_restitution = now.contact_restitution;
      config.damping_linear = now.damping_linear;
      config.damping_angular = now.damping_angular;
    }
  }
  // The node's settings, each checked as its parameter is at start.
  try {
    checkNodeParam(*findNodeParamKey("realtime_factor"), config.realtime_factor);
    if (config.realtime_factor != settings_.realtime_factor) {
      params_.node.realtime_factor = config.realtime_factor;
      rebaseClock();
    }
  } catch (const std::exception& e) {
    ROS_WARN("sim_node: ~physics refused: %s", e.what());
    config.realtime_factor = now.realtime_factor;
  }
  try {
    checkNodeParam(*findNodeParamKey("publish_rate"), config.publish_rate);
    params_.node.publish_rate = config.publish_rate;
    publish_every_ = std::max(1LL, std::llround(1.0 / (config.publish_rate * model_.dt())));
  } catch (const std::exception& e) {
    ROS_WARN("sim_node: ~physics refused: %s", e.what());
    config.publish_rate = now.publish_rate;
  }
  if (config.paused != paused_) setPaused(config.paused);
}

}  // namespace rigid_body_sim::node
