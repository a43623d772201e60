// The robots' controllers in the node: each controller's command topic
// (CONTROLLER/command under the robot's namespace: std_msgs/Float64,
// Float64MultiArray for a group, trajectory_msgs/JointTrajectory for a
// trajectory controller), the robot's `joint_command` (an Isaac
// Sim style sensor_msgs/JointState, joints by name), its DiffDriveControllers'
// cmd_vel and odometry (drive_ports.h), a base's cmd_vel (a body's velocity
// driver on the whole robot), the efforts and wrenches they give every step,
// and their restart when a robot is put somewhere. The control itself is the
// core's (core/controllers/joint_control.h), through effort only.
#pragma once

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_broadcaster.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <Eigen/Core>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation_step.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/io/controllers.h"
#include "rigid_body_sim/io/timeline.h"
#include "rigid_body_sim/ros/controller_watch.h"
#include "rigid_body_sim/ros/drive_ports.h"
#include "rigid_body_sim/ros/sim_clock.h"

namespace rigid_body_sim::node {

class RobotCommands {
 public:
  RobotCommands(const RobotCommands&) = delete;  // its subscribers' callbacks hold `this`
  RobotCommands& operator=(const RobotCommands&) = delete;
  /// Subscribes every controller's command on `nh` (under `prefixes[r]`
  /// for robot r: robotTopicPrefix's); the position and
  /// trajectory controllers hold the joints where `sim` starts them. `sim`
  /// and `time` (the node's, which outlive this) are read when a
  /// trajectory arrives: where it starts, on which clock.
  RobotCommands(const ros::NodeHandle& nh, std::vector<io::RobotControls> controls, const core::Simulation& sim,
                const NodeTime& time, const std::vector<std::string>& prefixes);

  /// Robot r of `sim`, added to the world (~spawn_body), with `controls`:
  /// their topics under `prefix`, the position and trajectory controllers
  /// holding the joints where they are, its drives' frames after `frame_prefix`.
  void addRobot(const core::Simulation& sim, std::size_t r, const std::string& prefix, const std::string& frame_prefix,
                io::RobotControls controls);
  /// Robot r deleted (~delete_body): its topics unsubscribed, its
  /// controllers gone; the later robots move down by one.
  void removeRobot(std::size_t r);

  /// Each robot's loads for the step [t, t + dt) from `sim`'s state: its
  /// controllers' efforts and the timed ones (apply_joint_effort) added,
  /// within the joints' limits (also kept for joint_states).
  void loadsFor(const core::Simulation& sim, double t, std::vector<core::ArticulationLoads>& loads);
  /// After the step: each drive's odometry from where the step left its wheels.
  void observe(const core::Simulation& sim);
  /// Each drive's odometry, and odom -> base on tf, stamped `stamp`: those
  /// due at step `steps`, or every one (`steps` < 0).
  void publishDrives(const ros::Time& stamp, long long steps = -1);
  /// The frames robot r's drives put on tf as odom -> FRAME.
  std::vector<std::string> odometryFrames(std::size_t r) const;
  /// The efforts of the last step, per robot (empty before the first).
  const std::vector<Eigen::VectorXd>& applied() const { return applied_; }
  /// After a reset or set_state: every controller starts again from where
  /// its robot now is (no integral, position targets where the joints are;
  /// a drive's odometry at zero).
  void restart(const core::Simulation& sim);
  /// The same for robot r alone (after set_model_configuration; a drive's
  /// odometry goes on from where it was).
  void restart(const core::Simulation& sim, std::size_t r, bool zero_odometry = false);
  /// Hz of robot r's joint_state_controller, 0 for none.
  double jointStateRate(std::size_t r) const { return controls_[r].joint_state_rate; }

  /// A command for robot r's controller c (the topics' callback; public for
  /// the tests): refused with a warning when not finite or of the wrong
  /// length, clipped to the limits with a warning once per joint.
  void command(std::size_t r, std::size_t c, const std::vector<double>& values);
  /// A joint_command for robot r: each named joint's target from the field
  /// its controller takes (position, velocity or effort). The message is
  /// dropped whole with a warning when a joint is unknown or owned by no
  /// controller, its field is missing, a value is not finite, or the
  /// arrays' lengths differ from the names'.
  void jointCommand(std::size_t r, const sensor_msgs::JointState& msg);
  /// A trajectory for robot r's trajectory controller c, as ros_controllers'
  /// JointTrajectoryController takes it on its command topic: every joint
  /// of the controller named once, in any order; header.stamp 0 starts it
  /// now, else at the stamp (the node's clock); points already past are
  /// dropped; no points: hold where the joints are. Dropped whole with a
  /// warning otherwise (joint_trajectory.h's checks, a stamp far ahead).
  void trajectory(std::size_t r, std::size_t c, const trajectory_msgs::JointTrajectory& msg);
  /// A cmd_vel for robot r's base (its `cmd_vel` key): refused with a
  /// warning when not finite, clipped to the driver's speeds (said once).
  void baseCommand(std::size_t r, const geometry_msgs::Twist& msg);

  /// The config's `timeline` (io/timeline.h), checked against the robots
  /// and the bodies' drivers at start (ConfigError naming the entry); its
  /// commands are then given before the steps they are due at, as its
  /// topics' messages are, so a scenario runs here as it does in rbsim.
  void setTimeline(std::vector<io::TimedCommand> entries, io::BodyDrivers bodies);
  /// Before the step that starts at sim time t: the timeline's commands
  /// due, its joint efforts into `efforts` (the simulation's).
  void giveTimed(double t, core::JointEffortSchedule& efforts);

 private:
  /// Robot r's controllers' command topics and its joint_command, under `prefix`.
  std::vector<ros::Subscriber> subscribe(std::size_t r, const std::string& prefix);
  /// Robot r's drives' topics under `prefix`, frames after `frame_prefix`.
  std::vector<std::unique_ptr<DrivePorts>> openDrives(std::size_t r, const std::string& prefix,
                                                      const std::string& frame_prefix);
  /// Warns once per joint and limit of the commands `source` had clipped.
  void warnClipped(std::size_t r, const std::string& source, const std::vector<core::Clipped>& clipped);

  const core::Simulation& sim_;
  const NodeTime& time_;
  ros::NodeHandle nh_;
  // Per robot, in the world's order of robots.
  std::vector<io::RobotControls> controls_;
  std::vector<std::string> robot_names_;
  std::vector<std::vector<std::string>> joint_names_;  ///< per robot, per link
  std::vector<Eigen::VectorXd> applied_;
  std::set<std::pair<std::string, std::string>> warned_;   ///< (robot/joint, limit) clipped once
  ControllerWatch watch_;                                  ///< saturated or pressing controllers, said once
  std::vector<std::shared_ptr<ros::NodeHandle>> handles_;  ///< per robot, its own (ownHandle)
  std::vector<std::vector<ros::Subscriber>> subscribers_;
  std::vector<std::vector<std::unique_ptr<DrivePorts>>> drives_;  ///< per robot, per drive
  std::vector<geometry_msgs::TransformStamped> odom_tf_;          ///< this publication's
  tf2_ros::TransformBroadcaster tf_;
  io::Timeline timeline_;  ///< the config's commands at given sim times
};

}  // namespace rigid_body_sim::node
