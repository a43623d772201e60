// Where a robot's sensors sit: each entry of its config (`imu`, `lidar`,
// `depth_camera`) or of its URDF's Gazebo markup on one of its links, or on
// a link a fixed joint lumped into one (as a laser_link or an imu_link
// usually is), at its pose there; and a free body's (`imu`, `odom_noise`)
// on its root link. ROS-free.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/devices/body_sensors.h"
#include "rigid_body_sim/core/devices/link_sensors.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

/// A device of a robot, `entry` as its config or markup gives it, on the
/// moving link `link` (index in the model) at X_LS in that link's frame:
/// the sensor (at entry.pose in entry.link, a link or one lumped into a
/// moving one) or, for odometry, a GNSS receiver, a magnetometer, the
/// frame it reports (a contact sensor's: the frame its contacts are given
/// in, if not the world's).
template <typename Entry>
struct OnLink {
  Entry entry;
  int link = 0;
  core::Pose X_LS;
};
using RobotLidar = OnLink<LidarEntry>;
using RobotCamera = OnLink<DepthCameraEntry>;
using RobotOdometry = OnLink<OdometryEntry>;
using RobotGnss = OnLink<GnssEntry>;
using RobotMagnetometer = OnLink<MagnetometerEntry>;
using RobotContactSensor = OnLink<ContactSensorEntry>;

/// An IMU on link `link` of a robot: entry.settings.X_LS is the sensor in
/// that moving link's frame, and entry.frame_id the frame its messages
/// name (before the robot's tf prefix): as given, or the link's it was put on.
struct RobotImu {
  ImuEntry entry;
  int link = 0;
};

/// A force-torque sensor on the joint of moving link `link` (index in the model).
struct RobotForceTorque {
  ForceTorqueEntry entry;
  int link = 0;
};

/// Every sensor of one robot, on its links.
struct RobotSensors {
  std::vector<RobotImu> imus;
  std::vector<RobotLidar> lidars;
  std::vector<RobotCamera> cameras;
  std::vector<RobotOdometry> odometry;
  std::vector<RobotGnss> gnss;
  std::vector<RobotMagnetometer> magnetometers;
  std::vector<RobotContactSensor> contact_sensors;
  std::vector<RobotForceTorque> force_torques;
  std::uintmax_t bytes = 0;  ///< what its lidars and cameras may hold (core::lidarBytes, core::depthCameraBytes)
  /// For the caller to say once (at start, or in a spawn's answer): each
  /// lidar or camera whose rays a second of sim time (rays x rate) pass
  /// kRaysKeepingRealTime, with what that costs.
  std::vector<std::string> notes;
};

/// Rays a second of sim time that one device may cast and still leave the
/// node near real time: about half of what one core casts among 100 bodies
/// (bench/README.md, "Range sensors": 8.8 M/s for a culled depth camera).
inline constexpr double kRaysKeepingRealTime = 4.0e6;

/// What the lidars and depth cameras of a world may hold (config key
/// `devices.memory`) and what those counted so far hold. Each is counted
/// before it is built: 40 depth cameras once ended the node in
/// std::bad_alloc, and a spawn of 400 took 5.8 GB before it was refused.
struct DeviceMemory {
  std::uintmax_t budget = 0;  ///< bytes
  std::uintmax_t used = 0;    ///< bytes
  /// Counts `bytes` for the device at `key`, or refuses it (ConfigError
  /// naming `key` and devices.memory), `used` unchanged.
  void take(std::uintmax_t bytes, const std::string& key);
};

/// `config`'s sensors and then `markup`'s (a URDF's Gazebo markup: checked
/// here against a step of `dt`, an IMU's rate capped at one sample a step,
/// as Gazebo samples no faster than it steps) on `model`'s links. An IMU's
/// `link` "" is the robot's frame its `frame_id` names, else the base.
/// Refused (ConfigError naming the entry's key): a link the robot does not
/// have (the message lists its links), settings core::checkLidar,
/// core::validateImu or core::validateOdomNoise refuse, a lidar's or an
/// odometry's rate outside the publish rates, a topic ROS cannot name.
/// A force-torque sensor on no moving joint (a fixed one is lumped, as
/// Gazebo lumps it, and the plugin then does not load) is said in the
/// notes and not mounted.
/// An odometry's link "" is the base; it cannot be a lumped link (its
/// twist is a moving link's).
/// Each lidar and camera is counted in `memory` first (refused, naming its
/// key, beyond it), and named in the result's notes if it casts more than
/// kRaysKeepingRealTime rays a second.
RobotSensors mountSensors(const RobotDevices& config, const RobotDevices& markup, const core::ArticulationModel& model,
                          double dt, DeviceMemory& memory);

/// The core's set of `sensors`' IMUs, odometry, receivers, magnetometers,
/// lidars (range finders among them), depth cameras, force-torque and
/// contact sensors on a robot of `model` at `now`, in steps of `dt`: each
/// at its entry's rate (an odometry's 0: `odometry_rate`, the node's
/// ~publish_rate; a receiver's, magnetometer's, force-torque or contact
/// sensor's 0: every step).
core::LinkSensors linkSensors(const RobotSensors& sensors, const core::ArticulationModel& model,
                              const core::ArticulationState& now, double dt, double odometry_rate);

/// The core's set of a free body's devices, `imu` and `odom_noise`, in
/// steps of `dt`: the IMU at its entry's pose in its entry's link (the
/// body's root link, or a link fixed to it), refused otherwise
/// (ConfigError naming KEY.link and the body's links). Started by
/// BodySensors::start when the body enters the world.
core::BodySensors bodySensors(const core::BodyModel& body, const std::optional<ImuEntry>& imu,
                              const std::optional<core::OdomNoiseSettings>& odom_noise, double dt);

}  // namespace rigid_body_sim::io
