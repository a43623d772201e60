// The robots' range sensors in the node, each at its rate of sim time from
// its link, against the scene, the free bodies and every robot's links but
// its own, stamped on the node's clock in its frame: a lidar
// (core/devices/lidar.h) publishes sensor_msgs/LaserScan (one fan) or
// sensor_msgs/PointCloud2 (several fans: x, y, z of each return in the
// sensor's frame) on its topic, or, a range finder's (gazebo_ros_range),
// sensor_msgs/Range of its nearest ray (core/devices/range_finder.h); a depth camera (core/devices/depth_camera.h)
// publishes TOPIC/depth/image_raw (sensor_msgs/Image, 32FC1 or 16UC1),
// TOPIC/depth/camera_info and TOPIC/depth/points, as Gazebo's
// openni_kinect plugin names them. What nobody subscribes to is not cast.
// The messages are built by plain functions (tested without a master).
#pragma once

#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/Range.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/devices/range_finder.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/io/sensor_mount.h"
#include "rigid_body_sim/ros/counted_publisher.h"

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

class RangeSensors {
 public:
  RangeSensors(const ros::NodeHandle& nh, double dt) : nh_(nh), dt_(dt) {}
  /// Robot r (the last) and its lidars: their topics under `prefix`, frames after `frame_prefix`.
  void addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                const std::vector<io::RobotLidar>& lidars, const std::vector<io::RobotCamera>& cameras = {});
  /// Robot r deleted: its sensors' topics close; the later robots move down by one.
  void removeRobot(std::size_t r);
  /// Bytes the lidars and cameras of every robot may hold (core::lidarBytes,
  /// core::depthCameraBytes): what a spawn's devices are counted on top of.
  /// Read on the spawn thread, changed on the loop's.
  std::uintmax_t bytes() const { return bytes_.load(); }
  /// After a reset: each lidar's noise from its seed again.
  void restart();
  /// The scans due at step `steps` of `sim`'s state, stamped `stamp`.
  void sample(const core::Simulation& sim, long long steps, const ros::Time& stamp);

 private:
  struct Port {
    core::Lidar lidar;
    int link = 0;
    core::Pose X_LS;
    double rate = 10.0;
    long long every = 1;
    std::string frame;
    CountedPublisher publisher;
    std::optional<io::RangeEntry> range;      ///< a range finder: its Range's fields
    std::optional<core::RangeFinder> finder;  ///< and its reading
    bool organized = false;                   ///< a cloud of every ray (LidarEntry::organized)
  };
  struct CameraPort {
    core::DepthCamera camera;
    int link = 0;
    core::Pose X_LS;
    long long every = 1;
    bool millimetres = false;
    std::string frame;
    CountedPublisher image, info, points;
  };
  /// Where robot r's link `link`, at X_LS in it, is in the world (its links
  /// placed and its own bodies marked in skip_ once per step, `placed`).
  core::Pose sensorPose(const core::Simulation& sim, std::size_t r, int link, const core::Pose& X_LS, bool& placed);

  ros::NodeHandle nh_;
  double dt_;
  std::vector<std::vector<Port>> robots_;
  std::vector<std::vector<CameraPort>> cameras_;           ///< per robot
  std::vector<std::shared_ptr<ros::NodeHandle>> handles_;  ///< per robot, its own (ownHandle)
  std::atomic<std::uintmax_t> bytes_{0};
  // Reused by every scan.
  core::ArticulationKinematics kin_;
  std::vector<double> ranges_, depth_;
  std::vector<char> skip_;
};

}  // namespace rigid_body_sim::node
