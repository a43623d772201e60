// What a config key or a URDF's Gazebo markup says of one device on a body
// or a robot's link: each sensor's and base drive's entry, the core's
// settings with the topics and frames the node gives it, and the key that
// names it in a refusal (io/config.h reads the config's, io/gazebo_*.h the
// markup's; io/sensor_mount.h puts them on the links). ROS-free.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/devices/depth_camera.h"
#include "rigid_body_sim/core/devices/earth_sensors.h"
#include "rigid_body_sim/core/devices/force_torque.h"
#include "rigid_body_sim/core/devices/imu.h"
#include "rigid_body_sim/core/devices/lidar.h"
#include "rigid_body_sim/core/devices/odom_noise.h"
#include "rigid_body_sim/core/devices/range_finder.h"
#include "rigid_body_sim/core/devices/velocity_driver.h"

namespace rigid_body_sim::io {

/// An IMU on a body or a robot's link (`imu` for one, `bodies[i].imu`;
/// or a URDF's Gazebo `<sensor type="imu">`): the core's settings, and the
/// frame the node names it by.
struct ImuEntry {
  core::ImuSettings settings;  ///< its pose X_LS as given: in the frame of `link`
  /// A body's: its own frame under the body's prefix, on /tf_static ("":
  /// "imu_link"; "NAME/imu_link" in a world). A robot's: the frame its
  /// messages name after the robot's tf prefix ("": the link's), as
  /// Gazebo's frameName, whatever its pose.
  std::string frame_id;
  /// The link it is mounted on. A body's: "" the root link, or a link fixed
  /// to it. A robot's: any link ("": the robot's frame `frame_id` names, or else its base).
  std::string link;
  std::string topic = "imu";  ///< sensor_msgs/Imu, under the body's or robot's prefix ("NAME/imu")
  std::string key = "imu";    ///< its config key, for messages ("bodies[2].imu")
};

/// A lidar on a robot's link (`lidar`, `bodies[i].lidar`: a map, or a list
/// of them; or a URDF's Gazebo `<sensor type="ray">`): it scans from `pose`
/// in the link (a link lumped into another by a fixed joint will do, as a
/// laser_link), its scans in the link's tf frame or `frame_id`.
/// A range finder's reading from a lidar's rays (gazebo_ros_range): the
/// nearest, published as sensor_msgs/Range.
struct RangeEntry {
  core::RangeFinderSettings settings;  ///< the reading's own noise (`gaussianNoise`)
  double field_of_view = 0.05;         ///< rad, Range's field_of_view (`fov`)
  bool infrared = false;               ///< Range's radiation_type: ULTRASOUND, or INFRARED
};

struct LidarEntry {
  core::LidarSettings settings;
  std::string link;  ///< the robot's link it is on (required)
  core::Pose pose;   ///< the sensor in that link's frame (`pose`, as Gazebo's <sensor><pose>)
  /// The scans' tf frame, after the robot's tf_prefix; "": the link's. As
  /// in Gazebo, ranges are measured from `pose` whatever frame they name.
  std::string frame_id;
  std::string topic = "scan";       ///< under the robot's prefix in a world ("NAME/scan")
  double rate = 10.0;               ///< Hz of sim time
  std::string key = "lidar";        ///< its config key, for messages ("bodies[2].lidar[0]")
  std::optional<RangeEntry> range;  ///< a range finder: one sensor_msgs/Range of its rays, not a scan
  bool organized = false;  ///< fans > 1: a cloud of every ray, NaN where none met (Velodyne's `organize_cloud`)
};

/// A depth camera on a robot's link (`depth_camera`, `bodies[i].depth_camera`:
/// a map, or a list): it looks along `pose`'s x in the link; its images are
/// laid out as an optical frame's (`frame_id`, "": the link's frame).
struct DepthCameraEntry {
  core::DepthCameraSettings settings;
  std::string link;              ///< the robot's link it is on (required)
  core::Pose pose;               ///< the camera in that link's frame
  std::string frame_id;          ///< the images' tf frame, after the robot's tf_prefix; "": the link's
  std::string topic = "camera";  ///< the namespace of the three topics below
  /// Under `topic` (or from the root, "/..."): the image, its CameraInfo, its points (as Gazebo's openni_kinect names
  /// them).
  std::string image_topic = "depth/image_raw", info_topic = "depth/camera_info", points_topic = "depth/points";
  double rate = 30.0;        ///< Hz of sim time
  bool millimetres = false;  ///< `encoding`: 16UC1 (mm, 0 where none) instead of 32FC1 (m)
  std::string key = "depth_camera";
};

/// Odometry of a robot's link as nav_msgs/Odometry, its pose in the world
/// frame and its twist in the link's axes: a robot's `odom_noise` (its base
/// on `odom` with the noise, and exact on `ground_truth`), or Gazebo's
/// gazebo_ros_p3d (`bodyName` on `topicName`, `gaussianNoise` on its pose and twist),
/// or gazebo_ros_planar_move's and gazebo_ros_force_based_move's (the truth
/// in their `odometryFrame`, on tf too).
struct OdometryEntry {
  std::string link;                              ///< "": the base
  std::string topic = "odom";                    ///< under the robot's prefix; /... as it is
  std::string ground_truth;                      ///< the exact state's topic too; "": none
  std::optional<core::OdomNoiseSettings> noise;  ///< none: exact
  double rate = 0.0;                             ///< Hz of sim time; 0: the node's ~publish_rate
  std::string key = "odom_noise";                ///< for messages
  /// The frame the pose is given in, after the robot's tf_prefix ("": the
  /// world's): it coincides with the world's.
  std::string frame_id;
  /// frame_id -> the link's frame on tf too, in place of world -> base.
  bool on_tf = false;

