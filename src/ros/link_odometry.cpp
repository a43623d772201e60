// What robots' links report of where they are: link_odometry.h.
#include "rigid_body_sim/ros/link_odometry.h"

#include <geometry_msgs/Vector3Stamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/MagneticField.h>
#include <sensor_msgs/NavSatFix.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/link_imus.h"
#include "rigid_body_sim/ros/state_publisher.h"
#include "rigid_body_sim/ros/topic_claims.h"

namespace rigid_body_sim::node {

namespace {

/// A fix as hector's gazebo_ros_gps publishes it: the covariance in east,
/// north, up, DIAGONAL_KNOWN unless a heading turns unequal axes.
sensor_msgs::NavSatFix fixMessage(const core::GnssFix& f, const std_msgs::Header& header, int status, int service) {
  sensor_msgs::NavSatFix m;
  m.header = header;
  m.status.status = static_cast<std::int8_t>(status);
  m.status.service = static_cast<std::uint16_t>(service);
  m.latitude = f.latitude;
  m.longitude = f.longitude;
  m.altitude = f.altitude;
  bool diagonal = true;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      m.position_covariance[3 * i + j] = f.position_covariance_ENU(i, j);
      diagonal = diagonal && (i == j || f.position_covariance_ENU(i, j) == 0.0);
    }
  }
  m.position_covariance_type =
      diagonal ? sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN : sensor_msgs::NavSatFix::COVARIANCE_TYPE_KNOWN;
  return m;
}

geometry_msgs::Vector3Stamped vectorMessage(const core::Vec3& v, const std_msgs::Header& header) {
  geometry_msgs::Vector3Stamped m;
  m.header = header;
  m.vector.x = v.x();
  m.vector.y = v.y();
  m.vector.z = v.z();
  return m;
}

}  // namespace

void LinkOdometry::addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                            const io::RobotSensors& sensors) {
  ros::NodeHandle& nh = *handles_.emplace_back(ownHandle(nh_));
  RobotPorts ports;
  const auto resolved = [&](const std::string& topic) { return deviceTopic(prefix, topic); };
  const auto every = [&](double rate) { return std::max(1LL, std::llround(1.0 / (rate * dt_))); };
  const auto hz = [&](const Schedule& at) { return 1.0 / (static_cast<double>(at.every) * dt_); };
  for (const io::RobotOdometry& o : sensors.odometry) {
    const io::OdometryEntry& e = o.entry;
    Port p;
    p.at = Schedule{o.link, o.X_LS, every(e.rate > 0.0 ? e.rate : publish_rate_)};
    p.child = frame_prefix + e.link;
    if (!e.frame_id.empty()) p.frame = frame_prefix + e.frame_id;
    p.on_tf = e.on_tf;
    if (p.on_tf && !broadcaster_) broadcaster_.emplace();
    if (e.noise) p.noise.emplace(*e.noise);
    p.odom = CountedPublisher::advertise<nav_msgs::Odometry>(nh, resolved(e.topic), 10);
    if (!e.ground_truth.empty()) {
      p.truth = CountedPublisher::advertise<nav_msgs::Odometry>(nh, resolved(e.ground_truth), 10);
    }
    const std::string on_tf = p.on_tf ? ", " + p.frame + " -> " + p.child + " on tf" : "";
    ROS_INFO("sim_node: odometry of '%s' link '%s' on %s at %g Hz%s%s", robot.c_str(), e.link.c_str(),
             nh_.resolveName(resolved(e.topic)).c_str(), hz(p.at), e.noise ? ", with noise" : "", on_tf.c_str());
    ports.odometry.push_back(std::move(p));
  }
  for (const io::RobotGnss& g : sensors.gnss) {
    const io::GnssEntry& e = g.entry;
    FixPort p{Schedule{g.link, g.X_LS, e.rate > 0.0 ? every(e.rate) : 1},
              core::Gnss(e.settings),
              frame_prefix + e.frame_id,
              e.status,
              e.service,
              {},
              {}};
    p.fix = CountedPublisher::advertise<sensor_msgs::NavSatFix>(nh, resolved(e.topic), 10);
    p.velocity = CountedPublisher::advertise<geometry_msgs::Vector3Stamped>(nh, resolved(e.velocity_topic), 10);
    ROS_INFO("sim_node: GNSS of '%s' on link '%s': fix on %s, velocity on %s at %g Hz", robot.c_str(), e.link.c_str(),
             nh_.resolveName(resolved(e.topic)).c_str(), nh_.resolveName(resolved(e.velocity_topic)).c_str(), hz(p.at));
    ports.fixes.push_back(std::move(p));
  }
  for (const io::RobotMagnetometer& m : sensors.magnetometers) {
    const io::MagnetometerEntry& e = m.entry;
    FieldPort p{Schedule{m.link, m.X_LS, e.rate > 0.0 ? every(e.rate) : 1},
                core::Magnetometer(e.settings),
                frame_prefix + e.frame_id,
                e.field_message,
                {}};
    p.field = e.field_message ? CountedPublisher::advertise<sensor_msgs::MagneticField>(nh, resolved(e.topic), 10)
                              : CountedPublisher::advertise<geometry_msgs::Vector3Stamped>(nh, resolved(e.topic), 10);
    ROS_INFO("sim_node: magnetometer of '%s' on link '%s' on %s at %g Hz", robot.c_str(), e.link.c_str(),
             nh_.resolveName(resolved(e.topic)).c_str(), hz(p.at));
    ports.fields.push_back(std::move(p));
  }
  robots_.push_back(std::move(ports));
}

