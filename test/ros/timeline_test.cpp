// A config's timeline in the node (timeline.test): the shipped scenario run
// in lock-step (paused, then ~step) publishes on /base_controller/odom what
// rbsim writes for the same URDF and config, to the last bit (issue 57).
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../scratch_dir.h"
#include "node_fixture.h"
#include "rigid_body_sim/Step.h"

namespace {

using namespace rbs_test;

/// rbsim's odometry rows by their step (t / dt), each t,x,y,heading,linear,lateral,angular.
std::map<long long, std::vector<double>> rbsimOdometry() {
  const std::string out = rigid_body_sim::test::scratch().path().string();
  const std::string src = RBS_SOURCE_DIR;
  const std::string cmd = std::string(RBS_RBSIM) + " --urdf " + src + "/urdf/diff_drive.urdf --config " + src +
                          "/config/diff_drive_timeline.yaml --duration 3 --quiet --out " + out +
                          " 2>/dev/null >/dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(out + "/diff_drive.base_controller.odom.csv");
  std::string line;
  std::getline(in, line);
  std::map<long long, std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> x;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) x.push_back(std::strtod(cell.c_str(), nullptr));
    rows[std::llround(x.at(0) / kDt)] = x;
  }
  return rows;
}

TEST(Timeline, TheNodeInLockStepPublishesRbsimsOdometryToTheLastBit) {
  ros::NodeHandle nh;
  std::vector<nav_msgs::Odometry> odom;
  ros::Subscriber sub = nh.subscribe<nav_msgs::Odometry>(
      "/base_controller/odom", 1000, [&](const nav_msgs::Odometry::ConstPtr& m) { odom.push_back(*m); });
  ros::ServiceClient step = nh.serviceClient<rigid_body_sim::Step>("/sim_node/step");
  ASSERT_TRUE(step.waitForExistence(ros::Duration(30.0)));
  ASSERT_TRUE(spinUntil([&] { return sub.getNumPublishers() > 0; }, 30.0));
  // 3 s in batches of 0.3 s, each batch's 15 messages in before the next.
  for (int batch = 1; batch <= 10; ++batch) {
    rigid_body_sim::Step srv;
    srv.request.steps = 300;
    ASSERT_TRUE(step.call(srv) && srv.response.success) << srv.response.message;
    ASSERT_TRUE(
        spinUntil([&] { return !odom.empty() && odom.back().header.stamp.toSec() >= 0.3 * batch - 1e-9; }, 30.0))
        << "batch " << batch;
  }
  const std::map<long long, std::vector<double>> rows = rbsimOdometry();
  ASSERT_EQ(rows.size(), 151u);
  int compared = 0;
  for (const nav_msgs::Odometry& m : odom) {
    const long long k = std::llround(m.header.stamp.toSec() / kDt);
    const auto it = rows.find(k);
    ASSERT_NE(it, rows.end()) << "no rbsim row at step " << k;
    const std::vector<double>& r = it->second;
    const Eigen::Quaterniond q(Eigen::AngleAxisd(r[3], Eigen::Vector3d::UnitZ()));
    EXPECT_EQ(m.pose.pose.position.x, r[1]) << "t " << r[0];
    EXPECT_EQ(m.pose.pose.position.y, r[2]) << "t " << r[0];
    EXPECT_EQ(m.pose.pose.orientation.z, q.z()) << "t " << r[0];
    EXPECT_EQ(m.pose.pose.orientation.w, q.w()) << "t " << r[0];
    EXPECT_EQ(m.twist.twist.linear.x, r[4]) << "t " << r[0];
    EXPECT_EQ(m.twist.twist.linear.y, r[5]) << "t " << r[0];
    EXPECT_EQ(m.twist.twist.angular.z, r[6]) << "t " << r[0];
    ++compared;
  }
  EXPECT_GE(compared, 150);  // every 20 steps (the one at start may come before the subscription)
  // And it moved: 0.5 m/s on an arc for 2 s.
  EXPECT_GT(odom.back().pose.pose.position.x, 0.8);
}

}  // namespace