  /// A robot's `odom_noise` (config key `key`): its base on `odom` with
  /// the noise, exact on `ground_truth`.
  static OdometryEntry ofOdomNoise(const core::OdomNoiseSettings& noise, const std::string& key) {
    OdometryEntry e;
    e.topic = "odom";
    e.ground_truth = "ground_truth";
    e.noise = noise;
    e.key = key;
    return e;
  }
};

/// A force-torque sensor on a robot's joint (gazebo_ros_ft_sensor): the
/// wrench the joint carries onto its child link (core::ForceTorqueSensor)
/// as geometry_msgs/WrenchStamped on `topic` under the robot's prefix,
/// headed the child link's frame.
struct ForceTorqueEntry {
  core::ForceTorqueSettings settings;
  std::string joint;
  std::string topic;
  double rate = 0.0;  ///< Hz of sim time; 0: every step
  std::string key;
};

/// A robot's base driven toward a commanded twist by a wrench
/// (core::VelocityDriver, core::baseLoad), on `topic` under the robot's
/// prefix: a config's `cmd_vel`, or gazebo_ros_planar_move's and
/// gazebo_ros_force_based_move's `commandTopic`.
struct BaseDriveEntry {
  core::DriverSettings settings;
  std::string topic = "cmd_vel";
  /// force_based_move's gains, N per m/s and N·m per rad/s (0: settings'
  /// own, per kg and per kg·m²): divided by the robot's mass and yaw
  /// inertia when it is known.
  double force_gain = 0.0, torque_gain = 0.0;
  std::string key = "cmd_vel";
};

/// A GNSS receiver on a robot's link (hector_gazebo_ros_gps): its fix as
/// sensor_msgs/NavSatFix on `topic` and its velocity (north, west, up) as
/// geometry_msgs/Vector3Stamped on `velocity_topic`, both under the
/// robot's prefix, headed `frame_id`.
struct GnssEntry {
  core::GnssSettings settings;
  std::string link;      ///< "": the base
  std::string frame_id;  ///< after the robot's tf_prefix; "": the link's
  std::string topic = "fix", velocity_topic = "fix_velocity";
  double rate = 4.0;  ///< Hz of sim time
  int status = 0;     ///< sensor_msgs/NavSatStatus's status (0: STATUS_FIX)
  int service = 1;    ///< and its service (1: SERVICE_GPS)
  std::string key = "gps";
};

/// A magnetometer on a robot's link (hector_gazebo_ros_magnetic): the
/// Earth's field in the link's axes as geometry_msgs/Vector3Stamped, or
/// sensor_msgs/MagneticField, on `topic` under the robot's prefix.
struct MagnetometerEntry {
  core::MagnetometerSettings settings;
  std::string link;      ///< "": the base
  std::string frame_id;  ///< after the robot's tf_prefix; "": the link's
  std::string topic = "magnetic";
  double rate = 0.0;           ///< Hz of sim time; 0: every step
  bool field_message = false;  ///< sensor_msgs/MagneticField, not Vector3Stamped (`useMagneticFieldMsgs`)
  std::string key = "magnetometer";
};

/// A contact sensor on a robot's link (`<sensor type="contact">` with
/// gazebo_ros_bumper): every pair touching the moving link that carries
/// `link`, as rigid_body_sim/Contacts on `topic` under the robot's prefix,
/// in the world frame or in `frame_id`, a frame of the robot.
struct ContactSensorEntry {
  std::string link;
  std::string frame_id;  ///< "": the world's; else a frame of the robot (after its tf_prefix)
  std::string topic = "bumper_states";
  double rate = 0.0;  ///< Hz of sim time; 0: every step
  std::string key = "contact";
};

}  // namespace rigid_body_sim::io
