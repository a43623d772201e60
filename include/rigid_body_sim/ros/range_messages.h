// The messages of the range sensors on robots' links (core::LinkSensors'
// lidars, range finders and depth cameras), built by plain functions
// (tested without a master): a lidar's sensor_msgs/LaserScan (one fan) or
// sensor_msgs/PointCloud2 (several fans: x, y, z of each return in the
// sensor's frame), a range finder's sensor_msgs/Range of its nearest ray
// (gazebo_ros_range's), a depth camera's sensor_msgs/Image, CameraInfo
// and PointCloud2 (Gazebo's openni_kinect's).
#pragma once

#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/Range.h>

#include <string>
#include <vector>

#include "rigid_body_sim/core/devices/depth_camera.h"
#include "rigid_body_sim/core/devices/lidar.h"
#include "rigid_body_sim/io/device_entries.h"

namespace rigid_body_sim::node {

/// sensor_msgs/LaserScan of one fan: REP 117's ±inf kept, scan_time 1/rate.
sensor_msgs::LaserScan scanMessage(const core::Lidar& lidar, const std::vector<double>& ranges, double rate,
                                   const std::string& frame, const ros::Time& stamp);
/// sensor_msgs/PointCloud2 of a scan as the Velodyne plugin lays it out:
/// x, y, z (float32, the sensor's frame), intensity (float32; 0, Gazebo's
/// for a surface without <laser_retro>), ring (uint16, the fan: 0 the
/// lowest), time (float32 s after the stamp: 0, one instant), 22 bytes a
/// point, azimuth by azimuth and in each its fans from the lowest. Every
/// finite return in one row, or `organized`: every ray, NaN where none
/// met, a row per azimuth (width: the fans), as `<organize_cloud>` gives.
sensor_msgs::PointCloud2 cloudMessage(const core::Lidar& lidar, const std::vector<double>& ranges, bool organized,
                                      const std::string& frame, const ros::Time& stamp);

/// sensor_msgs/Range of `reading` (m, REP 117's ±inf kept) from `lidar`'s rays as `range` describes it.
sensor_msgs::Range rangeMessage(const core::Lidar& lidar, const io::RangeEntry& range, double reading,
                                const std::string& frame, const ros::Time& stamp);

/// sensor_msgs/Image of a depth image: 32FC1 in m (REP 117's ±inf kept), or
/// `millimetres`: 16UC1 in mm, 0 where there is no depth (as OpenNI's).
sensor_msgs::Image depthImageMessage(const core::DepthCamera& camera, const std::vector<double>& depth,
                                     bool millimetres, const std::string& frame, const ros::Time& stamp);
/// sensor_msgs/CameraInfo of the pinhole: no distortion, K and P of its focal length and centre.
sensor_msgs::CameraInfo cameraInfoMessage(const core::DepthCamera& camera, const std::string& frame,
                                          const ros::Time& stamp);
/// sensor_msgs/PointCloud2 of every pixel (x, y, z float32 in the optical
/// frame: x right, y down, z ahead), organized as the image, NaN where
/// nothing is within range (gazebo_ros_openni_kinect's layout, without its rgb).
sensor_msgs::PointCloud2 depthCloudMessage(const core::DepthCamera& camera, const std::vector<double>& depth,
                                           const std::string& frame, const ros::Time& stamp);

}  // namespace rigid_body_sim::node
