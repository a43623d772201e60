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
constexpr const char* kAckermannType = "ackermann_steering_controller/AckermannSteeringController";

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
/// An ackermann_steering_controller/AckermannSteeringController's:
/// `rear_wheel` ("rear_wheel_joint") and `front_steer` ("front_steer_joint"),
/// each a joint or, beyond ros_controllers, a list (the rear wheels all
/// driven, the front knuckles turned by Ackermann's linkage: §11.14),
/// `wheel_separation_h` (none: from the URDF) and its multiplier, beside
/// DiffDriveController's keys; `steer_pos_multiplier` other than 1 named as not read.
DiffDriveEntry parseAckermannDrive(const YAML::Node& body, const std::string& key);

}  // namespace rigid_body_sim::io
