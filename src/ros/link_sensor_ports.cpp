// The topics of robots' link sensors: link_sensor_ports.h.
#include "rigid_body_sim/ros/link_sensor_ports.h"

#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>

#include <array>
#include <utility>

#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/range_messages.h"
#include "rigid_body_sim/ros/sensor_messages.h"
#include "rigid_body_sim/ros/state_publisher.h"
#include "rigid_body_sim/ros/topic_claims.h"

namespace rigid_body_sim::node {

void LinkSensorPorts::addRobot(const core::Simulation& sim, std::size_t r, const std::string& prefix,
                               const std::string& frame_prefix, const io::RobotSensors& sensors) {
  const core::SceneRobot& robot = sim.scene.robots()[r];
  Robot& ports = robots_.emplace_back(
      ownHandle(nh_), io::linkSensors(sensors, robot.model, sim.robots[r], dt_, publish_rate_), sensors.bytes);
  bytes_ += sensors.bytes;
  ros::NodeHandle& nh = *ports.nh;
  const char* name = robot.name.c_str();
  const auto resolved = [&](const std::string& topic) { return deviceTopic(prefix, topic); };
  const auto shown = [&](const std::string& topic) { return nh_.resolveName(resolved(topic)); };
  for (std::size_t i = 0; i < sensors.imus.size(); ++i) {
    const io::ImuEntry& e = sensors.imus[i].entry;
    ImuPort& p = ports.imus.emplace_back(ImuPort{frame_prefix + e.frame_id, {}});
    p.imu = CountedPublisher::advertise<sensor_msgs::Imu>(nh, resolved(e.topic), kStreamQueue);
    ROS_INFO("sim_node: IMU on '%s' link '%s', frame '%s', on %s at %g Hz", name, e.link.c_str(), p.frame.c_str(),
             shown(e.topic).c_str(), ports.sensors.imus()[i].clock.rate());
  }
  for (std::size_t i = 0; i < sensors.odometry.size(); ++i) {
    const io::OdometryEntry& e = sensors.odometry[i].entry;
    OdometryPort& p = ports.odometry.emplace_back();
    p.child = frame_prefix + e.link;
    if (!e.frame_id.empty()) p.frame = frame_prefix + e.frame_id;
    p.on_tf = e.on_tf;
    if (p.on_tf && !broadcaster_) broadcaster_.emplace();
    p.odom = CountedPublisher::advertise<nav_msgs::Odometry>(nh, resolved(e.topic), kStreamQueue);
    if (!e.ground_truth.empty()) {
      p.truth = CountedPublisher::advertise<nav_msgs::Odometry>(nh, resolved(e.ground_truth), kStreamQueue);
    }
    const std::string on_tf = p.on_tf ? ", " + p.frame + " -> " + p.child + " on tf" : "";
    ROS_INFO("sim_node: odometry of '%s' link '%s' on %s at %g Hz%s%s", name, e.link.c_str(), shown(e.topic).c_str(),
             ports.sensors.odometry()[i].clock.rate(), e.noise ? ", with noise" : "", on_tf.c_str());
  }
  for (std::size_t i = 0; i < sensors.gnss.size(); ++i) {
    const io::GnssEntry& e = sensors.gnss[i].entry;
    FixPort& p = ports.fixes.emplace_back(FixPort{frame_prefix + e.frame_id, e.status, e.service, {}, {}});
    p.fix = CountedPublisher::advertise<sensor_msgs::NavSatFix>(nh, resolved(e.topic), kStreamQueue);
    p.velocity =
        CountedPublisher::advertise<geometry_msgs::Vector3Stamped>(nh, resolved(e.velocity_topic), kStreamQueue);
    ROS_INFO("sim_node: GNSS of '%s' on link '%s': fix on %s, velocity on %s at %g Hz", name, e.link.c_str(),
             shown(e.topic).c_str(), shown(e.velocity_topic).c_str(), ports.sensors.gnss()[i].clock.rate());
  }
  for (std::size_t i = 0; i < sensors.magnetometers.size(); ++i) {
    const io::MagnetometerEntry& e = sensors.magnetometers[i].entry;
    FieldPort& p = ports.fields.emplace_back(FieldPort{frame_prefix + e.frame_id, e.field_message, {}});
    p.field = e.field_message
                  ? CountedPublisher::advertise<sensor_msgs::MagneticField>(nh, resolved(e.topic), kStreamQueue)
                  : CountedPublisher::advertise<geometry_msgs::Vector3Stamped>(nh, resolved(e.topic), kStreamQueue);
    ROS_INFO("sim_node: magnetometer of '%s' on link '%s' on %s at %g Hz", name, e.link.c_str(), shown(e.topic).c_str(),
             ports.sensors.magnetometers()[i].clock.rate());
  }
  addRangePorts(ports, name, prefix, frame_prefix, sensors);
  addForcePorts(ports, name, robot.model, prefix, frame_prefix, sensors);
}

void LinkSensorPorts::addForcePorts(Robot& robot, const char* name, const core::ArticulationModel& model,
                                    const std::string& prefix, const std::string& frame_prefix,
                                    const io::RobotSensors& sensors) {
  ros::NodeHandle& nh = *robot.nh;
  for (std::size_t i = 0; i < sensors.force_torques.size(); ++i) {
    const io::RobotForceTorque& f = sensors.force_torques[i];
    WrenchPort& p = robot.wrenches.emplace_back();
    p.frame = frame_prefix + model.links[static_cast<std::size_t>(f.link)].name;
    const std::string topic = deviceTopic(prefix, f.entry.topic);
    p.wrench = CountedPublisher::advertise<geometry_msgs::WrenchStamped>(nh, topic, kStreamQueue);
    ROS_INFO("sim_node: robot '%s': the force-torque sensor of joint '%s' on %s at %g Hz", name, f.entry.joint.c_str(),
             nh_.resolveName(topic).c_str(), robot.sensors.forceTorques()[i].clock.rate());
  }
  for (std::size_t i = 0; i < sensors.contact_sensors.size(); ++i) {
    const io::ContactSensorEntry& e = sensors.contact_sensors[i].entry;
    ContactPort& p = robot.contacts.emplace_back();
    p.frame = e.frame_id.empty() ? world_frame_ : frame_prefix + e.frame_id;
    const std::string topic = deviceTopic(prefix, e.topic);
    p.contacts = CountedPublisher::advertise<Contacts>(nh, topic, kStreamQueue);
    ROS_INFO("sim_node: robot '%s': the contacts of link '%s' on %s in '%s' at %g Hz", name, e.link.c_str(),
             nh_.resolveName(topic).c_str(), p.frame.c_str(), robot.sensors.contactSensors()[i].clock.rate());
  }
}

void LinkSensorPorts::addRangePorts(Robot& robot, const char* name, const std::string& prefix,
                                    const std::string& frame_prefix, const io::RobotSensors& sensors) {
  ros::NodeHandle& nh = *robot.nh;
  for (std::size_t i = 0; i < sensors.cameras.size(); ++i) {
    const io::DepthCameraEntry& e = sensors.cameras[i].entry;
    CameraPort& p = robot.cameras.emplace_back();
    p.frame = frame_prefix + (e.frame_id.empty() ? e.link : e.frame_id);
    p.millimetres = e.millimetres;
    const std::array<std::string, 3> topics = cameraTopics(prefix, e);  // image, info, points
    p.image = CountedPublisher::advertise<sensor_msgs::Image>(nh, topics[0], 2);
    p.info = CountedPublisher::advertise<sensor_msgs::CameraInfo>(nh, topics[1], 2);
    p.points = CountedPublisher::advertise<sensor_msgs::PointCloud2>(nh, topics[2], 2);
    ROS_INFO("sim_node: robot '%s': a depth camera of %d x %d on '%s', %s{%s, %s, %s} at %g Hz", name, e.settings.width,
             e.settings.height, p.frame.c_str(), nh_.resolveName(deviceTopic(prefix, e.topic) + "/").c_str(),
             e.image_topic.c_str(), e.info_topic.c_str(), e.points_topic.c_str(),
             robot.sensors.depthCameras()[i].clock.rate());
  }
  for (std::size_t i = 0; i < sensors.lidars.size(); ++i) {
    const io::LidarEntry& e = sensors.lidars[i].entry;
    LidarPort& p = robot.lidars.emplace_back();
    p.frame = frame_prefix + (e.frame_id.empty() ? e.link : e.frame_id);
    p.rate = e.rate;
    p.range = e.range;
    p.organized = e.organized;
    const bool cloud = e.settings.vertical_samples > 1;
    const std::string topic = deviceTopic(prefix, e.topic);
    p.publisher = p.range ? CountedPublisher::advertise<sensor_msgs::Range>(nh, topic, kStreamQueue)
                  : cloud ? CountedPublisher::advertise<sensor_msgs::PointCloud2>(nh, topic, 10)
                          : CountedPublisher::advertise<sensor_msgs::LaserScan>(nh, topic, kStreamQueue);
    ROS_INFO("sim_node: robot '%s': a %s of %zu rays on '%s', %s on %s at %g Hz", name,
             p.range ? "range finder" : "lidar", robot.sensors.lidars()[i].lidar.rayCount(), p.frame.c_str(),
             p.range ? "sensor_msgs/Range"
             : cloud ? "sensor_msgs/PointCloud2"
                     : "sensor_msgs/LaserScan",
             nh_.resolveName(topic).c_str(), robot.sensors.lidars()[i].clock.rate());
  }
}

void LinkSensorPorts::removeRobot(std::size_t r) {
  bytes_ -= robots_.at(r).bytes;
  robots_.erase(robots_.begin() + static_cast<std::ptrdiff_t>(r));
}

std::vector<std::string> LinkSensorPorts::tfFrames(std::size_t r) const {
  std::vector<std::string> out;
  for (const OdometryPort& p : robots_.at(r).odometry) {
    if (p.on_tf) out.push_back(p.child);
  }
  return out;
}

void LinkSensorPorts::restartImus(const core::Simulation& sim, std::size_t r) {
  robots_.at(r).sensors.restartImus(sim.scene.robots()[r].model, sim.robots[r]);
}

void LinkSensorPorts::restart(const core::Simulation& sim) {
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    restartImus(sim, r);
    robots_[r].sensors.restartNoise();
  }
}

