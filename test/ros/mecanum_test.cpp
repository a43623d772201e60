// A mecanum base as Ridgeback's and Dingo-O's are described for Gazebo
// (mecanum.test, test/ros/mecanum_base.urdf): its MecanumDriveController
// turns the wheels for a body twist with v_y and counts its odometry from
// them; force_based_move on cmd_vel moves the base, sideways too.
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <cmath>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/BodyStates.h"

namespace {

using namespace rbs_test;

TEST(MecanumBase, ItsControllerTurnsTheWheelsForATwistAndTheBasePluginMovesIt) {
  ros::NodeHandle nh;
  std::vector<nav_msgs::Odometry> wheel_odom;
  ros::Subscriber odom_sub = nh.subscribe<nav_msgs::Odometry>(
      "/omni_controller/odom", 1000, [&](const nav_msgs::Odometry::ConstPtr& m) { wheel_odom.push_back(*m); });
  std::vector<rigid_body_sim::BodyStates> truth;
  ros::Subscriber truth_sub = nh.subscribe<rigid_body_sim::BodyStates>(
      "/sim_node/body_states", 1000, [&](const rigid_body_sim::BodyStates::ConstPtr& m) { truth.push_back(*m); });
  ros::Publisher wheels = nh.advertise<geometry_msgs::Twist>("/omni_controller/cmd_vel", 10);
  ros::Publisher base = nh.advertise<geometry_msgs::Twist>("/cmd_vel", 10);
  ASSERT_TRUE(spinUntil([&] { return wheels.getNumSubscribers() > 0 && base.getNumSubscribers() > 0; }, 30.0));
  ASSERT_TRUE(spinUntil([&] { return !wheel_odom.empty() && !truth.empty(); }, 30.0));
  const auto simTime = [&] { return truth.back().header.stamp.toSec(); };
  const auto send = [&](ros::Publisher& pub, const geometry_msgs::Twist& cmd, double seconds) {
    const double from = simNow(simTime());
    return spinUntil(
        [&] {
          pub.publish(cmd);
          return simTime() >= from + seconds;
        },
        60.0);
  };
  // The wheels alone (frictionless, as Ridgeback's): its odometry reads the
  // twist from their speeds; the base stays where it is.
  geometry_msgs::Twist cmd;
  cmd.linear.x = 0.2;
  cmd.linear.y = 0.1;
  cmd.angular.z = 0.3;
  const geometry_msgs::Pose before = truth.back().poses.at(0);
  ASSERT_TRUE(send(wheels, cmd, 1.5));
  const nav_msgs::Odometry& o = wheel_odom.back();
  EXPECT_NEAR(o.twist.twist.linear.x, 0.2, 0.004);
  EXPECT_NEAR(o.twist.twist.linear.y, 0.1, 0.004);
  EXPECT_NEAR(o.twist.twist.angular.z, 0.3, 0.006);
  EXPECT_EQ(o.child_frame_id, "base_link");
  const geometry_msgs::Pose after = truth.back().poses.at(0);
  EXPECT_LT(std::hypot(after.position.x - before.position.x, after.position.y - before.position.y), 0.01);
  // The base plugin on cmd_vel: sideways and forward at once, in the base's axes.
  cmd = geometry_msgs::Twist();
  cmd.linear.x = 0.3;
  cmd.linear.y = -0.2;
  const double start = simTime();
  ASSERT_TRUE(send(base, cmd, 2.0));
  double vx = 0.0, vy = 0.0;
  int n = 0;
  for (const auto& s : truth) {
    if (s.header.stamp.toSec() < start + 1.0) continue;
    vx += s.twists.at(0).linear.x;
    vy += s.twists[0].linear.y;
    ++n;
  }
  ASSERT_GT(n, 10);
  EXPECT_NEAR(vx / n, 0.3, 0.006);
  EXPECT_NEAR(vy / n, -0.2, 0.004);
}

}  // namespace
