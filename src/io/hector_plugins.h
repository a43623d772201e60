// The model plugins of hector_gazebo_plugins that this project runs, read
// as hector reads them (private to io): its IMU, GPS and magnetometer,
// each with hector's error model (offset, drift, white noise).
#pragma once

#include <tinyxml.h>

#include "gazebo_markup.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io::detail {

/// hector_gazebo_ros_imu's IMU (hector_plugins.cpp says which elements).
ImuEntry pluginHectorImu(const TiXmlElement& plugin, const Unread& unread);
/// hector_gazebo_ros_gps's receiver.
GnssEntry pluginHectorGps(const TiXmlElement& plugin, const Unread& unread);
/// hector_gazebo_ros_magnetic's magnetometer.
MagnetometerEntry pluginHectorMagnetic(const TiXmlElement& plugin);

}  // namespace rigid_body_sim::io::detail