void LinkSensorPorts::before(const core::Simulation& sim) {
  for (std::size_t r = 0; r < robots_.size(); ++r)
    robots_[r].sensors.before(sim.scene.robots()[r].model, sim.robots[r]);
}

void LinkSensorPorts::publish(const core::Simulation& sim, const std::vector<core::ArticulationLoads>& robot_loads,
                              long long steps, double t, const ros::Time& stamp) {
  std_msgs::Header header;
  header.stamp = stamp;
  header.frame_id = world_frame_;
  tf_.clear();
  core::StepContacts contacts(sim.model(), sim.state, sim.contacts, sim.workspace.bodies.contacts);
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    Robot& robot = robots_[r];
    if (robot.sensors.empty()) continue;
    chooseWanted(robot);
    const core::StepForces forces{r < robot_loads.size() ? &robot_loads[r] : nullptr, &contacts};
    const bool any = robot.sensors.sample(sim.scene, r, sim.state, sim.robots[r], steps, t, forces);
    if (any && ros::ok()) {
      publishRobot(robot, header);
      publishForces(sim.model(), robot, stamp);
    }
  }
  if (!tf_.empty() && broadcaster_ && ros::ok()) broadcaster_->sendTransform(tf_);
}

void LinkSensorPorts::publishRobot(const Robot& robot, const std_msgs::Header& header) {
  using Kind = core::LinkSensors::Kind;
  const core::LinkSensors& s = robot.sensors;
  for (std::size_t i = 0; i < robot.imus.size(); ++i) {
    const ImuPort& p = robot.imus[i];
    if (!s.fresh(Kind::kImu, i) || !p.imu.listened()) continue;
    const core::ImuChannel& c = s.imus()[i];
    p.imu.publish(imuMessage(c.reading, c.imu.settings(), p.frame, header.stamp));
  }
  for (std::size_t i = 0; i < robot.odometry.size(); ++i) {
    const OdometryPort& p = robot.odometry[i];
    if (!s.fresh(Kind::kOdometry, i)) continue;
    const core::OdometryChannel& c = s.odometry()[i];
    std_msgs::Header h = header;
    if (!p.frame.empty()) h.frame_id = p.frame;
    if (p.odom.listened()) p.odom.publish(odometryMessage(c.report, p.child, h, std::nullopt));
    if (p.truth.listened()) p.truth.publish(odometryMessage(c.truth, p.child, h, std::nullopt));
    if (p.on_tf) {
      geometry_msgs::TransformStamped& tf = tf_.emplace_back();
      tf.header = h;
      tf.child_frame_id = p.child;
      tf.transform = toTransform(c.report.p_WL, c.report.q_WL);
    }
  }
  for (std::size_t i = 0; i < robot.fixes.size(); ++i) {
    const FixPort& p = robot.fixes[i];
    if (!s.fresh(Kind::kGnss, i)) continue;
    std_msgs::Header h = header;
    h.frame_id = p.frame;
    const core::GnssFix& fix = s.gnss()[i].fix;
    if (p.fix.listened()) p.fix.publish(fixMessage(fix, h, p.status, p.service));
    if (p.velocity.listened()) p.velocity.publish(vectorMessage(fix.v_NWU, h));
  }
  for (std::size_t i = 0; i < robot.fields.size(); ++i) {
    const FieldPort& p = robot.fields[i];
    if (!s.fresh(Kind::kMagnetometer, i) || !p.field.listened()) continue;
    std_msgs::Header h = header;
    h.frame_id = p.frame;
    const core::Vec3& field = s.magnetometers()[i].field_S;
    if (p.field_message) {
      p.field.publish(magneticFieldMessage(field, h));
    } else {
      p.field.publish(vectorMessage(field, h));
    }
  }
  publishRanges(robot, header.stamp);
}

