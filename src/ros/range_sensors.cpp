// The robots' lidars in the node: range_sensors.h.
#include "rigid_body_sim/ros/range_sensors.h"

#include <sensor_msgs/point_cloud2_iterator.h>

#include <algorithm>
#include <cmath>

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

sensor_msgs::PointCloud2 cloudMessage(const core::Lidar& lidar, const std::vector<double>& ranges,
                                      const std::string& frame, const ros::Time& stamp) {
  sensor_msgs::PointCloud2 m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  sensor_msgs::PointCloud2Modifier modifier(m);
  modifier.setPointCloud2FieldsByString(1, "xyz");
  const auto finite =
      static_cast<std::size_t>(std::count_if(ranges.begin(), ranges.end(), [](double r) { return std::isfinite(r); }));
  modifier.resize(finite);
  m.height = 1;
  m.width = static_cast<uint32_t>(finite);
  m.is_dense = true;
  sensor_msgs::PointCloud2Iterator<float> x(m, "x"), y(m, "y"), z(m, "z");
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    if (!std::isfinite(ranges[k])) continue;
    const core::Vec3 p = ranges[k] * lidar.direction(k);
    *x = static_cast<float>(p.x());
    *y = static_cast<float>(p.y());
    *z = static_cast<float>(p.z());
    ++x;
    ++y;
    ++z;
  }
  return m;
}

void RangeSensors::addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                            const std::vector<io::RobotLidar>& lidars) {
  std::vector<Port> ports;
  for (const io::RobotLidar& l : lidars) {
    const std::string& frame = l.entry.frame_id.empty() ? l.entry.link : l.entry.frame_id;
    Port p{core::Lidar(l.entry.settings), l.link, l.X_LS, l.entry.rate, 1, frame_prefix + frame, {}};
    p.every = std::max(1LL, std::llround(1.0 / (l.entry.rate * dt_)));
    const bool cloud = l.entry.settings.vertical_samples > 1;
    const std::string topic = l.entry.topic.front() == '/' ? l.entry.topic : prefix + l.entry.topic;  // absolute
    p.publisher = cloud ? CountedPublisher::advertise<sensor_msgs::PointCloud2>(nh_, topic, 10)
                        : CountedPublisher::advertise<sensor_msgs::LaserScan>(nh_, topic, 10);
    ROS_INFO("sim_node: robot '%s': a lidar of %zu rays on '%s', %s on %s at %g Hz", robot.c_str(), p.lidar.rayCount(),
             p.frame.c_str(), cloud ? "sensor_msgs/PointCloud2" : "sensor_msgs/LaserScan",
             nh_.resolveName(topic).c_str(), p.rate);
    ports.push_back(std::move(p));
  }
  robots_.push_back(std::move(ports));
}

void RangeSensors::restart() {
  for (std::vector<Port>& ports : robots_) {
    for (Port& p : ports) p.lidar.restart();
  }
}

void RangeSensors::sample(const core::Simulation& sim, long long steps, const ros::Time& stamp) {
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    bool placed = false;
    for (Port& p : robots_[r]) {
      if (steps % p.every != 0 || !p.publisher.listened()) continue;
      const core::SceneRobot& robot = sim.scene.robots()[r];
      if (!placed) {  // the robot's links, once for all its lidars
        core::kinematics(robot.model, sim.robots[r], kin_);
        skip_.assign(sim.model().bodyCount(), 0);
        for (std::size_t k = 0; k < robot.link.size(); ++k) skip_[static_cast<std::size_t>(robot.first_body) + k] = 1;
        placed = true;
      }
      const core::Placement X_WS = kin_.X_WL[static_cast<std::size_t>(p.link)] * core::Placement::of(p.X_LS);
      p.lidar.scan(sim.model(), sim.state, core::Pose{core::Quat(X_WS.R_PC), X_WS.p_PC}, skip_, ranges_);
      if (p.lidar.settings().vertical_samples > 1) {
        p.publisher.publish(cloudMessage(p.lidar, ranges_, p.frame, stamp));
      } else {
        p.publisher.publish(scanMessage(p.lidar, ranges_, p.rate, p.frame, stamp));
      }
    }
  }
}

}  // namespace rigid_body_sim::node
