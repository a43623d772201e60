// A diff_drive_controller/DiffDriveController's keys in a robot's
// `controllers` map, as ros_controllers' YAML gives them. Private to io.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

constexpr const char* kDiffDriveType = "diff_drive_controller/DiffDriveController";

/// The controller at `key` (its map `body`): every key read or refused
/// (ConfigError naming it); the wheels checked against the robot later
/// (io/controllers.h).
DiffDriveEntry parseDiffDrive(const YAML::Node& body, const std::string& key);

}  // namespace rigid_body_sim::io
