// A robot from a config: its articulation, its links as the contact
// detection sees them, and its start state (docs/physics.md §11). rbsim's
// way to a robot; ROS-free.
#pragma once

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/articulations/articulation_contacts.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

struct Robot {
  core::ArticulationModel model;
  /// The links against the config's scene, with its settings: dt, gravity,
  /// contact, solver and speed limits are read from `colliders.bodies`.
  core::ArticulationColliders colliders;
  core::ArticulationState state;
};

/// `model` with the config's settings and start: the base link at
/// `initial` (pose, and twist for a floating base; a base fixed to the world
/// may be placed but not set moving), its joints at
/// `initial.joint_positions` and `.joint_velocities` (io/joint_start.h).
/// A config with a `bodies` list is refused (a robot among bodies is not
/// yet simulated), as are a start farther or faster than a body's may be,
/// and keys a robot would not read: `damping` (a robot's is its joints'),
/// a `contact.method` other than impulse, `gyroscopic: false`. ConfigError names
/// the key, and the model's std::invalid_argument the link.
Robot buildRobot(const SimConfig& config, core::ArticulationModel model);

/// Refuses the keys a robot named `robot` would not read (ConfigError
/// naming the key): `damping`, a `contact.method` other than impulse,
/// `gyroscopic: false`.
void checkRobotSettings(const SimConfig& config, const std::string& robot);

/// A robot's start: its base link at `initial` (its twist turned into the
/// base's axes; a base fixed to the world may be placed, not set moving),
/// its joints from `joints` (io/joint_start.h). ConfigError names `key`'s
/// field ("initial", "bodies[2].initial").
core::ArticulationState robotStart(const core::ArticulationModel& model, const core::LinkState& initial,
                                   const InitialJoints& joints, const core::SpeedLimits& limits,
                                   const std::string& key);

}  // namespace rigid_body_sim::io
