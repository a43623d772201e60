// A diff_drive_controller/DiffDriveController's keys in a robot's
// `controllers` map, as ros_controllers' YAML gives them, and a
// mecanum_drive_controller/MecanumDriveController's. Private to io.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

constexpr const char* kDiffDriveType = "diff_drive_controller/DiffDriveController";
constexpr const char* kMecanumType = "mecanum_drive_controller/MecanumDriveController";

/// The controller at `key` (its map `body`): every key read or refused
/// (ConfigError naming it); the wheels checked against the robot later
/// (io/controllers.h).
DiffDriveEntry parseDiffDrive(const YAML::Node& body, const std::string& key);
/// A mecanum_drive_controller/MecanumDriveController's (Ridgeback's,
/// Dingo-O's): `front_left_wheel_joint`, `back_left_wheel_joint`,
/// `front_right_wheel_joint`, `back_right_wheel_joint`, `wheel_separation_x`
/// and `_y` (both or neither: from the URDF), `linear/y` limits beside
/// DiffDriveController's keys, read the same.
DiffDriveEntry parseMecanumDrive(const YAML::Node& body, const std::string& key);

}  // namespace rigid_body_sim::io
