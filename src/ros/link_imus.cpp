// The IMUs on robots' links: link_imus.h.
#include "rigid_body_sim/ros/link_imus.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/topic_claims.h"

namespace rigid_body_sim::node {
namespace {

/// Diagonal covariance σ² (row-major 3×3).
boost::array<double, 9> diagonal(double sigma) {
  boost::array<double, 9> c{};
  c[0] = c[4] = c[8] = sigma * sigma;
  return c;
}

}  // namespace

sensor_msgs::Imu imuMessage(const core::ImuReading& r, const core::ImuSettings& s, const std::string& frame,
                            const ros::Time& stamp) {
  sensor_msgs::Imu msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.orientation = toQuaternion(r.q_WS);
  msg.orientation_covariance = diagonal(s.orientation_noise);
  msg.angular_velocity = toVector3(r.w_S);
  msg.angular_velocity_covariance = diagonal(s.gyro_noise);
  msg.linear_acceleration = toVector3(r.f_S);
  msg.linear_acceleration_covariance = diagonal(s.accel_noise);
  return msg;
}

core::LinkState linkStateOf(const core::ArticulationKinematics& kin, int link) {
  const core::Placement& X_WL = kin.X_WL[static_cast<std::size_t>(link)];
  const core::Vec6& V_L = kin.V_L[static_cast<std::size_t>(link)];  // [ω; v] in the link's axes
  core::LinkState s;
  s.p_WL = X_WL.p_PC;
  s.q_WL = core::Quat(X_WL.R_PC).normalized();
  s.w_W = X_WL.R_PC * V_L.head<3>();
  s.v_WL = X_WL.R_PC * V_L.tail<3>();
  return s;
}

void LinkImus::addRobot(const core::Simulation& sim, std::size_t r, const std::string& prefix,
                        const std::string& frame_prefix, const std::vector<io::RobotImu>& imus) {
  core::kinematics(sim.scene.robots()[r].model, sim.robots[r], kin_);
  ros::NodeHandle& nh = *handles_.emplace_back(ownHandle(nh_));
  std::vector<Port> ports;
  for (const io::RobotImu& m : imus) {
    const io::ImuEntry& e = m.entry;
    Port p{core::Imu(e.settings, linkStateOf(kin_, m.link)),
           m.link,
           std::max(1LL, std::llround(1.0 / (e.settings.rate * dt_))),
           frame_prefix + e.frame_id,
           {}};
    const std::string topic = deviceTopic(prefix, e.topic);
    p.publisher = CountedPublisher::advertise<sensor_msgs::Imu>(nh, topic, 100);
    ROS_INFO("sim_node: IMU on '%s' link '%s', frame '%s', on %s at %g Hz", sim.scene.robots()[r].name.c_str(),
             e.link.c_str(), p.frame.c_str(), nh_.resolveName(topic).c_str(),
             1.0 / (static_cast<double>(p.every) * dt_));
    ports.push_back(std::move(p));
  }
  robots_.push_back(std::move(ports));
}

void LinkImus::restart(const core::Simulation& sim, std::size_t r) {
  if (robots_.at(r).empty()) return;
  core::kinematics(sim.scene.robots()[r].model, sim.robots[r], kin_);
  for (Port& p : robots_[r]) p.imu.restart(linkStateOf(kin_, p.link));
}

void LinkImus::sample(const core::Simulation& sim, long long steps, const ros::Time& stamp) {
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    bool placed = false;
    for (Port& p : robots_[r]) {
      if (steps % p.every != 0) continue;
      if (!placed) {  // the robot's links, once for all its IMUs
        core::kinematics(sim.scene.robots()[r].model, sim.robots[r], kin_);
        placed = true;
      }
      const core::ImuReading reading =
          p.imu.sample(linkStateOf(kin_, p.link), sim.model().gravity(), static_cast<double>(p.every) * dt_);
      if (ros::ok() && p.publisher.listened())
        p.publisher.publish(imuMessage(reading, p.imu.settings(), p.frame, stamp));
    }
  }
}

}  // namespace rigid_body_sim::node
