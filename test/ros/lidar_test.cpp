// A robot's lidars in the node (lidar.test): what a subscriber receives on
// /scan (sensor_msgs/LaserScan) and /points (sensor_msgs/PointCloud2) from
// the wheeled base at rest 1.9 m before a wall: the wall at its distance
// over the cosine, REP 117's +inf where nothing is within range, the
// robot's own links unseen, stamped on the node's clock in base_link.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud2_iterator.h>

#include <cmath>
#include <limits>

#include "node_fixture.h"

namespace {

using namespace rbs_test;

TEST(Lidar, ReadsTheWallAtItsDistanceAndInfinityPastMaxRange) {
  ros::NodeHandle nh;
  sensor_msgs::LaserScan scan;
  int scans = 0;
  ros::Subscriber sub =
      nh.subscribe<sensor_msgs::LaserScan>("/scan", 10, [&](const sensor_msgs::LaserScan::ConstPtr& m) {
        scan = *m;
        ++scans;
      });
  ASSERT_TRUE(spinUntil([&] { return scans >= 3; }, 30.0));  // the base has settled on its wheels
  EXPECT_EQ(scan.header.frame_id, "base_link");
  ASSERT_EQ(scan.ranges.size(), 361u);
  EXPECT_NEAR(scan.angle_increment, M_PI / 180, 1e-6);
  EXPECT_FLOAT_EQ(scan.range_min, 0.3F);
  EXPECT_FLOAT_EQ(scan.range_max, 5.0F);
  EXPECT_FLOAT_EQ(scan.scan_time, 0.1F);
  // Ray k is at −π + k°: straight ahead (k = 180) the wall is 1.9 m away, at 30° 1.9 / cos 30°.
  EXPECT_NEAR(scan.ranges[180], 1.9, 0.01);
  EXPECT_NEAR(scan.ranges[210], 1.9 / std::cos(M_PI / 6), 0.01);
  EXPECT_NEAR(scan.ranges[150], 1.9 / std::cos(M_PI / 6), 0.01);
  // Behind and to the sides nothing is within 5 m (the wall ends 2 m to each side): +inf, as REP 117 says.
  EXPECT_EQ(scan.ranges[0], std::numeric_limits<float>::infinity());
  EXPECT_EQ(scan.ranges[90], std::numeric_limits<float>::infinity());
  EXPECT_EQ(scan.ranges[270], std::numeric_limits<float>::infinity());
  // The robot's own wheels, 0.18 m to each side, are not seen.
  for (const float r : scan.ranges) EXPECT_TRUE(std::isinf(r) || r > 1.8F) << r;
  EXPECT_GT(scan.header.stamp.toSec(), 0.0);
}

TEST(Lidar, ItsFansArePointsOnTheWall) {
  ros::NodeHandle nh;
  sensor_msgs::PointCloud2 cloud;
  bool got = false;
  ros::Subscriber sub =
      nh.subscribe<sensor_msgs::PointCloud2>("/points", 10, [&](const sensor_msgs::PointCloud2::ConstPtr& m) {
        cloud = *m;
        got = true;
      });
  ASSERT_TRUE(spinUntil([&] { return got; }, 30.0));
  EXPECT_EQ(cloud.header.frame_id, "base_link");
  // 4 fans of 91 rays within ±45°, level to 0.2 rad up: every one meets the wall (at most 1.9 / cos 45° = 2.7 m
  // away, at most 0.55 m up; it is 1 m high).
  ASSERT_EQ(cloud.width * cloud.height, 4u * 91u);
  sensor_msgs::PointCloud2ConstIterator<float> x(cloud, "x"), z(cloud, "z");
  for (; x != x.end(); ++x, ++z) {
    EXPECT_NEAR(*x, 1.9, 0.01);  // the wall's face, in base_link
    EXPECT_GT(*z, -1e-6);
    EXPECT_LT(*z, 1.9 * std::tan(0.2) / std::cos(M_PI / 4) + 0.01);
  }
}

}  // namespace
