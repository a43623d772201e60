// The topics of robots' link sensors: each robot's core::LinkSensors (its
// IMUs, odometry, GNSS receivers, magnetometers, lidars, range finders and
// depth cameras, sampled by the core at their rates of sim time,
// core/devices/link_sensors.h) and, beside each channel, the port that
// turns its fresh samples into messages stamped on the node's clock:
// - an IMU's sensor_msgs/Imu (REP 145);
// - odometry, a robot's `odom_noise` (its base on `odom` with the noise,
//   exact on `ground_truth`) and Gazebo's gazebo_ros_p3d, a
//   nav_msgs/Odometry of its link: the pose in the world frame, the twist
//   in the link's axes (child_frame_id); gazebo_ros_planar_move's and
//   force_based_move's, the truth in their odometry frame (where the world
//   is), odom -> link on tf too;
// - hector's GNSS receivers (sensor_msgs/NavSatFix and its velocity,
//   geometry_msgs/Vector3Stamped) and magnetometers (Vector3Stamped or
//   sensor_msgs/MagneticField);
// - a lidar's sensor_msgs/LaserScan (one fan) or PointCloud2 (several), a
//   range finder's sensor_msgs/Range, in the sensor's frame; a depth
//   camera's TOPIC/depth/image_raw (sensor_msgs/Image, 32FC1 or 16UC1),
//   TOPIC/depth/camera_info and TOPIC/depth/points (range_messages.h);
// - a force-torque sensor's geometry_msgs/WrenchStamped (Gazebo's
//   gazebo_ros_ft_sensor: what its joint carries onto its child link, in
//   that link's frame), a contact sensor's rigid_body_sim/Contacts (Gazebo's
//   gazebo_ros_bumper: every pair touching its link, the link on the `body`
//   side, in the world frame or a frame fixed to the link;
//   gazebo_msgs/ContactsState is not in Debian 12).
// A ray device or force sensor nobody listens to is not read; every noise
// is what it would be if someone had. A robot's sensors and their ports are one record,
// added and dropped together.
#pragma once

#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rigid_body_sim/core/devices/link_sensors.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/io/sensor_mount.h"
#include "rigid_body_sim/ros/counted_publisher.h"

namespace rigid_body_sim::node {

class LinkSensorPorts {
 public:
  /// Each odometry of rate 0 at `publish_rate` Hz; `world_frame` heads every message.
  LinkSensorPorts(const ros::NodeHandle& nh, double dt, double publish_rate, std::string world_frame)
      : nh_(nh), dt_(dt), publish_rate_(publish_rate), world_frame_(std::move(world_frame)) {}
  /// Robot r of `sim` (the last added) and its link sensors of `sensors`,
  /// started from its state now: topics under `prefix` (an absolute topic
  /// as it is), frames after `frame_prefix`.
  void addRobot(const core::Simulation& sim, std::size_t r, const std::string& prefix, const std::string& frame_prefix,
                const io::RobotSensors& sensors);
  /// The frames robot r's odometry puts on tf (odom -> frame, after its
  /// tf_prefix): the world's frame of its base leaves tf for them.
  std::vector<std::string> tfFrames(std::size_t r) const;
  /// Robot r deleted: its topics close; the later robots move down by one.
  void removeRobot(std::size_t r);
  /// Bytes the lidars and cameras of every robot may hold (io::RobotSensors::bytes):
  /// what a spawn's devices are counted on top of. Read on the spawn thread, changed on the loop's.
  std::uintmax_t bytes() const { return bytes_.load(); }
  /// Robot r was put somewhere (set_model_configuration, a reset): each of
  /// its IMUs' next period starts now.
  void restartImus(const core::Simulation& sim, std::size_t r);
  /// After a reset: every robot's IMUs restarted, each drift from zero, each noise from its seed.
  void restart(const core::Simulation& sim);
  /// Before a step of `sim`: the velocities its force-torque sensors read the step's acceleration from.
  void before(const core::Simulation& sim);
  /// Samples what is due after step `steps` of `sim`'s state (sim time
  /// t; its contact ledger updated with the step), under `robot_loads`
  /// (the step's, per robot, or none), and publishes it, stamped `stamp`.
  void publish(const core::Simulation& sim, const std::vector<core::ArticulationLoads>& robot_loads, long long steps,
               double t, const ros::Time& stamp);