void LinkSensorPorts::chooseWanted(Robot& robot) {
  using Kind = core::LinkSensors::Kind;
  for (std::size_t i = 0; i < robot.lidars.size(); ++i) {
    robot.sensors.want(Kind::kLidar, i, robot.lidars[i].publisher.listened());
  }
  for (std::size_t i = 0; i < robot.cameras.size(); ++i) {
    const CameraPort& p = robot.cameras[i];
    robot.sensors.want(Kind::kDepthCamera, i, p.image.listened() || p.points.listened());
  }
  for (std::size_t i = 0; i < robot.wrenches.size(); ++i) {
    robot.sensors.want(Kind::kForceTorque, i, robot.wrenches[i].wrench.listened());
  }
  for (std::size_t i = 0; i < robot.contacts.size(); ++i) {
    robot.sensors.want(Kind::kContacts, i, robot.contacts[i].contacts.listened());
  }
}

void LinkSensorPorts::publishForces(const core::Model& model, const Robot& robot, const ros::Time& stamp) const {
  using Kind = core::LinkSensors::Kind;
  const core::LinkSensors& s = robot.sensors;
  for (std::size_t i = 0; i < robot.wrenches.size(); ++i) {
    const WrenchPort& p = robot.wrenches[i];
    const core::Vec6& w = s.forceTorques()[i].wrench;
    if (!s.fresh(Kind::kForceTorque, i) || !s.wanted(Kind::kForceTorque, i) || !w.allFinite()) continue;
    geometry_msgs::WrenchStamped m;  // nothing is published non-finite
    m.header.stamp = stamp;
    m.header.frame_id = p.frame;
    m.wrench.torque = toVector3(w.head<3>());
    m.wrench.force = toVector3(w.tail<3>());
    p.wrench.publish(m);
  }
  for (std::size_t i = 0; i < robot.contacts.size(); ++i) {
    const ContactPort& p = robot.contacts[i];
    if (!s.fresh(Kind::kContacts, i) || !s.wanted(Kind::kContacts, i)) continue;
    std_msgs::Header header;
    header.stamp = stamp;
    header.frame_id = p.frame;
    p.contacts.publish(contactsMessage(model, s.contactSensors()[i].pairs, header));
  }
}

