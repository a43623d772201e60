// A robot from a config: robot.h.
#include "rigid_body_sim/io/robot.h"

#include "rigid_body_sim/io/joint_start.h"
#include "rigid_body_sim/io/world.h"

namespace rigid_body_sim::io {

void checkRobotSettings(const SimConfig& config, const std::string& robot) {
  // What a robot does not read is refused, not ignored: a robot's damping
  // is its joints' <dynamics damping>, its contacts are impulses, and its
  // dynamics always hold the gyroscopic terms.
  const core::ModelSpec& m = config.model;
  const auto unread = [&robot](const std::string& key, const std::string& why) {
    throw ConfigError("config key '" + key + "': robot '" + robot + "' " + why);
  };
  const core::Damping& d = m.damping;
  if (d.linear != 0.0 || d.angular != 0.0 || d.linear_drag != 0.0 || d.angular_drag != 0.0) {
    unread("damping", "is damped by its joints' <dynamics damping> only: set damping to 0");
  }
  if (m.contact.method != core::ContactMethod::kImpulse) unread("contact.method", "takes impulse contacts only");
  if (!m.gyroscopic) unread("gyroscopic", "always integrates its links' gyroscopic terms");
}

core::ArticulationState robotStart(const core::ArticulationModel& model, const core::LinkState& initial,
                                   const InitialJoints& joints, const core::SpeedLimits& limits,
                                   const std::string& key) {
  checkStart(initial, limits, key);
  if (model.fixed_base && (initial.v_WL != core::Vec3::Zero() || initial.w_W != core::Vec3::Zero())) {
    throw ConfigError("config key '" + key + ".linear_velocity' / '" + key + ".angular_velocity': robot '" +
                      model.name +
                      "' is fixed to the world (its root link is 'world'): it may be placed, not set moving");
  }
  core::ArticulationState state = core::restState(model);
  core::setBaseLinkState(state, initial);
  startJoints(model, joints, limits, key, state);
  return state;
}

}  // namespace rigid_body_sim::io
