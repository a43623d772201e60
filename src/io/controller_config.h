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
/// it, every controller's problems in one); the type and the joints are
/// checked against the robot later (io/controllers.h).
std::vector<ControllerEntry> parseControllers(const YAML::Node& node, const std::string& path);

/// Throws one ConfigError saying every one of `problems` ("N problems: a;
/// b"), when there is one.
void throwProblems(const std::vector<std::string>& problems);

/// gazebo_ros_control's map at `path` ({pid_gains: {JOINT: {p, i, d,
/// i_clamp}}}): each joint's gains go to the position_controllers or
/// velocity_controllers controller in `entries` that owns it (in Gazebo
/// they act at its hardware interface; here, as everywhere, on effort).
/// Refused (ConfigError naming the key): a joint no controller of
/// `entries` owns, one of an effort_controllers controller (it takes its
/// own `pid`), one whose controller has gains already, any other key.
void applyPidGains(const YAML::Node& node, const std::string& path, std::vector<ControllerEntry>& entries);

/// steer_bot_hardware_gazebo's map at `path` (gazebo_ros_control's
/// robotSimType on car-like robots, AgileX Hunter's): its `rear_wheel` and
/// `front_steer` name the joints of an AckermannSteeringController of
/// `entries`, which then drives `virtual_rear_wheels` and
/// `virtual_front_wheels` for them (each at its own path's speed) and turns
/// `virtual_front_steers` by the linkage (on such a robot, URDF effort and
/// speed limits of 0 are read as none: io/urdf_lumper.h); `wheel_separation_h` is the wheelbase when the
/// controller gives none; `wheel_separation_w` (the track: the URDF's
/// knuckles' here) and `enable_ackermann_link` false (a parallel linkage)
/// are named as not read. Refused (ConfigError naming the key): no such controller in
/// `entries`, a list not of joint names, any other key.
void applySteerBot(const YAML::Node& node, const std::string& path, std::vector<ControllerEntry>& entries);

}  // namespace rigid_body_sim::io
