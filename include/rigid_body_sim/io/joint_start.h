// A robot's joints at the start, from a config's `initial.joint_positions`
// and `initial.joint_velocities` (io/config.h). ROS-free.
#pragma once

#include <string>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/bodies/settings.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

/// Sets `state`'s joints from `initial`. Each name must be a moving joint of
/// `model` that is not a mimic (a mimic follows its joint); a position
/// within the joint's limits; a velocity within `limits` (max_angular_speed
/// for revolute and continuous joints, max_linear_speed for prismatic ones).
/// Joints not named keep their value. Then every mimic joint is put where
/// its joint puts it (q = multiplier · q_joint + offset, v likewise).
/// Refused with ConfigError naming `key` (initial, or bodies[i].initial),
/// the map and the joint; the state is then unchanged.
void startJoints(const core::ArticulationModel& model, const InitialJoints& initial, const core::SpeedLimits& limits,
                 const std::string& key, core::ArticulationState& state);

}  // namespace rigid_body_sim::io
