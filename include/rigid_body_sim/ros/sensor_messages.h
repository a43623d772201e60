// The messages of the link sensors' samples (core/devices/link_sensors.h)
// and of a body's IMU: sensor_msgs/Imu (REP 145), hector's NavSatFix and
// Vector3Stamped, sensor_msgs/MagneticField. Plain functions.
#pragma once

#include <geometry_msgs/Vector3Stamped.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/MagneticField.h>
#include <sensor_msgs/NavSatFix.h>
#include <std_msgs/Header.h>

#include <string>

#include "rigid_body_sim/core/devices/earth_sensors.h"
#include "rigid_body_sim/core/devices/imu.h"

namespace rigid_body_sim::node {

/// sensor_msgs/Imu of a reading: each covariance diagonal σ² of its settings' noise.
sensor_msgs::Imu imuMessage(const core::ImuReading& r, const core::ImuSettings& s, const std::string& frame,
                            const ros::Time& stamp);

/// A fix as hector's gazebo_ros_gps publishes it: the covariance in east,
/// north, up, DIAGONAL_KNOWN unless a heading turns unequal axes.
sensor_msgs::NavSatFix fixMessage(const core::GnssFix& f, const std_msgs::Header& header, int status, int service);

geometry_msgs::Vector3Stamped vectorMessage(const core::Vec3& v, const std_msgs::Header& header);

/// A field as sensor_msgs/MagneticField: its covariance all zeros (unknown), as hector's.
sensor_msgs::MagneticField magneticFieldMessage(const core::Vec3& field, const std_msgs::Header& header);

}  // namespace rigid_body_sim::node
