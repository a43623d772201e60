// The messages of lidars, range finders and depth cameras: range_messages.h.
#include "rigid_body_sim/ros/range_messages.h"

#include <sensor_msgs/point_cloud2_iterator.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>

namespace rigid_body_sim::node {

sensor_msgs::LaserScan scanMessage(const core::Lidar& lidar, const std::vector<double>& ranges, double rate,
                                   const std::string& frame, const ros::Time& stamp) {
  const core::LidarSettings& s = lidar.settings();
  sensor_msgs::LaserScan m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.angle_min = static_cast<float>(s.min_angle);
  m.angle_max = static_cast<float>(s.max_angle);
  m.angle_increment = static_cast<float>(lidar.angleIncrement());
  m.time_increment = 0.0F;  // every ray of a scan at one instant
  m.scan_time = static_cast<float>(1.0 / rate);
  m.range_min = static_cast<float>(s.min_range);
  m.range_max = static_cast<float>(s.max_range);
  m.ranges.assign(ranges.begin(), ranges.end());
  return m;
}

sensor_msgs::Range rangeMessage(const core::Lidar& lidar, const io::RangeEntry& range, double reading,
                                const std::string& frame, const ros::Time& stamp) {
  sensor_msgs::Range m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.radiation_type = range.infrared ? sensor_msgs::Range::INFRARED : sensor_msgs::Range::ULTRASOUND;
  m.field_of_view = static_cast<float>(range.field_of_view);
  m.min_range = static_cast<float>(lidar.settings().min_range);
  m.max_range = static_cast<float>(lidar.settings().max_range);
  m.range = static_cast<float>(reading);
  return m;
}

sensor_msgs::PointCloud2 cloudMessage(const core::Lidar& lidar, const std::vector<double>& ranges, bool organized,
                                      const std::string& frame, const ros::Time& stamp) {
  const auto samples = static_cast<std::size_t>(lidar.settings().samples);
  const auto fans = static_cast<std::size_t>(lidar.settings().vertical_samples);
  const std::size_t met =
      static_cast<std::size_t>(std::count_if(ranges.begin(), ranges.end(), [](double r) { return std::isfinite(r); }));
  // The Velodyne plugin's layout: its fields at its offsets, the rays of
  // one azimuth bottom fan (ring 0) to top, azimuth by azimuth.
  sensor_msgs::PointCloud2 m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.point_step = 22;
  for (const auto& [name, offset, type] : {std::tuple{"x", 0, sensor_msgs::PointField::FLOAT32},
                                           {"y", 4, sensor_msgs::PointField::FLOAT32},
                                           {"z", 8, sensor_msgs::PointField::FLOAT32},
                                           {"intensity", 12, sensor_msgs::PointField::FLOAT32},
                                           {"ring", 16, sensor_msgs::PointField::UINT16},
                                           {"time", 18, sensor_msgs::PointField::FLOAT32}}) {
    sensor_msgs::PointField f;
    f.name = name;
    f.offset = static_cast<uint32_t>(offset);
    f.datatype = type;
    f.count = 1;
    m.fields.push_back(f);
  }
  m.data.assign(m.point_step * (organized ? samples * fans : met), 0);
  uint8_t* out = m.data.data();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < samples; ++i) {
    for (std::size_t j = 0; j < fans; ++j) {
      const std::size_t k = j * samples + i;
      const bool hit = std::isfinite(ranges[k]);
      if (!hit && !organized) continue;
      const core::Vec3 p = hit ? core::Vec3(ranges[k] * lidar.direction(k)) : core::Vec3::Zero();
      const std::array<float, 4> xyzi{hit ? static_cast<float>(p.x()) : nan, hit ? static_cast<float>(p.y()) : nan,
                                      hit ? static_cast<float>(p.z()) : nan, hit ? 0.0F : nan};
      const auto ring = static_cast<uint16_t>(j);
      const float time = 0.0F;  // every ray of a scan at one instant
      std::memcpy(out, xyzi.data(), 16);
      std::memcpy(out + 16, &ring, 2);
      std::memcpy(out + 18, &time, 4);
      out += m.point_step;
    }
  }
  m.width = static_cast<uint32_t>(organized ? fans : met);
  m.height = static_cast<uint32_t>(organized ? samples : 1);
  m.row_step = m.point_step * m.width;
  m.is_dense = !organized;
  return m;
}

