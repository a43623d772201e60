// The robots' lidars and depth cameras in the node: range_sensors.h.
#include "rigid_body_sim/ros/range_sensors.h"

#include <sensor_msgs/point_cloud2_iterator.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>

#include "rigid_body_sim/ros/topic_claims.h"

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

void RangeSensors::addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                            const std::vector<io::RobotLidar>& lidars, const std::vector<io::RobotCamera>& cameras) {
  ros::NodeHandle& nh = *handles_.emplace_back(ownHandle(nh_));
  std::vector<CameraPort> camera_ports;
  for (const io::RobotCamera& c : cameras) {
    bytes_ += core::depthCameraBytes(c.entry.settings);
    const std::string& frame = c.entry.frame_id.empty() ? c.entry.link : c.entry.frame_id;
    CameraPort p{
        core::DepthCamera(c.entry.settings), c.link, c.X_LS, 1, c.entry.millimetres, frame_prefix + frame, {}, {}, {}};
    p.every = std::max(1LL, std::llround(1.0 / (c.entry.rate * dt_)));
    const std::array<std::string, 3> topics = cameraTopics(prefix, c.entry);  // image, info, points
    const std::string ns = deviceTopic(prefix, c.entry.topic) + "/";
    p.image = CountedPublisher::advertise<sensor_msgs::Image>(nh, topics[0], 2);
    p.info = CountedPublisher::advertise<sensor_msgs::CameraInfo>(nh, topics[1], 2);
    p.points = CountedPublisher::advertise<sensor_msgs::PointCloud2>(nh, topics[2], 2);
    ROS_INFO("sim_node: robot '%s': a depth camera of %d x %d on '%s', %s{%s, %s, %s} at %g Hz", robot.c_str(),
             c.entry.settings.width, c.entry.settings.height, p.frame.c_str(), nh_.resolveName(ns).c_str(),
             c.entry.image_topic.c_str(), c.entry.info_topic.c_str(), c.entry.points_topic.c_str(), c.entry.rate);
    camera_ports.push_back(std::move(p));
  }
  cameras_.push_back(std::move(camera_ports));
  std::vector<Port> ports;
  for (const io::RobotLidar& l : lidars) {
    bytes_ += core::lidarBytes(l.entry.settings);
    const std::string& frame = l.entry.frame_id.empty() ? l.entry.link : l.entry.frame_id;
    Port p{core::Lidar(l.entry.settings), l.link, l.X_LS, l.entry.rate, 1,
           frame_prefix + frame,          {},     {},     {},           l.entry.organized};
    p.every = std::max(1LL, std::llround(1.0 / (l.entry.rate * dt_)));
    const bool cloud = l.entry.settings.vertical_samples > 1;
    const std::string topic = deviceTopic(prefix, l.entry.topic);
    if (l.entry.range) {
      p.range = l.entry.range;
      p.finder.emplace(l.entry.range->settings);
      p.publisher = CountedPublisher::advertise<sensor_msgs::Range>(nh, topic, 10);
    } else {
      p.publisher = cloud ? CountedPublisher::advertise<sensor_msgs::PointCloud2>(nh, topic, 10)
                          : CountedPublisher::advertise<sensor_msgs::LaserScan>(nh, topic, 10);
    }
    ROS_INFO("sim_node: robot '%s': a %s of %zu rays on '%s', %s on %s at %g Hz", robot.c_str(),
             p.range ? "range finder" : "lidar", p.lidar.rayCount(), p.frame.c_str(),
             p.range ? "sensor_msgs/Range"
             : cloud ? "sensor_msgs/PointCloud2"
                     : "sensor_msgs/LaserScan",
             nh_.resolveName(topic).c_str(), p.rate);
    ports.push_back(std::move(p));
  }
  robots_.push_back(std::move(ports));
}

void RangeSensors::removeRobot(std::size_t r) {
  for (const Port& p : robots_.at(r)) bytes_ -= core::lidarBytes(p.lidar.settings());
  for (const CameraPort& p : cameras_.at(r)) bytes_ -= core::depthCameraBytes(p.camera.settings());
  robots_.erase(robots_.begin() + static_cast<std::ptrdiff_t>(r));
  cameras_.erase(cameras_.begin() + static_cast<std::ptrdiff_t>(r));
  handles_.erase(handles_.begin() + static_cast<std::ptrdiff_t>(r));  // after what it opened
}

void RangeSensors::restart() {
  for (std::vector<Port>& ports : robots_) {
    for (Port& p : ports) {
      p.lidar.restart();
      if (p.finder) p.finder->restart();
    }
  }
  for (std::vector<CameraPort>& ports : cameras_) {
    for (CameraPort& p : ports) p.camera.restart();
  }
}

core::Pose RangeSensors::sensorPose(const core::Simulation& sim, std::size_t r, int link, const core::Pose& X_LS,
                                    bool& placed) {
  const core::SceneRobot& robot = sim.scene.robots()[r];
  if (!placed) {  // the robot's links, once for all its sensors
    core::kinematics(robot.model, sim.robots[r], kin_);
    skip_.assign(sim.model().bodyCount(), 0);
    for (std::size_t k = 0; k < robot.link.size(); ++k) skip_[static_cast<std::size_t>(robot.first_body) + k] = 1;
    placed = true;
  }
  const core::Placement X_WS = kin_.X_WL[static_cast<std::size_t>(link)] * core::Placement::of(X_LS);
  return core::Pose{core::Quat(X_WS.R_PC), X_WS.p_PC};
}

void RangeSensors::sample(const core::Simulation& sim, long long steps, const ros::Time& stamp) {
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    bool placed = false;
    for (Port& p : robots_[r]) {
      if (steps % p.every != 0 || !p.publisher.listened()) continue;
      p.lidar.scan(sim.model(), sim.state, sensorPose(sim, r, p.link, p.X_LS, placed), skip_, ranges_);
      if (p.finder) {
        const core::LidarSettings& s = p.lidar.settings();
        p.publisher.publish(
            rangeMessage(p.lidar, *p.range, p.finder->reading(ranges_, s.min_range, s.max_range), p.frame, stamp));
      } else if (p.lidar.settings().vertical_samples > 1) {
        p.publisher.publish(cloudMessage(p.lidar, ranges_, p.organized, p.frame, stamp));
      } else {
        p.publisher.publish(scanMessage(p.lidar, ranges_, p.rate, p.frame, stamp));
      }
    }
    for (CameraPort& p : cameras_[r]) {
      if (steps % p.every != 0) continue;
      if (p.info.listened()) p.info.publish(cameraInfoMessage(p.camera, p.frame, stamp));
      if (!p.image.listened() && !p.points.listened()) continue;
      p.camera.capture(sim.model(), sim.state, sensorPose(sim, r, p.link, p.X_LS, placed), skip_, depth_);
      if (p.image.listened()) p.image.publish(depthImageMessage(p.camera, depth_, p.millimetres, p.frame, stamp));
      if (p.points.listened()) p.points.publish(depthCloudMessage(p.camera, depth_, p.frame, stamp));
    }
  }
}

}  // namespace rigid_body_sim::node
