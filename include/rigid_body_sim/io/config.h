// Simulation settings from YAML (yaml-cpp): the keys of config/default.yaml.
// rbsim reads them from a file; the ROS node reads the same keys from its
// private parameters through the same parser. ROS-free.
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/controllers/diff_drive.h"
#include "rigid_body_sim/core/controllers/joint_control.h"
#include "rigid_body_sim/io/device_entries.h"
#include "rigid_body_sim/io/timeline.h"

namespace rigid_body_sim::io {

/// A config that cannot be used. The message names the key and the value.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
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
  /// A steered base's steering joints (an AckermannSteeringController's
  /// `front_steer`, a tricycle's `steeringJoint`); `left` its driven wheels
  /// (`rear_wheel`, `actuatedWheelJoint`), `right` empty, wheel_separation its
  /// wheelbase (`wheel_separation_h`).
  std::vector<std::string> steers;
  /// A steered base's wheels on its fixed axle, when they are not driven
  /// (a tricycle's encoder wheels); empty: the driven wheels that do not steer.
  std::vector<std::string> fixed_axle;
  bool speed_at_steered_wheel = false;  ///< the command's speed is the steered wheel's (a tricycle's)
  double steering_speed = std::numeric_limits<double>::infinity();  ///< rad/s, the steering's fastest
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
  /// gazebo_ros_control's `robotSimType` ("": its default, DefaultRobotHWSim).
  std::string robot_sim_type;
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
  std::vector<TimedCommand> timeline;           ///< `timeline`: commands at given sim times (timeline.h)
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
  /// `publish_rate` (Hz), sim_node's ~publish_rate, read where the node's
  /// keys are set aside (rbsim): an odometry with no rate of its own
  /// reports at it in both. Its default is the node's.
  double publish_rate = 100.0;
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
/// With `node_keys`, the node's own top-level keys (node_keys.h) are set
/// aside, their names appended to it, instead of refused as unknown;
/// `publish_rate` among them is read (SimConfig::publish_rate).
SimConfig parseConfigText(const std::string& yaml, const std::string& source,
                          const std::vector<std::string>& overrides = {}, const std::string& base_dir = "",
                          std::vector<std::string>* node_keys = nullptr);
/// parseConfigText of the file at `path` (at most InputCaps::kConfigBytes).
SimConfig loadConfigFile(const std::string& path, const std::vector<std::string>& overrides = {},
                         const std::string& base_dir = "", std::vector<std::string>* node_keys = nullptr);

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
