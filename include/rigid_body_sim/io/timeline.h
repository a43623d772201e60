// A config's `timeline`: commands for the robots' controllers and the
// bodies' velocity drivers at given sim times, as a user would publish them
// on the node's topics, and efforts on the robots' joints, as
// apply_joint_effort gives them (docs/rbsim.md).
// rbsim takes its commands from it, and the node gives them as it gives
// its topics' messages, so a scenario runs the same with and without ROS.
// ROS-free.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/joint_effort_schedule.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/core/bodies/types.h"
#include "rigid_body_sim/core/controllers/joint_trajectory.h"
#include "rigid_body_sim/core/devices/velocity_driver.h"

namespace rigid_body_sim::io {

struct RobotControls;

/// One entry: `{t: 1.0, cmd_vel: {linear: [0.5, 0, 0], angular: [0, 0, 0.3]}}`
/// (a geometry_msgs/Twist, to the robot's base driver or one drive; with
/// `body: NAME`, to that free body's velocity driver, its config `cmd_vel`) or
/// `{t: 1.0, controller: NAME, command: [values]}` (CONTROLLER/command's data)
/// or `{t: 1.0, controller: NAME, trajectory: {joint_names: [a, b], points:
/// [{positions: [0, 1], time_from_start: 2.0}]}}` (a trajectory_msgs/JointTrajectory
/// on CONTROLLER/command, from the step it is given at)
/// or `{t: 1.0, joint_effort: {joint_name: J, effort: 2.0, duration: 0.5}}`
/// (apply_joint_effort's request, starting at t).
struct TimedCommand {
  std::string key;  ///< "timeline[3]", for messages
  double t = 0.0;   ///< s of sim time: given before the first step that starts at or after it
  double until =
      0;  ///< s: given again before every step that starts before it (a publisher at the step's rate); ≤ t: once
  std::string robot;  ///< "": the world's one robot
  std::string body;   ///< a free body whose driver a cmd_vel is for; "": a robot's
  std::string
      controller;        ///< cmd_vel: a drive's name, "" for the base driver or the one drive; command: its controller
  bool cmd_vel = false;  ///< a twist (linear, angular), else `values`
  core::Vec3 linear = core::Vec3::Zero(), angular = core::Vec3::Zero();  ///< m/s, rad/s, in the base's axes
  std::vector<double> values;                                            ///< one per joint of the controller
  bool trajectory = false;                    ///< waypoints for a trajectory controller, neither a twist nor values
  std::vector<std::string> joint_names;       ///< trajectory.joint_names: the order of the points' fields
  std::vector<core::TrajectoryPoint> points;  ///< trajectory.points, times from the step it is given at
  bool joint_effort = false;  ///< an effort on `joint` over [t, t + duration), neither a twist nor values
  std::string joint;          ///< joint_effort.joint_name: a moving joint of the robot
  double effort = 0.0;        ///< N·m or N
  double duration = 0.0;      ///< s; < 0: until the run ends (apply_joint_effort's "until cleared")
};

/// The config's `timeline` list (ConfigError naming `timeline[i].FIELD`):
/// each `t` within [0, 1e6] s, `until` after it, one of `cmd_vel`,
/// `command` and `joint_effort` (its effort within 1e6, its duration not 0
/// and within 1e6 s, no `until` or `controller` beside it), `body` with a
/// cmd_vel alone (no `robot` or `controller`), every value finite.
std::vector<TimedCommand> parseTimeline(const YAML::Node& list);

/// The velocity driver of the free body named so (config `cmd_vel`), or
/// null if there is no such body or it has none.
using BodyDrivers = std::function<core::VelocityDriver*(const std::string& body)>;

/// A timeline checked against a world's robots and bodies, each command
/// found by its robot's and controller's names, or its body's, when it is
/// given (so an entity deleted or spawned in the node moves no command onto
/// another).
class Timeline {
 public:
  Timeline() = default;
  /// Refuses (ConfigError naming the entry's key) a robot not among
  /// `robots` (or no robot named in a world of several), a controller the
  /// robot does not have or of the wrong kind (cmd_vel to a drive or a base
  /// driver, command to a joint controller), a command of the wrong length,
  /// a joint effort on a joint the robot does not move, a body `bodies`
  /// has no driver of. Steps are `dt` s long.
  Timeline(std::vector<TimedCommand> entries, const std::vector<core::SceneRobot>& robots, double dt,
           const std::vector<RobotControls>& controls, BodyDrivers bodies);

  /// Gives each command due before the step that starts at sim time t to
  /// its controller in `controls` (robot r's `robots`' r-th) or its body's
  /// driver, as the node gives a topic's message received at t, and each
  /// joint effort to `efforts` from its own t. Returns what to say: a
  /// command held to its controller's limits, or whose robot or body is gone.
  std::vector<std::string> apply(double t, const std::vector<core::SceneRobot>& robots,
                                 std::vector<RobotControls>& controls, core::JointEffortSchedule& efforts);
  bool empty() const { return entries_.empty(); }

 private:
  struct Entry {
    TimedCommand command;
    std::string robot;  ///< its robot's name ("" for a body's)
    double due;         ///< s: given before the first step that starts at or after it
  };
  void give(const Entry& e, double t, const std::vector<core::SceneRobot>& robots, std::vector<RobotControls>& controls,
            core::JointEffortSchedule& efforts, std::vector<std::string>& said) const;
  void giveBody(const TimedCommand& c, double t, std::vector<std::string>& said) const;

  std::vector<Entry> entries_;     ///< by due, then as listed
  std::size_t next_ = 0;           ///< the first not yet given
  std::vector<std::size_t> held_;  ///< given, and given again until their `until`
  BodyDrivers bodies_;
};

}  // namespace rigid_body_sim::io
