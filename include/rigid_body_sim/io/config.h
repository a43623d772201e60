// Simulation settings from YAML (yaml-cpp): the keys of config/default.yaml.
// rbsim reads them from a file; the ROS node reads the same keys from its
// private parameters through the same parser. ROS-free.
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/controllers/diff_drive.h"
#include "rigid_body_sim/core/controllers/joint_control.h"
#include "rigid_body_sim/core/devices/depth_camera.h"
#include "rigid_body_sim/core/devices/earth_sensors.h"
#include "rigid_body_sim/core/devices/force_torque.h"
#include "rigid_body_sim/core/devices/imu.h"
#include "rigid_body_sim/core/devices/lidar.h"
#include "rigid_body_sim/core/devices/odom_noise.h"
#include "rigid_body_sim/core/devices/range_finder.h"
#include "rigid_body_sim/core/devices/velocity_driver.h"

namespace rigid_body_sim::io {

/// A config that cannot be used. The message names the key and the value.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

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

/// A robot's joints at the start (`initial.joint_positions` and
/// `initial.joint_velocities`: maps from joint name to rad or m, rad/s or
/// m/s), in the file's order. Applied by io::startJoints (joint_start.h).
struct InitialJoints {
  std::vector<std::pair<std::string, double>> positions, velocities;
  bool empty() const { return positions.empty() && velocities.empty(); }
};

/// What a DiffDriveController publishes, and on which frames: its YAML's
/// keys the node reads (ros_controllers' defaults).
struct DriveTopics {
  double publish_rate = 50.0;                         ///< Hz of sim time, its odometry's
  std::array<double, 6> pose_covariance_diagonal{};   ///< nav_msgs/Odometry's pose covariance, its diagonal
  std::array<double, 6> twist_covariance_diagonal{};  ///< and its twist's
  std::string base_frame_id = "base_link";            ///< after the robot's tf prefix, in the node
  std::string odom_frame_id = "odom";                 ///< after the robot's tf prefix, in the node
  bool enable_odom_tf = true;                         ///< odom -> base on tf
  bool publish_cmd = false;                           ///< the limited command on cmd_vel_out
  bool allow_multiple_cmd_vel_publishers = true;      ///< false: brake while two publish on cmd_vel
  /// Its topics: under CONTROLLER/ (ros_controllers'), or under the robot's
  /// prefix alone (gazebo_ros_diff_drive's `commandTopic`, `odometryTopic`);
  /// a topic starting with '/' as it is.
  bool under_controller = true;
  std::string cmd_vel_topic = "cmd_vel", odom_topic = "odom";
};

/// A key of a controller's YAML that is not read here, and why: a
/// ros_controllers key for what this project does not run, or a key no
/// ros_controllers controller of its type reads (ROS lets such parameters
/// be; the node names them all in one warning at start).
struct UnreadKey {
  std::string key;  ///< "controllers.NAME.KEY"
  std::string why;
};

/// A diff_drive_controller/DiffDriveController's keys (io/drive_config.h reads them).
struct DiffDriveEntry {
  std::vector<std::string> left, right;  ///< `left_wheel`, `right_wheel`: a joint name or a list
  /// A MecanumDriveController's: left and right each its front then its
  /// back wheel, wheel_separation its x and y spans added.
  bool mecanum = false;
  /// m; unset: from the URDF as ros_controllers finds them (the first wheels' joint
  /// origins apart, the left one's first collision cylinder or sphere).
  std::optional<double> wheel_separation, wheel_radius;
  core::DiffDriveSettings settings;  ///< multipliers, cmd_vel_timeout, limits, open_loop, window
  DriveTopics topics;
  std::vector<UnreadKey> unread;
};

/// One controller of a robot's `controllers` map, as ros_controllers' YAML
/// gives it (io/controllers.h turns it into the core's).
struct ControllerEntry {
  std::string name;                 ///< its key in the map: its topic's namespace
  std::string type;                 ///< e.g. effort_controllers/JointPositionController
  std::vector<std::string> joints;  ///< `joint`, or `joints`
  bool joint_list = false;          ///< given as `joints` (a group's key)
  /// Per joint, `pid` (one joint) or `gains: {JOINT: {p, i, d, i_clamp}}`
  /// (a group); empty where none was given.
  std::vector<std::optional<core::PidGains>> gains;
  std::optional<double> publish_rate;  ///< Hz, a JointStateController's `publish_rate`
  std::string key;                     ///< "controllers.NAME", "bodies[2].controllers.NAME"
  /// A DiffDriveController's own keys (its wheels are `joints` too, left then
  /// right, so gazebo_ros_control's pid_gains find them).
  std::optional<DiffDriveEntry> drive;
  std::vector<UnreadKey> unread;  ///< its keys not read here
};

/// A URDF's `<transmission>`: the joints it drives and the hardware
/// interfaces it declares for them (gazebo_ros_control runs a controller
/// only on such a joint, through an interface the controller's type uses).
struct TransmissionEntry {
  std::string name;
  std::vector<std::string> joints;
  std::vector<std::string> interfaces;  ///< as `EffortJointInterface`, without `hardware_interface/`
};

/// The devices on a robot's links: its config entry's, or its URDF's
/// Gazebo markup's (io/sensor_mount.h puts the sensors on the links).
struct RobotDevices {
  std::vector<ImuEntry> imus;
  std::vector<LidarEntry> lidars;
  std::vector<DepthCameraEntry> cameras;
  std::vector<OdometryEntry> odometry;
  std::vector<GnssEntry> gnss;
  std::vector<MagnetometerEntry> magnetometers;
  std::vector<ContactSensorEntry> contact_sensors;
  std::vector<ForceTorqueEntry> force_torques;
  /// The markup's drives (gazebo_ros_diff_drive) as DiffDriveControllers,
  /// run beside the config's `controllers`.
  std::vector<ControllerEntry> controllers;
  /// gazebo_ros_planar_move's or gazebo_ros_force_based_move's base drive.
  std::optional<BaseDriveEntry> base_drive;
  std::vector<TransmissionEntry> transmissions;  ///< the URDF's, to check the config's controllers against
  /// The mimic-joint plugins' (roboticsgroup's): joint `follower` at
  /// multiplier · `leader` + offset, as a URDF <mimic> (set on the URDF's
  /// joints when it is read, urdf_parse.h).
  struct Mimic {
    std::string follower, leader;
    double multiplier = 1.0, offset = 0.0;
    std::string key;
  };
  std::vector<Mimic> mimics;
  /// gazebo_ros_control's `robotNamespace` ("": none): where the robot's
  /// controllers and joint_states are, as gazebo_ros_control puts them.
  std::string robot_namespace;
};

/// One entry of the `bodies` list: a body of the world.
struct BodyEntry {
  std::string name;  ///< unique in the world
  std::string urdf;  ///< a URDF file (relative to the config's folder, or package://), or for
                     ///< the node the name of a parameter holding the URDF
  core::LinkState initial;
  InitialJoints initial_joints;  ///< bodies[i].initial.joint_positions, .joint_velocities
  /// Its surface (bodies[i].contact); unset: the scene's, contact.friction and contact.restitution.
  std::optional<double> friction, restitution;
  std::optional<ImuEntry> imu;                        ///< bodies[i].imu
  std::optional<core::OdomNoiseSettings> odom_noise;  ///< bodies[i].odom_noise
  std::optional<core::DriverSettings> cmd_vel;        ///< bodies[i].cmd_vel
  std::vector<ControllerEntry> controllers;           ///< bodies[i].controllers (a robot's)
  std::vector<LidarEntry> lidars;                     ///< bodies[i].lidar (a robot's)
  std::vector<DepthCameraEntry> cameras;              ///< bodies[i].depth_camera (a robot's)
};

struct SimConfig {
  /// dt, gravity, damping, gyroscopic, scene, contact, sleep (bodies come from URDF).
  core::ModelSpec model;
  /// Initial pose and twist of the root link frame, world frame (one body).
  core::LinkState initial;
  InitialJoints initial_joints;  ///< initial.joint_positions, .joint_velocities (one robot)
  /// The world's bodies, when the config lists them (`bodies`); empty for
  /// one body given separately (rbsim --urdf, the node's robot_description).
  std::vector<BodyEntry> bodies;
  /// The config has a `bodies` list, maybe an empty one (`bodies: []`: an
  /// empty world, which the node's ~spawn_body fills).
  bool bodies_listed = false;
  /// The one body's IMU (`imu`) and odometry noise (`odom_noise`), without a bodies list.
  std::optional<ImuEntry> imu;
  std::optional<core::OdomNoiseSettings> odom_noise;
  std::optional<core::DriverSettings> cmd_vel;  ///< the one body's velocity driver
  std::vector<ControllerEntry> controllers;     ///< the one robot's `controllers`
  std::vector<LidarEntry> lidars;               ///< the one robot's `lidar`
  std::vector<DepthCameraEntry> cameras;        ///< the one robot's `depth_camera`
  /// urdf.repair: read the URDFs as Gazebo and KDL do, repairing what a
  /// strict reading refuses (io::UrdfOptions); false refuses it.
  bool urdf_repair = true;
  /// devices.memory (given in MiB): the bytes the world's lidars and depth
  /// cameras may hold in all, each counted before it is built
  /// (io::DeviceMemory). 1 GiB: three 2000 x 2000 depth cameras, a laptop's share.
  std::uintmax_t device_memory = std::uintmax_t{1024} << 20;
  /// The config file's folder (parseConfig's base_dir): package:// URDFs are
  /// also looked for above it, so a package's own worlds load without ROS.
  std::string base_dir;
};

/// Parses a config tree. Missing keys keep the defaults documented in
/// config/default.yaml; unknown keys and bad values throw ConfigError.
/// Relative URDF paths in `bodies` resolve against `base_dir`.
/// "" if `name` may name a body, else why not: it starts with a letter and
/// holds only letters, digits and '_', at most kMaxBodyNameLength (in a
/// world it names the body's topics and tf frames). The one rule for a
/// config's bodies[i].name and for spawn_body's name.
std::string bodyNameProblem(const std::string& name);
inline constexpr std::size_t kMaxBodyNameLength = 64;

/// A name or text a caller gave, as a message shows it: at most
/// kMaxShownLength characters (then "... (N characters)"), every byte that
/// is not printable ASCII as '?'. A delete once echoed a 100 KB name back.
std::string shownName(const std::string& text);
inline constexpr std::size_t kMaxShownLength = 200;

/// "" if `frame` may be a tf frame id a config or markup gives, else why
/// not, as tf2 requires: not empty, not starting with '/', and only
/// letters, digits, '_', '-', '.' and '/' ("bad frame#!" was taken).
std::string frameIdProblem(const std::string& frame);

SimConfig parseConfig(const YAML::Node& root, const std::string& base_dir = "");

/// parseConfig of `root` with a `bodies` list of `count` entries given apart,
/// `entry(i)` called once for each in order: the node converts each from
/// the parameter server's reply and lets it go, never holding the list as
/// one YAML tree (about 7 KB an entry). `root` itself has no `bodies` key
/// and is not changed. ConfigError as parseConfig.
SimConfig parseConfigWithBodies(const YAML::Node& root, std::size_t count,
                                const std::function<YAML::Node(std::size_t)>& entry, const std::string& base_dir = "");

/// A config from its YAML text, as parseConfig(loadYamlText(yaml, source))
/// with each of `overrides` (KEY=VALUE, applyOverride) applied, but the
/// `bodies` list is parsed an entry at a time as it is read, never held
/// whole as a YAML tree (about 7 KB an entry: 70 MB for a world of 10,000
/// bodies, bench/HISTORY.md). ConfigError as parseConfig and loadYamlText.
SimConfig parseConfigText(const std::string& yaml, const std::string& source,
                          const std::vector<std::string>& overrides = {}, const std::string& base_dir = "");
/// parseConfigText of the file at `path` (at most InputCaps::kConfigBytes).
SimConfig loadConfigFile(const std::string& path, const std::vector<std::string>& overrides = {},
                         const std::string& base_dir = "");

/// An IMU from the YAML text of an `imu` map (the node's ~spawn_body), for a
/// model of step `dt`; ConfigError naming `path`.KEY.
ImuEntry parseImuText(const std::string& yaml, const std::string& path, double dt);
/// Odometry noise from the YAML text of an `odom_noise` map (~spawn_body).
core::OdomNoiseSettings parseOdomNoiseText(const std::string& yaml, const std::string& path);
/// A velocity driver from the YAML text of a `cmd_vel` map (~spawn_body).
core::DriverSettings parseDriverText(const std::string& yaml, const std::string& path);

/// Reads a YAML file: ConfigError if it is not a readable regular file of at
/// most InputCaps::kConfigBytes, or its text is refused by loadYamlText.
YAML::Node loadYamlFile(const std::string& path);

/// Parses a YAML text after yamlProblem() (input_bounds.h) accepts it: one
/// document, aliases bounded (and copied, merge keys
/// resolved, as roslaunch reads them), bounded nesting. ConfigError names `source`.
YAML::Node loadYamlText(const std::string& text, const std::string& source);

/// Applies "a.b.c=VALUE" to the tree: VALUE is parsed as YAML
/// ("gravity=[0,0,0]", "gyroscopic=false"); missing maps are created.
void applyOverride(YAML::Node& root, const std::string& assignment);

}  // namespace rigid_body_sim::io
