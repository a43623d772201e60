// A robot's controllers from its config's `controllers` map: each type as
// ros_controllers names it turned into the core's joint controllers
// (core/controllers/joint_control.h), which act through effort only. ROS-free.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/controllers/joint_control.h"
#include "rigid_body_sim/core/controllers/robot_control.h"
#include "rigid_body_sim/core/devices/velocity_driver.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

/// What the node runs of a robot's controllers: the core's control stage
/// (its controllers, drives and base driver, core::RobotControl) and the
/// names of their ports.
struct RobotControls : core::RobotControl {
  /// Per controller of `controllers`: its command is a std_msgs/Float64MultiArray
  /// (a Joint*GroupController), else a std_msgs/Float64.
  std::vector<char> group;
  /// Hz of sim time of a joint_state_controller/JointStateController's
  /// joint_states; 0: none was given (the node's ~publish_rate).
  double joint_state_rate = 0.0;
  std::vector<DriveTopics> drive_topics;  ///< per drive of `drives`: what it publishes, on which frames
  /// The base driver's command topic (a config's `cmd_vel`: "cmd_vel"; a markup plugin's
  /// `commandTopic`), under the robot's prefix, or from the root ('/...').
  std::string base_driver_topic = "cmd_vel";
  /// gazebo_ros_control's `robotNamespace` in the URDF's markup ("": none):
  /// the namespace of the robot's controllers' topics and joint_states.
  std::string robot_namespace;
  /// What loading them has to say, for the log (the keys not read, in one line).
  std::vector<std::string> notes;
};

/// The robot's base drive into controls.base_driver: the config's
/// `cmd_vel` (config key `key` + "cmd_vel"), else its markup's planar_move
/// or force_based_move (`markup`), whose force gains are divided by the
/// robot's mass and yaw inertia at rest, its most force and torque 2 g of
/// that mass and 40 rad/s² of that inertia. Refused (ConfigError naming
/// the key): either for a robot fixed to the world, or both given.
void addBaseDrive(const std::optional<core::DriverSettings>& cmd_vel, const std::optional<BaseDriveEntry>& markup,
                  const core::ArticulationModel& model, const std::string& key, RobotControls& controls);

/// The types this project runs, as ros_controllers names them.
std::vector<std::string> controllerTypes();

/// `entries` for the robot `model`. Refused (ConfigError naming the key):
/// a type it does not run (the message lists those it does), `joint` for a
/// group type or `joints` for a one-joint type, a joint the robot does not
/// have or a mimic joint, a position or velocity controller without gains
/// for each joint (`pid`, or `gains` for a group): they act through a PID on
/// effort, never by setting the joint. A joint is one running controller's:
/// a later controller with a joint an earlier one has is checked and loaded
/// stopped (left out, named in `notes`), as controller_manager's spawner
/// leaves the second of two; a markup plugin (key `<gazebo> ...`) on such a
/// joint is refused, since a plugin always runs.
/// A DiffDriveController's wheels are checked likewise (each a turning
/// joint); its wheel_separation and wheel_radius, when
/// not given, come from the URDF as ros_controllers finds them (refused when
/// the left wheel's first collision is no cylinder or sphere); its wheels'
/// PID gains from gazebo_ros_control's pid_gains, else core::defaultWheelGains.
RobotControls buildControls(const std::vector<ControllerEntry>& entries, const core::ArticulationModel& model);

/// A robot's controllers given apart from a config (~spawn_body), for
/// `model`, read and checked as the config's are (every problem in one
/// ConfigError naming the keys under `path`). `node` is a map as the
/// config's `controllers` key, or, `in_namespace`, the robot's namespace
/// as a Gazebo user fills it (`rosparam load FILE /NAME`, which
/// gazebo_ros_control and controller_manager read): each of its maps
/// with a `type` key is a controller (as the spawner finds them by name),
/// its `gazebo_ros_control` map gives pid_gains, and the rest (the
/// robot_description, other nodes' parameters) is not this node's to read.
/// `markup`: the drives of the robot's URDF markup, run after them.
RobotControls controlsOf(const YAML::Node& node, const std::string& path, const core::ArticulationModel& model,
                         bool in_namespace, const std::vector<ControllerEntry>& markup = {});

}  // namespace rigid_body_sim::io
