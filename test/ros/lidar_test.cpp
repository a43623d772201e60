// A robot's lidars in the node (lidar.test): what a subscriber receives on
// /scan (sensor_msgs/LaserScan, from the URDF's Gazebo markup) and /points
// (sensor_msgs/PointCloud2, from the config) from the wheeled base at rest
// 1.9 m before a wall: the wall at its distance over the cosine, REP 117's
// +inf where nothing is within range, the robot's own links unseen; the
// depth camera's image; and what the IMUs on its links read at rest (REP 145).
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud2_iterator.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

#include "cloud_field.h"
#include "node_fixture.h"
#include "rigid_body_sim/BodyStates.h"

namespace {

using namespace rbs_test;

TEST(Lidar, DeclaredInGazeboMarkupReadsTheWallAndInfinityPastMaxRange) {
  ros::NodeHandle nh;
  sensor_msgs::LaserScan scan;
  int scans = 0;
  ros::Subscriber sub =
      nh.subscribe<sensor_msgs::LaserScan>("/scan", 10, [&](const sensor_msgs::LaserScan::ConstPtr& m) {
        scan = *m;
        ++scans;
      });
  ASSERT_TRUE(spinUntil([&] { return scans >= 3; }, 30.0));  // the base has settled on its wheels
  // As the markup says: 360 beams from -pi to pi, 0.12 to 10 m, 10 Hz, in laser_link.
  EXPECT_EQ(scan.header.frame_id, "laser_link");
  ASSERT_EQ(scan.ranges.size(), 360u);
  EXPECT_NEAR(scan.angle_min, -M_PI, 1e-6);
  EXPECT_NEAR(scan.angle_increment, 2.0 * M_PI / 359.0, 1e-6);
  EXPECT_FLOAT_EQ(scan.range_min, 0.12F);
  EXPECT_FLOAT_EQ(scan.range_max, 10.0F);
  EXPECT_FLOAT_EQ(scan.scan_time, 0.1F);
  int on_wall = 0, beyond = 0;
  for (std::size_t k = 0; k < scan.ranges.size(); ++k) {
    const double angle = scan.angle_min + static_cast<double>(k) * scan.angle_increment;
    if (std::abs(angle) < M_PI / 4) {  // the wall, 1.8 m ahead of the laser (it is 0.1 m ahead of the axle)
      EXPECT_NEAR(scan.ranges[k], 1.8 / std::cos(angle), 0.01) << k;
      ++on_wall;
    } else if (std::abs(angle) > M_PI / 2) {  // behind: nothing within 10 m, +inf as REP 117 says
      EXPECT_EQ(scan.ranges[k], std::numeric_limits<float>::infinity()) << k;
      ++beyond;
    }
  }
  EXPECT_GE(on_wall, 85);
  EXPECT_GT(beyond, 170);
  // The robot's own chassis, wheels and caster are not seen.
  for (const float r : scan.ranges) EXPECT_TRUE(std::isinf(r) || r > 1.7F) << r;
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
  for (std::size_t n = 0; n < 4u * 91u; ++n) {  // Velodyne's fields
    const auto x = cloudField<float>(cloud, n, "x"), y = cloudField<float>(cloud, n, "y");
    const auto z = cloudField<float>(cloud, n, "z");
    EXPECT_NEAR(x, 1.9, 0.01);  // the wall's face, in base_link
    EXPECT_GT(z, -1e-6);
    EXPECT_LT(z, 1.9 * std::tan(0.2) / std::cos(M_PI / 4) + 0.01);
    // Azimuth by azimuth, each from its lowest fan (ring 0, level) up by 0.2 / 3 rad.
    EXPECT_EQ(cloudField<uint16_t>(cloud, n, "ring"), n % 4) << n;
    EXPECT_NEAR(std::atan2(z, std::hypot(x, y)), 0.2 / 3.0 * (n % 4), 1e-4) << n;
  }
}

// The depth camera on base_link (0.08 m up, looking along x, 60 degrees across 64 pixels): rows that look
// level or up see the wall's face, 1.9 m away at every pixel (depth is along the optical axis); rows that
// look down by b = (v - cy) / f more than 0.08 / 1.9 see the ground, at depth 0.08 / b.
TEST(Lidar, ADepthCameraReadsTheWallsDistancePerPixel) {
  ros::NodeHandle nh;
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
  bool got_image = false, got_info = false;
  ros::Subscriber a =
      nh.subscribe<sensor_msgs::Image>("/camera/depth/image_raw", 2, [&](const sensor_msgs::Image::ConstPtr& m) {
        image = *m;
        got_image = true;
      });
  ros::Subscriber b = nh.subscribe<sensor_msgs::CameraInfo>("/camera/depth/camera_info", 2,
                                                            [&](const sensor_msgs::CameraInfo::ConstPtr& m) {
                                                              info = *m;
                                                              got_info = true;
                                                            });
  ASSERT_TRUE(spinUntil([&] { return got_image && got_info; }, 30.0));
  ASSERT_EQ(image.encoding, "32FC1");
  ASSERT_EQ(image.width, 64u);
  ASSERT_EQ(image.height, 48u);
  ASSERT_EQ(image.step, 64u * 4u);
  EXPECT_EQ(image.header.frame_id, "base_link");
  const double f = 32.0 / std::tan(M_PI / 6);
  EXPECT_NEAR(info.K[0], f, 1e-9);
  EXPECT_NEAR(info.K[2], 31.5, 1e-12);
  EXPECT_NEAR(info.K[5], 23.5, 1e-12);
  int wall = 0, ground = 0;
  for (int v = 0; v < 48; ++v) {
    const double down = (v - 23.5) / f;
    for (int u = 0; u < 64; ++u) {
      float depth = 0.0F;
      std::memcpy(&depth, &image.data[static_cast<std::size_t>(4 * (v * 64 + u))], 4);
      if (down < 0.08 / 1.9 - 0.01) {
        EXPECT_NEAR(depth, 1.9, 0.01) << u << ", " << v;
        ++wall;
      } else if (down > 0.08 / 1.9 + 0.01) {
        EXPECT_NEAR(depth, 0.08 / down, 0.01) << u << ", " << v;
        ++ground;
      }
    }
  }
  EXPECT_GT(wall, 64 * 20);
  EXPECT_GT(ground, 64 * 15);
  // Its points: organized as the image (64 x 48), each pixel's z its depth.
  sensor_msgs::PointCloud2 cloud;
  bool got_cloud = false;
  ros::Subscriber c = nh.subscribe<sensor_msgs::PointCloud2>("/camera/depth/points", 2,
                                                             [&](const sensor_msgs::PointCloud2::ConstPtr& m) {
                                                               cloud = *m;
                                                               got_cloud = true;
                                                             });
  ASSERT_TRUE(spinUntil([&] { return got_cloud; }, 30.0));
  ASSERT_EQ(cloud.width, 64u);
  ASSERT_EQ(cloud.height, 48u);
  sensor_msgs::PointCloud2ConstIterator<float> z(cloud, "z");
  for (int v = 0; v < 48; ++v) {
    const double down = (v - 23.5) / f;
    for (int u = 0; u < 64; ++u, ++z) {
      if (down < 0.08 / 1.9 - 0.01) EXPECT_NEAR(*z, 1.9, 0.01) << u << ", " << v;
      if (down > 0.08 / 1.9 + 0.01) EXPECT_NEAR(*z, 0.08 / down, 0.01) << u << ", " << v;
    }
  }
}

/// Every message on `topic` until `count` came; the last two.
std::pair<sensor_msgs::Imu, sensor_msgs::Imu> lastImus(const std::string& topic, int count) {
  ros::NodeHandle nh;
  sensor_msgs::Imu before, last;
  int n = 0;
  ros::Subscriber sub = nh.subscribe<sensor_msgs::Imu>(topic, 100, [&](const sensor_msgs::Imu::ConstPtr& m) {
    before = last;
    last = *m;
    ++n;
  });
  EXPECT_TRUE(spinUntil([&] { return n >= count; }, 30.0)) << topic;
  return {before, last};
}

Eigen::Quaterniond quaternionOf(const geometry_msgs::Quaternion& q) { return {q.w, q.x, q.y, q.z}; }
Eigen::Vector3d vectorOf(const geometry_msgs::Vector3& v) { return {v.x, v.y, v.z}; }

/// At rest, REP 145: the specific force is gravity's reaction, +g up, in
/// the sensor's axes as the reported orientation has them; no rotation.
void expectAtRest(const sensor_msgs::Imu& m) {
  const Eigen::Quaterniond q_WS = quaternionOf(m.orientation);
  EXPECT_NEAR(q_WS.norm(), 1.0, 1e-6);
  const Eigen::Vector3d f_S = vectorOf(m.linear_acceleration);
  EXPECT_LT((q_WS * f_S - Eigen::Vector3d(0, 0, 9.81)).norm(), 0.05) << f_S.transpose();
  EXPECT_LT(vectorOf(m.angular_velocity).norm(), 0.01);
  EXPECT_GT(m.header.stamp.toSec(), 0.0);
}

TEST(RobotImu, DeclaredInGazeboMarkupReadsGravityUpAt100Hz) {
  const auto [before, m] = lastImus("/imu", 150);  // 1.5 s: the base has settled on its wheels
  EXPECT_EQ(m.header.frame_id, "imu_link");
  expectAtRest(m);
  // imu_link is level with the base: +g along its z, the base facing +x.
  EXPECT_NEAR(m.linear_acceleration.z, 9.81, 0.05);
  EXPECT_LT((quaternionOf(m.orientation) * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX()).norm(), 0.02);
  EXPECT_NEAR((m.header.stamp - before.header.stamp).toSec(), 0.01, 1e-6);  // <updateRateHZ> 100
}

TEST(RobotImu, OnAWheelRolledAQuarterTurnItsZPointsAlongTheAxle) {
  const auto [before, m] = lastImus("/wheel_imu", 75);
  EXPECT_EQ(m.header.frame_id, "left_wheel");  // no frame_id: the link's
  expectAtRest(m);
  // Rolled a quarter turn about x, the sensor's z is the wheel's -y, the
  // axle, whatever angle the wheel stands at: gravity has no z part.
  EXPECT_LT((quaternionOf(m.orientation) * Eigen::Vector3d::UnitZ() + Eigen::Vector3d::UnitY()).norm(), 0.02);
  EXPECT_NEAR(m.linear_acceleration.z, 0.0, 0.05);
  EXPECT_NEAR((m.header.stamp - before.header.stamp).toSec(), 0.02, 1e-6);  // rate 50
}

// cmd_vel on the robot (a body's key): its base, rolling on its free
// wheels, driven to 0.2 m/s along its heading by a wrench, as a body is.
// Registered last: it moves the base off its place before the wall.
TEST(RobotBase, ItsCmdVelDrivesTheBaseAsABodysDrivesTheBody) {
  ros::NodeHandle nh;
  std::vector<sensor_msgs::Imu> imu;
  ros::Subscriber sub =
      nh.subscribe<sensor_msgs::Imu>("/imu", 100, [&](const sensor_msgs::Imu::ConstPtr& m) { imu.push_back(*m); });
  rigid_body_sim::BodyStates states;
  ros::Subscriber truth = nh.subscribe<rigid_body_sim::BodyStates>(
      "/sim_node/body_states", 10, [&](const rigid_body_sim::BodyStates::ConstPtr& m) { states = *m; });
  ros::Publisher cmd_vel = nh.advertise<geometry_msgs::Twist>("/cmd_vel", 10);
  ASSERT_TRUE(spinUntil([&] { return !imu.empty() && !states.names.empty(); }, 30.0));
  ASSERT_TRUE(spinUntil([&] { return cmd_vel.getNumSubscribers() > 0; }, 30.0));  // the drive listens
  geometry_msgs::Twist forward;
  forward.linear.x = 0.2;
  const double until = simNow(imu.back().header.stamp.toSec()) + 3.0;  // under ASan the first commands may come late
  while (ros::ok() && imu.back().header.stamp.toSec() < until) {
    cmd_vel.publish(forward);
    spinUntil([] { return false; }, 0.02);
  }
  ASSERT_EQ(states.twist_frames.at(0), "base_link");  // the twist in the base's axes
  EXPECT_NEAR(states.twists.at(0).linear.x, 0.2, 0.01);
  EXPECT_NEAR(states.twists[0].angular.z, 0.0, 0.01);
  EXPECT_GT(states.poses.at(0).position.x, 0.15);
}

}  // namespace
