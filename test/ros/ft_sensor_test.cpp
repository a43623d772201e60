// gazebo_ros_ft_sensor on a robot's joint (ft_sensor.test,
// test/ros/ft_sensor.urdf): geometry_msgs/WrenchStamped of what the joint
// carries onto its bar, in the bar's frame, at its rate; a box put on the
// bar adds its weight and its moment through their contact.
#include <geometry_msgs/WrenchStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/SpawnBody.h"

namespace {

using namespace rbs_test;

/// The mean of the wrenches stamped after `after` s, once there are 50.
geometry_msgs::Wrench meanAfter(std::vector<geometry_msgs::WrenchStamped>& got, double after) {
  std::vector<geometry_msgs::WrenchStamped> seen;
  EXPECT_TRUE(spinUntil(
      [&] {
        for (const auto& m : got) {
          if (m.header.stamp.toSec() > after) seen.push_back(m);
        }
        got.clear();
        return seen.size() >= 50;
      },
      30.0));
  geometry_msgs::Wrench mean;
  const double n = static_cast<double>(seen.size());
  for (const auto& m : seen) {
    mean.force.x += m.wrench.force.x / n;
    mean.force.y += m.wrench.force.y / n;
    mean.force.z += m.wrench.force.z / n;
    mean.torque.x += m.wrench.torque.x / n;
    mean.torque.y += m.wrench.torque.y / n;
    mean.torque.z += m.wrench.torque.z / n;
  }
  return mean;
}

TEST(GazeboForceTorque, ItsJointsWrenchCarriesTheBarAndWhatRestsOnIt) {
  ros::NodeHandle nh;
  std::vector<geometry_msgs::WrenchStamped> ft;
  ros::Subscriber ft_sub = nh.subscribe<geometry_msgs::WrenchStamped>(
      "/ft", 1000, [&](const geometry_msgs::WrenchStamped::ConstPtr& m) { ft.push_back(*m); });
  std::vector<sensor_msgs::JointState> joints;
  ros::Subscriber joint_sub = nh.subscribe<sensor_msgs::JointState>(
      "/joint_states", 1000, [&](const sensor_msgs::JointState::ConstPtr& m) { joints.push_back(*m); });
  ASSERT_TRUE(spinUntil([&] { return ft.size() > 10 && !joints.empty(); }, 30.0));
  EXPECT_EQ(ft.back().header.frame_id, "bar");  // the child link's, as the plugin's
  EXPECT_NEAR(leastSpacing(ft), 0.01, 1e-9);    // 100 Hz
  // Held level after a second: the joint bears the bar's 1 kg and its moment
  // about the shoulder, 9.81 N x 0.3 m, about -y (the bar's axes are the world's).
  const double settled = simNow(joints.back().header.stamp.toSec()) + 1.0;
  const geometry_msgs::Wrench bar = meanAfter(ft, settled);
  EXPECT_NEAR(bar.force.z, 9.81, 0.01);
  EXPECT_NEAR(bar.force.x, 0.0, 0.01);
  EXPECT_NEAR(bar.torque.y, -9.81 * 0.3, 0.01);
  // What the sensor reads about the axis is what the controller gives it.
  EXPECT_NEAR(bar.torque.y, joints.back().effort.at(0), 0.02);
  // A 1 kg box (urdf/box.urdf, 0.4 x 0.2 x 0.1 m) set on the bar, centred 0.4 m out.
  ASSERT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
  rigid_body_sim::SpawnBody box;
  box.request.name = "load";
  box.request.urdf_file = "package://rigid_body_sim/urdf/box.urdf";
  box.request.pose.position.x = 0.4;
  box.request.pose.position.z = 0.5 + 0.025 + 0.05 + 0.001;
  box.request.pose.orientation.w = 1.0;
  ASSERT_TRUE(ros::service::call("/sim_node/spawn_body", box)) << "the call";
  ASSERT_TRUE(box.response.success) << box.response.message;
  // Landed, the bar level again, and both asleep: the reading is then the
  // contacts they fell asleep with (physics.md §10.10), within 0.5 % of the
  // static load, where the controller's effort is exact.
  const double after = simNow(joints.back().header.stamp.toSec()) + 2.0;
  const geometry_msgs::Wrench loaded = meanAfter(ft, after);
  EXPECT_NEAR(loaded.force.z, 2.0 * 9.81, 0.1);
  EXPECT_NEAR(loaded.force.x, 0.0, 0.05);
  EXPECT_NEAR(loaded.torque.y, -9.81 * (0.3 + 0.4), 0.05);
  EXPECT_NEAR(joints.back().effort.at(0), -9.81 * (0.3 + 0.4), 0.005);
  std::printf("ft_sensor: bar %.4f N, %.4f N*m; with the box %.4f N, %.4f N*m (effort %.4f)\n", bar.force.z,
              bar.torque.y, loaded.force.z, loaded.torque.y, joints.back().effort.at(0));
}

}  // namespace
