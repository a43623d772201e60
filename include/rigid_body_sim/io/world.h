// A world from a config: the model of its bodies and their initial state.
// The one place rbsim and the ROS node set a world up (they differ only in
// where a URDF comes from: files, or for the node also parameters). ROS-free.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

/// The model and the initial state.
struct World {
  core::Model model;
  core::State state;
  /// What loading it repaired or warns of, one message per URDF or start,
  /// for the caller to log once (io::UrdfOptions::notes).
  std::vector<std::string> notes;
};

/// The warning for a body that touches nothing (it has no <collision>, as a
/// URDF with only <visual>s: Gazebo keeps such a body and so does this
/// project), or "" when it has collision geometry.
std::string touchesNothing(const core::BodyModel& body);

/// The warning for bodies first .. first + count − 1 of `model` (one body,
/// or a robot's links) starting inside the static scene deeper than 1 mm,
/// naming `who` ("body 'box'", "robot 'ur5'"), the depth and the deepest
/// body; "" when they start clear of it. Contacts push such a start out in
/// the first steps, which adds energy (Gazebo and MuJoCo do the same,
/// silently).
std::string insideSceneNote(const core::Model& model, const core::State& state, std::size_t first, std::size_t count,
                            const std::string& who);

/// Refuses (ConfigError naming `key`.position, .linear_velocity or
/// .angular_velocity) a start farther than 1e6 m from the origin or faster
/// than `limits`: the one check of a body's and a robot's start.
void checkStart(const core::LinkState& link, const core::SpeedLimits& limits, const std::string& key);

/// Turns a `bodies` entry's `urdf` into a body (the name is set afterwards).
using BodyLoader = std::function<core::BodySpec(const BodyEntry&)>;

/// Builds the model of one body with the config's settings (std::invalid_argument
/// from the model's validation names the field).
core::Model buildModel(const SimConfig& config, const core::BodySpec& body);

/// Loads every body of config.bodies, each named by its entry, through `load`
/// (default: URDF files, relative to the config's folder or package://), and
/// builds the model and the initial state.
World buildWorld(const SimConfig& config, const BodyLoader& load = {});

/// The world a config describes: its `bodies` list (buildWorld; `[]` gives
/// a world without bodies), or, when it has no list, the one body `single_body` gives (rbsim's --urdf, the node's
/// robot_description) at the config's `initial` pose. `single_body` is only
/// called then; without one, a config with no bodies list is an error.
World loadWorld(const SimConfig& config, const std::function<core::BodySpec()>& single_body,
                const BodyLoader& load = {});

}  // namespace rigid_body_sim::io
