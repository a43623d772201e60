// The model plugins of a URDF's Gazebo markup that this project runs, read
// as Gazebo reads them (private to io): `<gazebo><plugin filename=...>`
// with gazebo_ros_imu (an IMU), gazebo_ros_p3d (a link's odometry),
// gazebo_ros_diff_drive and gazebo_ros_skid_steer_drive (DiffDriveControllers),
// gazebo_ros_tricycle_drive (a steered one), gazebo_ros_control (its
// `robotNamespace`, a `robotSimType` of steer_bot_hardware_gazebo), the mimic-joint plugin,
// hector's (hector_plugins.h), and planar_move and force_based_move
// (base_plugins.h).
#pragma once

#include <tinyxml.h>

#include "gazebo_markup.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io::detail {

/// gazebo_ros_control's `robotSimType` of car-like robots (AgileX Hunter's):
/// it sets its joints' positions and speeds past their URDF limits.
constexpr const char* kSteerBotSimType = "steer_bot_hardware_gazebo/SteerBotHardwareGazebo";

/// Whether readModelPlugin reads `plugin` (a <plugin> under <gazebo>).
bool readsModelPlugin(const TiXmlElement& plugin);
/// Whether the plugin file `file` is a mimic-joint plugin: part of the
/// robot's model (its joints), read by every load, never a device.
bool isMimicPlugin(const std::string& file);

/// `plugin`'s device into `out`: as pluginImu, pluginHectorImu,
/// pluginOdometry, pluginDrive, pluginSkidSteer and pluginTricycle in gazebo_plugins.cpp say. One Gazebo would not run
/// (an IMU or p3d without its `bodyName`) is told to `unread`. Throws std::invalid_argument naming the element: a
/// number or flag it cannot read.
void readModelPlugin(const TiXmlElement& plugin, const Unread& unread, RobotDevices& out);

}  // namespace rigid_body_sim::io::detail
