#include "rigid_body_sim/ros/live_tuning.h"

#include <exception>

namespace rigid_body_sim::node {

PhysicsConfig physicsNow(const core::Model& model, const NodeSettings& settings, bool paused) {
  const core::Tuning t = model.tuning();
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
  c.realtime_factor = settings.realtime_factor;
  c.publish_rate = settings.publish_rate;
  c.paused = paused;
  return c;
}

TuningResult applyTuning(PhysicsConfig& config, core::Simulation& sim, NodeSettings& settings, bool paused) {
  TuningResult result;
  const PhysicsConfig now = physicsNow(sim.model(), settings, paused);
  // The model's settings: all or none (gravity's magnitude is one check).
  const core::Tuning was = sim.model().tuning();
  core::Tuning t = was;
  t.gravity_W = core::Vec3(config.gravity_x, config.gravity_y, config.gravity_z);
  t.friction = config.contact_friction;
  t.restitution = config.contact_restitution;
  t.damping.linear = config.damping_linear;
  t.damping.angular = config.damping_angular;
  const bool changed = t.gravity_W != was.gravity_W || t.friction != was.friction || t.restitution != was.restitution ||
                       t.damping.linear != was.damping.linear || t.damping.angular != was.damping.angular;
  if (changed) {
    try {
      sim.retune(t);  // every body awake: what rested must move under the new settings
      result.model = true;
    } catch (const std::exception& e) {
      result.refused.push_back(std::string(e.what()) + "; the model keeps its settings");
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
    if (config.realtime_factor != settings.realtime_factor) {
      settings.realtime_factor = config.realtime_factor;
      result.realtime_factor = true;
    }
  } catch (const std::exception& e) {
    result.refused.push_back(e.what());
    config.realtime_factor = now.realtime_factor;
  }
  try {
    checkNodeParam(*findNodeParamKey("publish_rate"), config.publish_rate);
    settings.publish_rate = config.publish_rate;
    result.publish_rate = true;
  } catch (const std::exception& e) {
    result.refused.push_back(e.what());
    config.publish_rate = now.publish_rate;
  }
  return result;
}

}  // namespace rigid_body_sim::node