std::vector<std::string> LinkOdometry::tfFrames(std::size_t r) const {
  std::vector<std::string> out;
  for (const Port& p : robots_.at(r).odometry) {
    if (p.on_tf) out.push_back(p.child);
  }
  return out;
}

void LinkOdometry::restart() {
  for (RobotPorts& ports : robots_) {
    for (Port& p : ports.odometry) {
      if (p.noise) p.noise->restart();
    }
    for (FixPort& p : ports.fixes) p.gnss.restart();
    for (FieldPort& p : ports.fields) p.magnetometer.restart();
  }
}

void LinkOdometry::publish(const core::Simulation& sim, long long steps, double t, const ros::Time& stamp) {
  std_msgs::Header header;
  header.stamp = stamp;
  header.frame_id = world_frame_;
  tf_.clear();
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    bool placed = false;
    // The frame at X_LS in its link, the robot's links placed once for all its reports.
    const auto frame = [&](const Schedule& at) {
      if (!placed) {
        core::kinematics(sim.scene.robots()[r].model, sim.robots[r], kin_);
        placed = true;
      }
      return core::frameState(linkStateOf(kin_, at.link), at.X_LS);
    };
    RobotPorts& ports = robots_[r];
    for (Port& p : ports.odometry) {
      if (steps % p.at.every != 0) continue;
      const core::LinkState link = frame(p.at);
      const double elapsed = p.at.elapsed(t, dt_);
      const core::OdomReport report = p.noise ? p.noise->report(link, elapsed) : core::exactOdom(link);
      if (!ros::ok()) continue;
      std_msgs::Header h = header;
      if (!p.frame.empty()) h.frame_id = p.frame;
      if (p.odom.listened()) p.odom.publish(odometryMessage(report, p.child, h, std::nullopt));
      if (p.truth.listened()) p.truth.publish(odometryMessage(core::exactOdom(link), p.child, h, std::nullopt));
      if (p.on_tf) {
        geometry_msgs::TransformStamped& tf = tf_.emplace_back();
        tf.header = h;
        tf.child_frame_id = p.child;
        tf.transform = toTransform(report.p_WL, report.q_WL);
      }
    }
    for (FixPort& p : ports.fixes) {
      if (steps % p.at.every != 0) continue;
      const core::LinkState link = frame(p.at);
      const core::GnssFix fix = p.gnss.report(link.p_WL, link.v_WL, p.at.elapsed(t, dt_));
      std_msgs::Header h = header;
      h.frame_id = p.frame;
      if (!ros::ok()) continue;
      if (p.fix.listened()) p.fix.publish(fixMessage(fix, h, p.status, p.service));
      if (p.velocity.listened()) p.velocity.publish(vectorMessage(fix.v_NWU, h));
    }
    for (FieldPort& p : ports.fields) {
      if (steps % p.at.every != 0) continue;
      const core::Vec3 field = p.magnetometer.report(frame(p.at).q_WL, p.at.elapsed(t, dt_));
      std_msgs::Header h = header;
      h.frame_id = p.frame;
      if (!ros::ok() || !p.field.listened()) continue;
      if (p.field_message) {
        sensor_msgs::MagneticField m;  // its covariance all zeros: unknown, as hector's
        m.header = h;
        m.magnetic_field = vectorMessage(field, h).vector;
        p.field.publish(m);
      } else {
        p.field.publish(vectorMessage(field, h));
      }
    }
  }
  if (!tf_.empty() && broadcaster_ && ros::ok()) broadcaster_->sendTransform(tf_);
}

}  // namespace rigid_body_sim::node
