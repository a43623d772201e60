// The odometry of robots' links: link_odometry.h.
#include "rigid_body_sim/ros/link_odometry.h"

#include <nav_msgs/Odometry.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "rigid_body_sim/ros/link_imus.h"
#include "rigid_body_sim/ros/state_publisher.h"
#include "rigid_body_sim/ros/topic_claims.h"

namespace rigid_body_sim::node {

void LinkOdometry::addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                            const std::vector<io::RobotOdometry>& odometry) {
  ros::NodeHandle& nh = *handles_.emplace_back(ownHandle(nh_));
  std::vector<Port> ports;
  const auto resolved = [&](const std::string& topic) { return deviceTopic(prefix, topic); };
  for (const io::RobotOdometry& o : odometry) {
    const io::OdometryEntry& e = o.entry;
    Port p;
    p.link = o.link;
    p.X_LS = o.X_LS;
    p.every = std::max(1LL, std::llround(1.0 / ((e.rate > 0.0 ? e.rate : publish_rate_) * dt_)));
    p.child = frame_prefix + e.link;
    if (e.noise) p.noise.emplace(*e.noise);
    p.odom = CountedPublisher::advertise<nav_msgs::Odometry>(nh, resolved(e.topic), 10);
    if (!e.ground_truth.empty()) {
      p.truth = CountedPublisher::advertise<nav_msgs::Odometry>(nh, resolved(e.ground_truth), 10);
    }
    ROS_INFO("sim_node: odometry of '%s' link '%s' on %s at %g Hz%s", robot.c_str(), e.link.c_str(),
             nh_.resolveName(resolved(e.topic)).c_str(), 1.0 / (static_cast<double>(p.every) * dt_),
             e.noise ? ", with noise" : "");
    ports.push_back(std::move(p));
  }
  robots_.push_back(std::move(ports));
}

void LinkOdometry::restart() {
  for (std::vector<Port>& ports : robots_) {
    for (Port& p : ports) {
      if (p.noise) p.noise->restart();
    }
  }
}

void LinkOdometry::publish(const core::Simulation& sim, long long steps, double t, const ros::Time& stamp) {
  std_msgs::Header header;
  header.stamp = stamp;
  header.frame_id = world_frame_;
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    bool placed = false;
    for (Port& p : robots_[r]) {
      if (steps % p.every != 0) continue;
      if (!placed) {  // the robot's links, once for all its reports
        core::kinematics(sim.scene.robots()[r].model, sim.robots[r], kin_);
        placed = true;
      }
      const core::LinkState link = core::frameState(linkStateOf(kin_, p.link), p.X_LS);
      const core::OdomReport report = p.noise ? p.noise->report(link, t - p.last) : core::exactOdom(link);
      p.last = t;
      if (!ros::ok()) continue;
      if (p.odom.listened()) p.odom.publish(odometryMessage(report, p.child, header, std::nullopt));
      if (p.truth.listened()) p.truth.publish(odometryMessage(core::exactOdom(link), p.child, header, std::nullopt));
    }
  }
}

}  // namespace rigid_body_sim::node
