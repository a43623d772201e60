// A DiffDriveController's topics: drive_ports.h.
#include "rigid_body_sim/ros/drive_ports.h"

#include <geometry_msgs/TwistStamped.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/topic_claims.h"

namespace rigid_body_sim::node {

namespace {

core::Quat yaw(double heading) { return core::Quat(Eigen::AngleAxisd(heading, core::Vec3::UnitZ())); }

}  // namespace

nav_msgs::Odometry odometryMessage(const core::DiffDrive& drive, const io::DriveTopics& topics,
                                   const DriveFrames& frames, const ros::Time& stamp) {
  const core::PlanarOdometry& o = drive.odometry();
  nav_msgs::Odometry m;
  m.header.stamp = stamp;
  m.header.frame_id = frames.odom;
  m.child_frame_id = frames.base;
  m.pose.pose = toPose(core::Vec3(o.x, o.y, 0.0), yaw(o.heading));
  m.twist.twist.linear.x = o.linear;
  m.twist.twist.linear.y = o.lateral;
  m.twist.twist.angular.z = o.angular;
  for (std::size_t k = 0; k < 6; ++k) {
    m.pose.covariance[7 * k] = topics.pose_covariance_diagonal[k];
    m.twist.covariance[7 * k] = topics.twist_covariance_diagonal[k];
  }
  return m;
}

geometry_msgs::TransformStamped odometryTransform(const core::DiffDrive& drive, const DriveFrames& frames,
                                                  const ros::Time& stamp) {
  const core::PlanarOdometry& o = drive.odometry();
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = frames.odom;
  t.child_frame_id = frames.base;
  t.transform = toTransform(core::Vec3(o.x, o.y, 0.0), yaw(o.heading));
  return t;
}

DrivePorts::DrivePorts(ros::NodeHandle& nh, const std::string& prefix, const std::string& name,
                       const io::DriveTopics& topics, DriveFrames frames, long long every,
                       const std::function<void(double, double, double)>& command)
    : topics_(topics), frames_(std::move(frames)), every_(std::max(1LL, every)) {
  const std::string ns = driveNamespace(prefix, name, topics_);
  const auto topic = [&](const std::string& t) { return deviceTopic(ns, t); };
  const std::string cmd_vel = topic(topics_.cmd_vel_topic), odom = topic(topics_.odom_topic);
  odom_ = CountedPublisher::advertise<nav_msgs::Odometry>(nh, odom, kStreamQueue);
  if (topics_.publish_cmd)
    cmd_vel_out_ = CountedPublisher::advertise<geometry_msgs::TwistStamped>(nh, ns + "cmd_vel_out", kStreamQueue);
  const bool one_publisher = !topics_.allow_multiple_cmd_vel_publishers;
  // The callback reads its own subscriber's publishers through `this` (the class is neither copied nor moved).
  cmd_vel_ = nh.subscribe<geometry_msgs::Twist>(
      cmd_vel, 10, [this, command, one_publisher, name](const geometry_msgs::Twist::ConstPtr& m) {
        if (one_publisher && cmd_vel_.getNumPublishers() > 1) {
          ROS_ERROR_THROTTLE(1.0, "sim_node: controller '%s': %u publishers on cmd_vel, only 1 allowed: braking",
                             name.c_str(), cmd_vel_.getNumPublishers());
          command(0.0, 0.0, 0.0);
          return;
        }
        command(m->linear.x, m->angular.z, m->linear.y);
      });
  const std::string on_tf = topics_.enable_odom_tf ? ", " + frames_.odom + " -> " + frames_.base + " on tf" : "";
  ROS_INFO("sim_node: controller '%s' (a wheeled base's) on %s, odometry on %s%s", name.c_str(),
           nh.resolveName(cmd_vel).c_str(), nh.resolveName(odom).c_str(), on_tf.c_str());
}

void DrivePorts::publish(const core::DiffDrive& drive, const ros::Time& stamp, long long steps,
                         std::vector<geometry_msgs::TransformStamped>& tf) const {
  if (steps >= 0 && steps % every_ != 0) return;
  if (odom_.listened()) odom_.publish(odometryMessage(drive, topics_, frames_, stamp));
  if (topics_.enable_odom_tf) tf.push_back(odometryTransform(drive, frames_, stamp));
  if (cmd_vel_out_.listened()) {
    geometry_msgs::TwistStamped out;
    out.header.stamp = stamp;
    out.header.frame_id = frames_.base;
    out.twist.linear.x = drive.limitedLinear();
    out.twist.linear.y = drive.limitedLateral();
    out.twist.angular.z = drive.limitedAngular();
    cmd_vel_out_.publish(out);
  }
}

}  // namespace rigid_body_sim::node