 private:
  struct ImuPort {
    std::string frame;
    CountedPublisher imu;
  };
  struct OdometryPort {
    std::string child;   ///< the link's frame: the twist's axes
    std::string frame;   ///< the pose's frame ("": the world's)
    bool on_tf = false;  ///< frame -> child on tf too
    CountedPublisher odom, truth;
  };
  struct FixPort {
    std::string frame;
    int status = 0, service = 1;
    CountedPublisher fix, velocity;
  };
  struct FieldPort {
    std::string frame;
    bool field_message = false;
    CountedPublisher field;
  };
  struct LidarPort {
    std::string frame;
    double rate = 10.0;                   ///< its entry's Hz: a LaserScan's scan_time is 1 / rate
    std::optional<io::RangeEntry> range;  ///< a range finder: its Range's fields
    bool organized = false;               ///< a cloud of every ray (LidarEntry::organized)
    CountedPublisher publisher;
  };
  struct CameraPort {
    std::string frame;
    bool millimetres = false;
    CountedPublisher image, info, points;
  };
  struct WrenchPort {
    std::string frame;  ///< the child link's, after the robot's tf_prefix
    CountedPublisher wrench;
  };
  struct ContactPort {
    std::string frame;  ///< the world's, or the one the sensor names
    CountedPublisher contacts;
  };
  /// One robot: its own handle first (what it opened closes before it), its
  /// sensors, and a port per channel, in the channels' order.
  struct Robot {
    Robot(std::shared_ptr<ros::NodeHandle> handle, core::LinkSensors set, std::uintmax_t held)
        : nh(std::move(handle)), sensors(std::move(set)), bytes(held) {}
    std::shared_ptr<ros::NodeHandle> nh;  ///< ownHandle
    core::LinkSensors sensors;
    std::vector<ImuPort> imus;
    std::vector<OdometryPort> odometry;
    std::vector<FixPort> fixes;
    std::vector<FieldPort> fields;
    std::vector<LidarPort> lidars;
    std::vector<CameraPort> cameras;
    std::vector<WrenchPort> wrenches;
    std::vector<ContactPort> contacts;
    std::uintmax_t bytes = 0;  ///< what its lidars and cameras may hold
  };

  /// Robot `robot`'s (named `name`) lidars and depth cameras: their ports.
  void addRangePorts(Robot& robot, const char* name, const std::string& prefix, const std::string& frame_prefix,
                     const io::RobotSensors& sensors);
  /// Its force-torque and contact sensors' ports.
  void addForcePorts(Robot& robot, const char* name, const core::ArticulationModel& model, const std::string& prefix,
                     const std::string& frame_prefix, const io::RobotSensors& sensors);
  /// Which of robot `robot`'s ray devices and force sensors someone listens to: those read.
  static void chooseWanted(Robot& robot);
  /// Publishes its lidars', cameras' and force sensors' fresh samples.
  static void publishRanges(const Robot& robot, const ros::Time& stamp);
  void publishForces(const core::Model& model, const Robot& robot, const ros::Time& stamp) const;

  /// Publishes robot `robot`'s fresh samples.
  void publishRobot(const Robot& robot, const std_msgs::Header& header);

  ros::NodeHandle nh_;
  double dt_, publish_rate_;
  std::string world_frame_;
  std::vector<Robot> robots_;
  std::atomic<std::uintmax_t> bytes_{0};
  std::vector<geometry_msgs::TransformStamped> tf_;           ///< this publication's, reused
  std::optional<tf2_ros::TransformBroadcaster> broadcaster_;  ///< made with the first odometry on tf
};

}  // namespace rigid_body_sim::node
