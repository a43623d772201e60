// The sensors of a URDF's Gazebo markup that this project runs, read as
// Gazebo reads them (private to io): `<gazebo reference="LINK"><sensor
// type="ray">` (or `gpu_ray`) with gazebo_ros's laser plugins
// (libgazebo_ros_laser.so, libgazebo_ros_gpu_laser.so: a LaserScan) or the
// Velodyne ones (libgazebo_ros_velodyne_laser.so, ..._gpu_laser.so: a
// PointCloud2), each turned into a lidar entry on LINK; `<sensor
// type="imu">` with gazebo_ros_imu_sensor, an IMU entry; `<sensor
// type="depth">` with gazebo_ros_openni_kinect or gazebo_ros_depth_camera,
// a depth camera entry; and the model plugins gazebo_plugins.h reads.
#pragma once

#include <tinyxml.h>

#include "gazebo_markup.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io::detail {

/// Whether `e` (a <sensor> or <plugin> element under <gazebo>) is one gazeboSensors reads.
bool readsMarkup(const TiXmlElement& e);

/// The devices of `robot`'s markup. A lidar: the sensor's `<pose>` (x y z roll pitch
/// yaw) in LINK, `<update_rate>`, `<ray><scan><horizontal>` and
/// `<vertical>` (`samples` times `resolution`, `min_angle`, `max_angle`),
/// `<range>` (`min`, `max`), `<noise>` (`stddev`), and the plugin's
/// `topicName` and `frameName` (a Velodyne plugin's `min_range`,
/// `max_range` and `gaussianNoise` over the sensor's). Each entry's key
/// names its markup. What it does not run (a noise's non-zero mean) is
/// told to `unread` (kind, link). An IMU and a depth camera: as sensorImu
/// and sensorCamera in gazebo_sensors.cpp say, an IMU's its rate infinite for "every step" (the mount
/// caps it at one sample a step). Throws std::invalid_argument naming the
/// element: a number it cannot read.
RobotDevices gazeboSensors(const TiXmlElement& robot, const Unread& unread);

}  // namespace rigid_body_sim::io::detail