void LinkSensorPorts::publishRanges(const Robot& robot, const ros::Time& stamp) {
  using Kind = core::LinkSensors::Kind;
  const core::LinkSensors& s = robot.sensors;
  for (std::size_t i = 0; i < robot.lidars.size(); ++i) {
    const LidarPort& p = robot.lidars[i];
    if (!s.fresh(Kind::kLidar, i) || !s.wanted(Kind::kLidar, i)) continue;
    const core::LidarChannel& c = s.lidars()[i];
    if (p.range) {
      p.publisher.publish(rangeMessage(c.lidar, *p.range, c.reading, p.frame, stamp));
    } else if (c.lidar.settings().vertical_samples > 1) {
      p.publisher.publish(cloudMessage(c.lidar, c.ranges, p.organized, p.frame, stamp));
    } else {
      p.publisher.publish(scanMessage(c.lidar, c.ranges, p.rate, p.frame, stamp));
    }
  }
  for (std::size_t i = 0; i < robot.cameras.size(); ++i) {
    const CameraPort& p = robot.cameras[i];
    if (!s.fresh(Kind::kDepthCamera, i)) continue;
    const core::DepthCameraChannel& c = s.depthCameras()[i];
    if (p.info.listened()) p.info.publish(cameraInfoMessage(c.camera, p.frame, stamp));
    if (!s.wanted(Kind::kDepthCamera, i)) continue;
    if (p.image.listened()) p.image.publish(depthImageMessage(c.camera, c.depth, p.millimetres, p.frame, stamp));
    if (p.points.listened()) p.points.publish(depthCloudMessage(c.camera, c.depth, p.frame, stamp));
  }
}

}  // namespace rigid_body_sim::node
