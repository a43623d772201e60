// The model plugins of a URDF's Gazebo markup: gazebo_plugins.h.
#include "gazebo_plugins.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "base_plugins.h"
#include "drive_config.h"
#include "hector_plugins.h"
#include "kobuki_plugin.h"
#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::io::detail {

namespace {

/// The IMU of gazebo_ros_imu's model plugin: on `bodyName`, `updateRate`
/// (0 or none: every step), `gaussianNoise`, `topicName` ("/default_imu"),
/// `frameName` (bodyName). Its readings follow REP 145 here: the plugin's
/// own leave gravity out of the acceleration.
ImuEntry pluginImu(const TiXmlElement& plugin, const std::string& link, const Unread& unread) {
  ImuEntry imu;
  imu.key = "<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">";
  imu.link = link;
  const Numbers numbers(imu.key);
  double rate = 0.0, sigma = 0.0;
  numbers.rate(&plugin, "updateRate", rate);
  numbers.at(&plugin, "gaussianNoise", sigma, Bounds{0.0, std::numeric_limits<double>::infinity(), false, "(sigma)"});
  imu.settings.rate = rate > 0.0 ? rate : std::numeric_limits<double>::infinity();
  imu.settings.gyro_noise = imu.settings.accel_noise = sigma;
  imu.topic = childText(plugin, "topicName", "/default_imu");
  imu.frame_id = childFrame(plugin, "frameName", imu.link, imu.key);
  if (plugin.FirstChildElement("rpyOffset") != nullptr || plugin.FirstChildElement("rpyOffsets") != nullptr) {
    unread("<plugin> libgazebo_ros_imu.so <rpyOffset>", imu.link);
  }
  return imu;
}

/// The odometry of gazebo_ros_p3d's model plugin: `bodyName` on
/// `topicName` ("odom"), at `updateRate` (0 or none: every step), its
/// `gaussianNoise` on the pose and the twist (p3d puts it on the twist
/// alone, and the covariances on both), in the world frame (a `frameName`
/// naming a link is read as the world, and said).
OdometryEntry pluginOdometry(const TiXmlElement& plugin, const std::string& link, const Unread& unread) {
  OdometryEntry o;
  o.key = "<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">";
  o.link = link;
  const Numbers numbers(o.key);
  double rate = 0.0, sigma = 0.0;
  numbers.rate(&plugin, "updateRate", rate);
  numbers.at(&plugin, "gaussianNoise", sigma, Bounds{0.0, std::numeric_limits<double>::infinity(), false, "(sigma)"});
  o.rate = rate > 0.0 ? rate : std::numeric_limits<double>::infinity();
  if (sigma > 0.0) o.noise = core::OdomNoiseSettings{sigma, sigma, sigma, sigma, 0.0, 0.0, 0.0, 0};
  o.topic = childText(plugin, "topicName", "odom");
  const std::string frame = childText(plugin, "frameName", "world");
  if (frame != "world" && frame != "/world" && frame != "map" && frame != "/map") {
    unread("<plugin> libgazebo_ros_p3d.so <frameName> of a link (read as the world)", link);
  }
  for (const char* name : {"xyzOffsets", "rpyOffsets", "xyzOffset", "rpyOffset"}) {
    if (const TiXmlElement* e = plugin.FirstChildElement(name)) {
      for (double x : numbers.read(*e, name, 3)) {
        if (x != 0.0) unread(std::string("<plugin> libgazebo_ros_p3d.so <") + name + ">", link);
      }
    }
  }
  return o;
}

/// What gazebo_ros_diff_drive and gazebo_ros_skid_steer_drive read alike,
/// into `e`: `wheelSeparation` and `wheelDiameter` (none: from the URDF, as
/// ros_controllers reads them; the plugins' own defaults, 0.34 or 0.4 and
/// 0.15 m, are another robot's), `torque_key` (5 N·m) as each wheel's most
/// effort, `updateRate` (100 Hz) as the odometry's, `commandTopic`
/// ("cmd_vel"), `odometryTopic` ("odom"), `odometryFrame` ("odom"),
/// `robotBaseFrame` ("base_footprint"), and `tf_key` (`tf_default`) for
/// odom -> base on tf. The last command is held (the plugins have no
/// timeout; ros_controllers' 0.5 s would stop a base whose commander
/// pauses). `file` names the plugin in what `unread` is told.
void readPluginDrive(const TiXmlElement& plugin, const char* file, const char* torque_key, const char* tf_key,
                     bool tf_default, const Unread& unread, ControllerEntry& e) {
  DiffDriveEntry& d = *e.drive;
  e.type = kDiffDriveType;
  e.key = "<gazebo> <plugin name=\"" + e.name + "\">";
  e.joints = d.left;
  e.joints.insert(e.joints.end(), d.right.begin(), d.right.end());
  e.joint_list = true;
  const Numbers numbers(e.key);
  double separation = 0.0, diameter = 0.0, rate = 100.0;
  const double inf = std::numeric_limits<double>::infinity();
  // A torque <= 0 once reached std::clamp(u, 5, -5), undefined, and drove the base with no command.
  const Bounds size{0.0, core::ranges::kMaxExtent, true, "m"}, torque{0.0, inf, true, "N*m"};
  numbers.at(&plugin, "wheelSeparation", separation, size);
  numbers.at(&plugin, "wheelDiameter", diameter, size);
  d.settings.max_wheel_torque = 5.0;
  d.settings.cmd_vel_timeout = inf;
  numbers.at(&plugin, torque_key, d.settings.max_wheel_torque, torque);
  numbers.rate(&plugin, "updateRate", rate);
  if (plugin.FirstChildElement("wheelSeparation") != nullptr) d.wheel_separation = separation;
  if (plugin.FirstChildElement("wheelDiameter") != nullptr) d.wheel_radius = 0.5 * diameter;
  DriveTopics& t = d.topics;
  if (rate > 0.0) {
    t.publish_rate = rate;
  } else {  // within the rates or 0
    unread("<plugin> " + std::string(file) + " <updateRate> 0 (read as 100 Hz)", e.name);
  }
  t.under_controller = false;
  t.cmd_vel_topic = childTopic(plugin, "commandTopic", "cmd_vel", e.key);
  t.odom_topic = childTopic(plugin, "odometryTopic", "odom", e.key);
  t.odom_frame_id = childFrame(plugin, "odometryFrame", "odom", e.key);
  t.base_frame_id = childFrame(plugin, "robotBaseFrame", "base_footprint", e.key);
  t.enable_odom_tf = childFlag(plugin, tf_key, tf_default, e.key);
}

/// gazebo_ros_diff_drive's model plugin as a DiffDriveController (its
/// topics under the robot's prefix, not a controller's namespace):
/// `leftJoint`, `rightJoint` ("left_joint", "right_joint"), what
/// readPluginDrive reads (`wheelTorque`, `publishOdomTF`), `wheelAcceleration`
/// (m/s² at the rim; 0: none) as the linear and angular acceleration
/// limits, and the plugin's pose covariances. Its odometry is the wheels'
/// here, whatever `odometrySource` says (the plugin's default, "world",
/// reports the truth: said); `publishTf` false is said too.
ControllerEntry pluginDrive(const TiXmlElement& plugin, const Unread& unread) {
  ControllerEntry e;
  e.name = attribute(plugin, "name").empty() ? "diff_drive" : attribute(plugin, "name");
  DiffDriveEntry& d = e.drive.emplace();
  d.left = {childText(plugin, "leftJoint", "left_joint")};
  d.right = {childText(plugin, "rightJoint", "right_joint")};
  readPluginDrive(plugin, "libgazebo_ros_diff_drive.so", "wheelTorque", "publishOdomTF", true, unread, e);
  const Numbers numbers(e.key);
  double accel = 0.0;
  numbers.at(&plugin, "wheelAcceleration", accel,
             Bounds{0.0, std::numeric_limits<double>::infinity(), false, "m/s^2 (0: none)"});
  if (accel > 0.0) {
    core::TwistLimiter& linear = d.settings.linear;
    linear.has_acceleration_limits = true;
    linear.min_acceleration = -accel;
    linear.max_acceleration = accel;
    if (d.wheel_separation && *d.wheel_separation > 0.0) {  // one wheel at +a, the other at -a
      core::TwistLimiter& angular = d.settings.angular;
      angular.has_acceleration_limits = true;
      angular.max_acceleration = 2.0 * accel / *d.wheel_separation;
      angular.min_acceleration = -angular.max_acceleration;
    }
  }
  d.topics.pose_covariance_diagonal = {1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3};  // the plugin's
  if (!childFlag(plugin, "publishTf", true, e.key)) {
    unread("<plugin> libgazebo_ros_diff_drive.so <publishTf> false (its odometry is published)", e.name);
  }
  if (childText(plugin, "odometrySource", "world") != "encoder") {
    unread("<plugin> libgazebo_ros_diff_drive.so <odometrySource> world (odometry from the wheels here)", e.name);
  }
  if (plugin.FirstChildElement("legacyMode") != nullptr) {
    unread("<plugin> libgazebo_ros_diff_drive.so <legacyMode>", e.name);
  }
  return e;
}

/// gazebo_ros_skid_steer_drive's model plugin as a DiffDriveController of
/// two wheels a side: `leftFrontJoint` and `leftRearJoint` on the left,
/// `rightFrontJoint` and `rightRearJoint` on the right (the plugin's
/// defaults "left_front_joint" and so on), what readPluginDrive reads
/// (`torque`, `broadcastTF` false by default, as the plugin's), and
/// `covariance_x`, `covariance_y`, `covariance_yaw` (1e-4, 1e-4, 1e-2) on
/// the pose and the twist. The plugin reports the truth as its odometry;
/// here it is the wheels' (said), which a skidding base makes drift.
ControllerEntry pluginSkidSteer(const TiXmlElement& plugin, const Unread& unread) {
  ControllerEntry e;
  e.name = attribute(plugin, "name").empty() ? "skid_steer_drive" : attribute(plugin, "name");
  DiffDriveEntry& d = e.drive.emplace();
  d.left = {childText(plugin, "leftFrontJoint", "left_front_joint"),
            childText(plugin, "leftRearJoint", "left_rear_joint")};
  d.right = {childText(plugin, "rightFrontJoint", "right_front_joint"),
             childText(plugin, "rightRearJoint", "right_rear_joint")};
  readPluginDrive(plugin, "libgazebo_ros_skid_steer_drive.so", "torque", "broadcastTF", false, unread, e);
  const Numbers numbers(e.key);
  double cx = 1e-4, cy = 1e-4, cyaw = 1e-2;
  const Bounds covariance{0.0, 1e12, false, "(a variance)"};
  numbers.at(&plugin, "covariance_x", cx, covariance);
  numbers.at(&plugin, "covariance_y", cy, covariance);
  numbers.at(&plugin, "covariance_yaw", cyaw, covariance);
  d.topics.pose_covariance_diagonal = d.topics.twist_covariance_diagonal = {cx, cy, 1e12, 1e12, 1e12, cyaw};
  unread("<plugin> libgazebo_ros_skid_steer_drive.so odometry of the truth (odometry from the wheels here)", e.name);
  return e;
}
/// gazebo_ros_tricycle_drive's model plugin (gazebo_plugins, ROS 1) as a
/// steered drive (§11.14): `steeringJoint` ("front_steering_joint") turns
/// `actuatedWheelJoint` ("front_wheel_joint"), whose rim runs at the
/// command's linear x (`actuatedWheelDiameter`, 0.15 m, or none: the URDF's)
/// while its steering angle is the command's angular z, held within ±90°;
/// `encoderWheelLeftJoint` and `encoderWheelRightJoint` ("left_wheel_joint",
/// "right_wheel_joint") place the fixed axle. `wheelTorque` (5 N·m) bounds
/// the wheel, `wheelAcceleration` (m/s² at the rim, 0: none) its speed's
/// change, `wheelDeceleration` its change downward; `steeringSpeed`
/// (rad/s, 0: as fast as the servo) the steering's. The topics and frames
/// as readPluginDrive's; odom -> base is on tf, as the plugin always puts it.
/// Its odometry is the wheels' here (the plugin's default `odometrySource`
/// world reports the truth, its encoder source the rear wheels': both said).
ControllerEntry pluginTricycle(const TiXmlElement& plugin, const Unread& unread) {
  ControllerEntry e;
  e.name = attribute(plugin, "name").empty() ? "tricycle_drive" : attribute(plugin, "name");
  DiffDriveEntry& d = e.drive.emplace();
  const char* file = "libgazebo_ros_tricycle_drive.so";
  d.left = {childText(plugin, "actuatedWheelJoint", "front_wheel_joint")};
  d.steers = {childText(plugin, "steeringJoint", "front_steering_joint")};
  d.fixed_axle = {childText(plugin, "encoderWheelLeftJoint", "left_wheel_joint"),
                  childText(plugin, "encoderWheelRightJoint", "right_wheel_joint")};
  d.speed_at_steered_wheel = true;
  readPluginDrive(plugin, file, "wheelTorque", "publishOdomTF", true, unread, e);
  e.joints.insert(e.joints.end(), d.steers.begin(), d.steers.end());
  const Numbers numbers(e.key);
  const double inf = std::numeric_limits<double>::infinity();
  double diameter = 0.15, accel = 0.0, steering_speed = 0.0;
  numbers.at(&plugin, "actuatedWheelDiameter", diameter, Bounds{0.0, core::ranges::kMaxExtent, true, "m"});
  d.wheel_radius = 0.5 * diameter;
  const Bounds rate{0.0, inf, false, "(0: none)"};
  numbers.at(&plugin, "wheelAcceleration", accel, rate);
  double decel = accel;
  numbers.at(&plugin, "wheelDeceleration", decel, rate);
  if (accel > 0.0 || decel > 0.0) {
    core::TwistLimiter& linear = d.settings.linear;
    linear.has_acceleration_limits = true;
    linear.max_acceleration = accel > 0.0 ? accel : 1e6;  // m/s², none in effect
    linear.min_acceleration = -(decel > 0.0 ? decel : linear.max_acceleration);
  }
  numbers.at(&plugin, "steeringSpeed", steering_speed, Bounds{0.0, 1e3, false, "rad/s (0: none)"});
  if (steering_speed > 0.0) d.steering_speed = steering_speed;
  unread(std::string("<plugin> ") + file + " <odometrySource> " + childText(plugin, "odometrySource", "world") +
             " (odometry from the driven wheel and the steering here)",
         e.name);
  for (const char* k :
       {"encoderWheelDiameter", "encoderWheelSeparation", "wheelSpeedTolerance", "steeringAngleTolerance"}) {
    if (plugin.FirstChildElement(k) != nullptr) unread(std::string("<plugin> ") + file + " <" + k + ">", e.name);
  }
  for (const char* k : {"publishWheelTF", "publishWheelJointState"}) {  // joint_states and robot_state_publisher's tf
    if (childFlag(plugin, k, false, e.key)) unread(std::string("<plugin> ") + file + " <" + k + ">", e.name);
  }
  return e;
}

/// gazebo_ros_ft_sensor's model plugin: `jointName` and `topicName`
/// (both required, as the plugin's), at `updateRate` (0 or none: every
/// step), `gaussianNoise` (0) on each of its six numbers.
ForceTorqueEntry pluginForceTorque(const TiXmlElement& plugin) {
  ForceTorqueEntry f;
  f.key = "<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">";
  f.joint = childText(plugin, "jointName", "");
  if (f.joint.empty()) throw std::invalid_argument(f.key + ": <jointName> is required");
  if (childText(plugin, "topicName", "").empty()) throw std::invalid_argument(f.key + ": <topicName> is required");
  f.topic = childTopic(plugin, "topicName", "", f.key);
  const Numbers numbers(f.key);
  numbers.rate(&plugin, "updateRate", f.rate);
  numbers.at(&plugin, "gaussianNoise", f.settings.noise,
             Bounds{0.0, std::numeric_limits<double>::infinity(), false, "(sigma, N and N*m)"});
  return f;
}

/// roboticsgroup's mimic-joint plugin (its two names): `mimicJoint`
/// follows `joint` at `multiplier` (1) and `offset` (0 rad or m), held by
/// the core's mimic row as a URDF <mimic> is, so `hasPID`, `maxEffort`
/// and `sensitiveness`, which tune the plugin's own tracking, do not apply.
RobotDevices::Mimic pluginMimic(const TiXmlElement& plugin) {
  RobotDevices::Mimic m;
  m.key = "<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">";
  const Numbers numbers(m.key);
  m.leader = childText(plugin, "joint", "");
  m.follower = childText(plugin, "mimicJoint", "");
  if (m.leader.empty() || m.follower.empty()) {
    throw std::invalid_argument(m.key + ": <joint> and <mimicJoint> are both required");
  }
  numbers.at(&plugin, "multiplier", m.multiplier, Bounds{-1e3, 1e3, false, ""});
  numbers.at(&plugin, "offset", m.offset, Bounds{-1e3, 1e3, false, "rad or m"});
  return m;
}

}  // namespace

