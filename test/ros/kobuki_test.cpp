// Kobuki's gazebo_ros_kobuki in a robot's markup (kobuki.test,
// test/ros/kobuki_base.urdf), spawned as turtlebot_gazebo spawns it: its
// topics at the root, driven on mobile_base/commands/velocity at the
// commanded speed, braking after its timeout, its odometry odom ->
// base_footprint, its IMU on mobile_base/sensors/imu_data.
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>

#include <cmath>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/BodyStates.h"

namespace {

using namespace rbs_test;

TEST(GazeboKobuki, ItsBaseDrivesOnItsTopicsAndStopsAfterItsTimeout) {
  ros::NodeHandle nh;
  std::vector<nav_msgs::Odometry> odom;
  ros::Subscriber odom_sub = nh.subscribe<nav_msgs::Odometry>(
      "/odom", 5000, [&](const nav_msgs::Odometry::ConstPtr& m) { odom.push_back(*m); });
  std::vector<rigid_body_sim::BodyStates> truth;
  ros::Subscriber truth_sub = nh.subscribe<rigid_body_sim::BodyStates>(
      "/sim_node/body_states", 1000, [&](const rigid_body_sim::BodyStates::ConstPtr& m) { truth.push_back(*m); });
  std::vector<sensor_msgs::Imu> imu;
  ros::Subscriber imu_sub = nh.subscribe<sensor_msgs::Imu>(
      "/mobile_base/sensors/imu_data", 5000, [&](const sensor_msgs::Imu::ConstPtr& m) { imu.push_back(*m); });
  ros::Publisher cmd_vel = nh.advertise<geometry_msgs::Twist>("/mobile_base/commands/velocity", 10);
  ASSERT_TRUE(spinUntil([&] { return cmd_vel.getNumSubscribers() > 0; }, 30.0));  // the plugin's drive listens
  ASSERT_TRUE(spinUntil([&] { return odom.size() > 10 && imu.size() > 10 && !truth.empty(); }, 30.0));
  EXPECT_EQ(odom.back().header.frame_id, "odom");
  EXPECT_EQ(odom.back().child_frame_id, "base_footprint");
  EXPECT_EQ(odom.back().pose.covariance[35], 0.05);  // the plugin's
  // Its IMU at rest: g up within the sensor's noise, headed base_link, every step.
  const sensor_msgs::Imu& at_rest = imu.back();
  EXPECT_EQ(at_rest.header.frame_id, "base_link");
  EXPECT_NEAR(at_rest.linear_acceleration.z, 9.81, 0.1);
  EXPECT_NEAR(leastSpacing(imu), 0.001, 1e-9);
  const auto simTime = [&] { return truth.back().header.stamp.toSec(); };
  geometry_msgs::Twist cmd;
  cmd.linear.x = 0.3;
  const double start = simTime();
  ASSERT_TRUE(spinUntil(
      [&] {
        cmd_vel.publish(cmd);
        return simTime() >= start + 2.0;
      },
      60.0));
  double v = 0.0;
  int n = 0;
  for (const auto& s : truth) {
    if (s.header.stamp.toSec() < start + 1.0) continue;
    v += s.twists.at(0).linear.x;
    ++n;
  }
  ASSERT_GT(n, 10);
  EXPECT_NEAR(v / n, 0.3, 0.006) << "m/s, the truth over the last second";
  EXPECT_NEAR(odom.back().twist.twist.linear.x, 0.3, 0.006);
  // No command for 1 s: braked after its 0.6 s timeout.
  const double stop = simTime();
  ASSERT_TRUE(spinUntil([&] { return simTime() >= stop + 1.2; }, 60.0));
  EXPECT_NEAR(truth.back().twists.at(0).linear.x, 0.0, 0.01);
}

}  // namespace
