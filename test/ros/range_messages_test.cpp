// The range sensors' clouds (no master): a lidar of several fans laid out
// as the Velodyne plugin lays out its points (x, y, z, intensity, ring,
// time; azimuth by azimuth, ring 0 the lowest fan), every met ray in one
// row or, organized, every ray with NaN where none met; a depth camera's
// cloud organized as its image.
#include "rigid_body_sim/ros/range_messages.h"

#include <gtest/gtest.h>
#include <sensor_msgs/point_cloud2_iterator.h>

#include <cmath>
#include <limits>
#include <vector>

#include "cloud_field.h"

namespace rigid_body_sim::node {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

core::LidarSettings threeByTwo() {
  core::LidarSettings s;
  s.samples = 3;  // azimuths -0.5, 0, 0.5 rad
  s.min_angle = -0.5;
  s.max_angle = 0.5;
  s.vertical_samples = 2;  // elevations 0 and 0.25 rad
  s.vertical_min_angle = 0.0;
  s.vertical_max_angle = 0.25;
  return s;
}

TEST(RangeMessages, ALidarsCloudHasVelodynesFieldsAndOrder) {
  const core::Lidar lidar(threeByTwo());
  // Ranges fan by fan (the lowest first): one ray of the upper fan met nothing.
  const std::vector<double> ranges{1.0, 2.0, 3.0, 4.0, kInf, 6.0};
  const sensor_msgs::PointCloud2 m = cloudMessage(lidar, ranges, false, "velodyne", ros::Time(2.0));
  ASSERT_EQ(m.fields.size(), 6u);
  const char* names[] = {"x", "y", "z", "intensity", "ring", "time"};
  const uint32_t offsets[] = {0, 4, 8, 12, 16, 18};
  for (std::size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(m.fields[f].name, names[f]);
    EXPECT_EQ(m.fields[f].offset, offsets[f]);
    EXPECT_EQ(m.fields[f].datatype, f == 4 ? sensor_msgs::PointField::UINT16 : sensor_msgs::PointField::FLOAT32);
  }
  EXPECT_EQ(m.point_step, 22u);
  EXPECT_EQ(m.height, 1u);
  ASSERT_EQ(m.width, 5u);
  EXPECT_EQ(m.row_step, 5u * 22u);
  EXPECT_EQ(m.data.size(), 5u * 22u);
  EXPECT_TRUE(m.is_dense);
  EXPECT_EQ(m.header.frame_id, "velodyne");
  // Azimuth by azimuth, each from ring 0: rays 0, 3, 1, (4 met nothing), 2, 5.
  const std::size_t order[] = {0, 3, 1, 2, 5};
  using rbs_test::cloudField;
  for (std::size_t n = 0; n < 5; ++n) {
    const std::size_t k = order[n];
    const double azimuth = -0.5 + 0.5 * static_cast<double>(k % 3), elevation = 0.25 * static_cast<double>(k / 3);
    const double r = ranges[k];
    EXPECT_NEAR(cloudField<float>(m, n, "x"), r * std::cos(elevation) * std::cos(azimuth), 1e-6) << n;
    EXPECT_NEAR(cloudField<float>(m, n, "y"), r * std::cos(elevation) * std::sin(azimuth), 1e-6) << n;
    EXPECT_NEAR(cloudField<float>(m, n, "z"), r * std::sin(elevation), 1e-6) << n;
    EXPECT_EQ(cloudField<uint16_t>(m, n, "ring"), k / 3) << n;
    EXPECT_EQ(cloudField<float>(m, n, "intensity"), 0.0F);
    EXPECT_EQ(cloudField<float>(m, n, "time"), 0.0F);
  }
  // Organized: every ray, a row per azimuth, NaN where none met.
  const sensor_msgs::PointCloud2 o = cloudMessage(lidar, ranges, true, "velodyne", ros::Time(2.0));
  EXPECT_EQ(o.width, 2u);
  EXPECT_EQ(o.height, 3u);
  EXPECT_EQ(o.row_step, 2u * 22u);
  EXPECT_FALSE(o.is_dense);
  int nans = 0;
  for (std::size_t n = 0; n < 6; ++n) {
    EXPECT_EQ(cloudField<uint16_t>(o, n, "ring"), n % 2) << n;
    if (std::isnan(cloudField<float>(o, n, "x"))) {
      EXPECT_EQ(n, 3u);  // azimuth 1 (0 rad), ring 1: ray 4
      ++nans;
    }
  }
  EXPECT_EQ(nans, 1);
}

TEST(RangeMessages, ADepthCloudIsOrganizedAsItsImage) {
  core::DepthCameraSettings s;
  s.width = 4;
  s.height = 3;
  s.hfov = 1.0;
  const core::DepthCamera camera(s);
  std::vector<double> depth(12, 2.0);
  depth[5] = kInf;  // (u 1, v 1) sees nothing
  const sensor_msgs::PointCloud2 m = depthCloudMessage(camera, depth, "optical", ros::Time(1.0));
  EXPECT_EQ(m.width, 4u);
  EXPECT_EQ(m.height, 3u);
  EXPECT_EQ(m.row_step, 4u * m.point_step);
  EXPECT_FALSE(m.is_dense);
  sensor_msgs::PointCloud2ConstIterator<float> x(m, "x"), y(m, "y"), z(m, "z");
  for (std::size_t k = 0; k < 12; ++k, ++x, ++y, ++z) {
    const double u = static_cast<double>(k % 4), v = static_cast<double>(k / 4);
    if (k == 5) {
      EXPECT_TRUE(std::isnan(*x) && std::isnan(*y) && std::isnan(*z));
      continue;
    }
    EXPECT_NEAR(*x, (u - camera.cx()) * 2.0 / camera.focal(), 1e-6) << k;
    EXPECT_NEAR(*y, (v - camera.cy()) * 2.0 / camera.focal(), 1e-6) << k;
    EXPECT_EQ(*z, 2.0F);
  }
}

}  // namespace
}  // namespace rigid_body_sim::node