sensor_msgs::Image depthImageMessage(const core::DepthCamera& camera, const std::vector<double>& depth,
                                     bool millimetres, const std::string& frame, const ros::Time& stamp) {
  const core::DepthCameraSettings& s = camera.settings();
  sensor_msgs::Image m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.width = static_cast<uint32_t>(s.width);
  m.height = static_cast<uint32_t>(s.height);
  m.is_bigendian = 0;
  const std::size_t bytes = millimetres ? 2 : 4;
  m.encoding = millimetres ? "16UC1" : "32FC1";
  m.step = static_cast<uint32_t>(bytes * m.width);
  m.data.resize(bytes * depth.size());
  for (std::size_t k = 0; k < depth.size(); ++k) {
    if (millimetres) {
      const double mm = std::isfinite(depth[k]) ? std::min(std::round(1000.0 * depth[k]), 65535.0) : 0.0;
      const auto value = static_cast<uint16_t>(mm);
      std::memcpy(&m.data[2 * k], &value, 2);
    } else {
      const auto value = static_cast<float>(depth[k]);
      std::memcpy(&m.data[4 * k], &value, 4);
    }
  }
  return m;
}

sensor_msgs::CameraInfo cameraInfoMessage(const core::DepthCamera& camera, const std::string& frame,
                                          const ros::Time& stamp) {
  const core::DepthCameraSettings& s = camera.settings();
  sensor_msgs::CameraInfo m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.width = static_cast<uint32_t>(s.width);
  m.height = static_cast<uint32_t>(s.height);
  m.distortion_model = "plumb_bob";
  m.D.assign(5, 0.0);
  const double f = camera.focal();
  m.K = {f, 0.0, camera.cx(), 0.0, f, camera.cy(), 0.0, 0.0, 1.0};
  m.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  m.P = {f, 0.0, camera.cx(), 0.0, 0.0, f, camera.cy(), 0.0, 0.0, 0.0, 1.0, 0.0};
  return m;
}

sensor_msgs::PointCloud2 depthCloudMessage(const core::DepthCamera& camera, const std::vector<double>& depth,
                                           const std::string& frame, const ros::Time& stamp) {
  const auto width = static_cast<std::size_t>(camera.settings().width);
  const auto height = static_cast<std::size_t>(camera.settings().height);
  sensor_msgs::PointCloud2 m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  sensor_msgs::PointCloud2Modifier modifier(m);
  modifier.setPointCloud2FieldsByString(1, "xyz");
  modifier.resize(width * height);
  // Organized as the image, as gazebo_ros_openni_kinect's: a pixel that
  // sees nothing within range is NaN.
  m.width = static_cast<uint32_t>(width);
  m.height = static_cast<uint32_t>(height);
  m.row_step = m.point_step * m.width;
  m.is_dense = false;
  sensor_msgs::PointCloud2Iterator<float> x(m, "x"), y(m, "y"), z(m, "z");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t k = 0; k < depth.size(); ++k, ++x, ++y, ++z) {
    const std::size_t row = k / width;  // whole rows above this pixel
    const double u = static_cast<double>(k - row * width), v = static_cast<double>(row), d = depth[k];
    const bool seen = std::isfinite(d);
    *x = seen ? static_cast<float>((u - camera.cx()) * d / camera.focal()) : nan;
    *y = seen ? static_cast<float>((v - camera.cy()) * d / camera.focal()) : nan;
    *z = seen ? static_cast<float>(d) : nan;
  }
  return m;
}

}  // namespace rigid_body_sim::node
