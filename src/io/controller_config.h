// A robot's `controllers` map in the config, as ros_controllers' YAML
// gives it (top level for one robot, bodies[i].controllers in a world).
// Private to io.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

/// The map at `path`: controller name → {type, joint | joints, pid |
/// gains, publish_rate}. Every key is read or refused (ConfigError naming
/// it); the type and the joints are checked against the robot later
/// (io/controllers.h).
std::vector<ControllerEntry> parseControllers(const YAML::Node& node, const std::string& path);

}  // namespace rigid_body_sim::io
