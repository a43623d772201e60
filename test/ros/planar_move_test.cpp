// gazebo_ros_planar_move in a robot's markup (planar_move.test,
// test/ros/planar_move.urdf): its base driven at the commanded twist in its
// heading, its odometry the truth in `odom`, odom -> base_footprint on tf in
// place of world -> base_footprint.
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/BodyStates.h"

namespace {

using namespace rbs_test;

TEST(GazeboPlanarMove, ItsBaseMovesAtTheCommandedTwistAndItsOdometryIsTheTruthInOdom) {
  ros::NodeHandle nh;
  std::vector<nav_msgs::Odometry> odom;
  ros::Subscriber odom_sub = nh.subscribe<nav_msgs::Odometry>(
      "/odom", 1000, [&](const nav_msgs::Odometry::ConstPtr& m) { odom.push_back(*m); });
  std::vector<rigid_body_sim::BodyStates> truth;
  ros::Subscriber truth_sub = nh.subscribe<rigid_body_sim::BodyStates>(
      "/sim_node/body_states", 1000, [&](const rigid_body_sim::BodyStates::ConstPtr& m) { truth.push_back(*m); });
  std::vector<std::string> parents;  // of base_footprint on /tf
  ros::Subscriber tf_sub = nh.subscribe<tf2_msgs::TFMessage>("/tf", 1000, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
    for (const auto& t : m->transforms) {
      if (t.child_frame_id == "base_footprint") parents.push_back(t.header.frame_id);
    }
  });
  ros::Publisher cmd_vel = nh.advertise<geometry_msgs::Twist>("/cmd_vel", 10);
  ASSERT_TRUE(spinUntil([&] { return cmd_vel.getNumSubscribers() > 0; }, 30.0));  // the plugin's drive listens
  ASSERT_TRUE(spinUntil([&] { return !odom.empty() && !truth.empty() && !parents.empty(); }, 30.0));
  const auto simTime = [&] { return truth.back().header.stamp.toSec(); };
  // `cmd` sent for `seconds` of sim time from `from`.
  const auto send = [&](const geometry_msgs::Twist& cmd, double from, double seconds) {
    return spinUntil(
        [&] {
          cmd_vel.publish(cmd);
          return simTime() >= from + seconds;
        },
        60.0);
  };
  // Holonomic: forward, sideways and turning at once, in its own heading.
  geometry_msgs::Twist cmd;
  cmd.linear.x = 0.3;
  cmd.linear.y = -0.2;
  cmd.angular.z = 0.4;
  const double start = simTime();
  ASSERT_TRUE(send(cmd, start, 3.0));
  // Its twist in its own axes (body_states gives the root link's) over the last second.
  double vx = 0.0, vy = 0.0, wz = 0.0;
  int n = 0;
  for (const auto& s : truth) {
    if (s.header.stamp.toSec() < start + 2.0) continue;
    vx += s.twists.at(0).linear.x;
    vy += s.twists[0].linear.y;
    wz += s.twists[0].angular.z;
    ++n;
  }
  ASSERT_GT(n, 10);
  EXPECT_NEAR(vx / n, 0.3, 0.006);
  EXPECT_NEAR(vy / n, -0.2, 0.004);
  EXPECT_NEAR(wz / n, 0.4, 0.008);
  // Its odometry: the truth, in odom (where the world is), at 50 Hz.
  const nav_msgs::Odometry& o = odom.back();
  EXPECT_EQ(o.header.frame_id, "odom");
  EXPECT_EQ(o.child_frame_id, "base_footprint");
  bool compared = false;
  for (const auto& s : truth) {
    if (s.header.stamp != o.header.stamp) continue;
    EXPECT_NEAR(o.pose.pose.position.x, s.poses.at(0).position.x, 1e-9);
    EXPECT_NEAR(o.pose.pose.position.y, s.poses[0].position.y, 1e-9);
    EXPECT_NEAR(o.pose.pose.orientation.z, s.poses[0].orientation.z, 1e-9);
    EXPECT_NEAR(o.twist.twist.linear.x, s.twists[0].linear.x, 1e-9);
    compared = true;
  }
  EXPECT_TRUE(compared) << "no body_states at the odometry's stamp";
  // At 50 Hz of sim time: its stamps 0.02 s apart (a busy machine may drop one, never add one).
  EXPECT_NEAR(leastSpacing(odom), 0.02, 1e-9) << "s between two odometry messages, at least";
  // One parent for base_footprint on tf: odom, never the world.
  for (const std::string& p : parents) EXPECT_EQ(p, "odom");
  // Held until the next command (the plugin has no timeout): a zero stops it.
  // At 4x under ASan the zero can reach the node most of a second of sim
  // time after it is sent (it drifted at 6.8 mm/s after 1 s in CI once), so
  // the wait is for the stop, within 3 s; then, unsent, the zero is held.
  const auto speed = [&] { return std::hypot(truth.back().twists[0].linear.x, truth.back().twists[0].linear.y); };
  const double stop_from = simTime();
  ASSERT_TRUE(spinUntil(
      [&] {
        cmd_vel.publish(geometry_msgs::Twist());
        return speed() < 1e-3 || simTime() >= stop_from + 3.0;
      },
      60.0));
  EXPECT_LT(speed(), 1e-3) << "m/s, 3 s of sim time after a zero";
  const double held_from = simTime();
  ASSERT_TRUE(spinUntil([&] { return simTime() >= held_from + 1.0; }, 60.0));
  EXPECT_LT(speed(), 1e-3) << "m/s, 1 s after the last zero";
}

}  // namespace