bool isMimicPlugin(const std::string& file) {
  return file == "libroboticsgroup_gazebo_mimic_joint_plugin.so" ||
         file == "libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so";
}

bool readsModelPlugin(const TiXmlElement& plugin) {
  const std::string file = attribute(plugin, "filename");
  return file == "libgazebo_ros_imu.so" || file == "libgazebo_ros_p3d.so" || file == "libgazebo_ros_diff_drive.so" ||
         file == "libgazebo_ros_skid_steer_drive.so" || file == "libgazebo_ros_control.so" ||
         file == "libhector_gazebo_ros_imu.so" || file == "libhector_gazebo_ros_gps.so" ||
         file == "libhector_gazebo_ros_magnetic.so" || file == "libgazebo_ros_ft_sensor.so" ||
         file == "libgazebo_ros_kobuki.so" || file == "libgazebo_ros_tricycle_drive.so" || isMimicPlugin(file) ||
         isBaseMovePlugin(file);
}

void readModelPlugin(const TiXmlElement& plugin, const Unread& unread, RobotDevices& out) {
  const std::string file = attribute(plugin, "filename");
  const std::string link = childText(plugin, "bodyName", "");
  if (file == "libgazebo_ros_diff_drive.so") {
    out.controllers.push_back(pluginDrive(plugin, unread));
  } else if (file == "libgazebo_ros_skid_steer_drive.so") {
    out.controllers.push_back(pluginSkidSteer(plugin, unread));
  } else if (file == "libgazebo_ros_tricycle_drive.so") {
    out.controllers.push_back(pluginTricycle(plugin, unread));
  } else if (file == "libhector_gazebo_ros_imu.so") {  // without bodyName: the base
    out.imus.push_back(pluginHectorImu(plugin, unread));
  } else if (file == "libhector_gazebo_ros_gps.so") {
    out.gnss.push_back(pluginHectorGps(plugin, unread));
  } else if (file == "libhector_gazebo_ros_magnetic.so") {
    out.magnetometers.push_back(pluginHectorMagnetic(plugin));
  } else if (isMimicPlugin(file)) {
    out.mimics.push_back(pluginMimic(plugin));
  } else if (isBaseMovePlugin(file)) {
    readBaseMovePlugin(plugin, unread, out);
  } else if (file == "libgazebo_ros_kobuki.so") {
    readKobukiPlugin(plugin, unread, out);
  } else if (file == "libgazebo_ros_ft_sensor.so") {
    out.force_torques.push_back(pluginForceTorque(plugin));
  } else if (file == "libgazebo_ros_control.so") {  // the controllers' namespace; they run every step
    const std::string where = "<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">";
    if (!childText(plugin, "robotNamespace", "").empty()) {  // empty: the root, as none
      out.robot_namespace = childTopic(plugin, "robotNamespace", "", where);
    }
    const std::string sim_type = childText(plugin, "robotSimType", "");
    if (sim_type == kSteerBotSimType) {
      out.robot_sim_type = sim_type;
    } else if (!sim_type.empty() && sim_type != "gazebo_ros_control/DefaultRobotHWSim") {
      unread("<plugin> libgazebo_ros_control.so <robotSimType> " + sim_type + " (the default hardware runs)",
             attribute(plugin, "name"));
    }
    if (plugin.FirstChildElement("controlPeriod") != nullptr) {
      unread("<plugin> libgazebo_ros_control.so <controlPeriod> (the controllers run every step)",
             attribute(plugin, "name"));
    }
  } else if (link.empty()) {
    unread("<plugin> " + file + " without <bodyName> (Gazebo does not run it)", attribute(plugin, "name"));
  } else if (file == "libgazebo_ros_imu.so") {
    out.imus.push_back(pluginImu(plugin, link, unread));
  } else {
    out.odometry.push_back(pluginOdometry(plugin, link, unread));
  }
}

}  // namespace rigid_body_sim::io::detail
