// A DiffDriveController's topics in the node, as ros_controllers names them
// under the controller's namespace: geometry_msgs/Twist on CONTROLLER/cmd_vel
// in; nav_msgs/Odometry on CONTROLLER/odom, odom -> base on tf
// (enable_odom_tf) and, with publish_cmd, the limited command as a
// geometry_msgs/TwistStamped on CONTROLLER/cmd_vel_out, out, at its
// publish_rate of sim time. The control and the odometry are the core's
// (core/controllers/diff_drive.h). The messages are built by plain
// functions (tested without a master); the class sends them.
#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include <functional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/controllers/diff_drive.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/ros/counted_publisher.h"

namespace rigid_body_sim::node {

/// Where a drive's odometry lives on tf: its frames after the robot's tf prefix.
struct DriveFrames {
  std::string odom;  ///< odom_frame_id
  std::string base;  ///< base_frame_id
};

/// nav_msgs/Odometry of `drive`'s odometry: pose in the odom frame (z 0,
/// turned about z by its heading), twist in the base's (linear.x,
/// angular.z), the covariances' diagonals as `topics` give them.
nav_msgs::Odometry odometryMessage(const core::DiffDrive& drive, const io::DriveTopics& topics,
                                   const DriveFrames& frames, const ros::Time& stamp);
/// The transform odom -> base of the same pose.
geometry_msgs::TransformStamped odometryTransform(const core::DiffDrive& drive, const DriveFrames& frames,
                                                  const ros::Time& stamp);

class DrivePorts {
 public:
  DrivePorts(const DrivePorts&) = delete;  // its subscriber's callback holds `this`
  DrivePorts& operator=(const DrivePorts&) = delete;
  /// Opens drive `name`'s topics under `prefix` ("" or "ROBOT/") on `nh`:
  /// a cmd_vel calls `command(v, ω)`, or brakes it (0, 0) with an error
  /// when another publisher joins and allow_multiple_cmd_vel_publishers is
  /// false. Publishes every `every` steps.
  DrivePorts(ros::NodeHandle& nh, const std::string& prefix, const std::string& name, const io::DriveTopics& topics,
             DriveFrames frames, long long every, const std::function<void(double, double, double)>& command);

  /// `drive`'s odometry (and its limited command) stamped `stamp`, if step
  /// `steps` is due (or always, `steps` < 0); the odom -> base transform into `tf`.
  void publish(const core::DiffDrive& drive, const ros::Time& stamp, long long steps,
               std::vector<geometry_msgs::TransformStamped>& tf) const;

  const DriveFrames& frames() const { return frames_; }
  /// Whether it puts odom -> base on tf.
  bool onTf() const { return topics_.enable_odom_tf; }

 private:
  io::DriveTopics topics_;
  DriveFrames frames_;
  long long every_ = 1;
  ros::Subscriber cmd_vel_;
  CountedPublisher odom_, cmd_vel_out_;
};

}  // namespace rigid_body_sim::node
