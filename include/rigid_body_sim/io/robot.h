// A robot from a config: the settings it reads and its start state
// (docs/physics.md §11); io::loadScene's way to a robot. ROS-free.
#pragma once

#include <string>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

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
