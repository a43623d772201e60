// gazebo_ros_kobuki's markup: kobuki_plugin.h.
#include "kobuki_plugin.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "drive_config.h"
#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::io::detail {
namespace {

/// The `<gazebo reference="LINK"><sensor type="imu" name="NAME">` of the
/// robot the plugin is in, or nullptr; `link` its LINK.
const TiXmlElement* imuSensor(const TiXmlElement& plugin, const std::string& name, std::string& link) {
  const TiXmlNode* gazebo = plugin.Parent();
  const TiXmlNode* robot = gazebo != nullptr ? gazebo->Parent() : nullptr;
  if (robot == nullptr) return nullptr;
  for (const TiXmlElement* g = robot->FirstChildElement("gazebo"); g; g = g->NextSiblingElement("gazebo")) {
    for (const TiXmlElement* s = g->FirstChildElement("sensor"); s; s = s->NextSiblingElement("sensor")) {
      if (attribute(*s, "type") == "imu" && attribute(*s, "name") == name) {
        link = attribute(*g, "reference");
        return s;
      }
    }
  }
  return nullptr;
}

/// A required element's text, or throws naming it (the plugin does not load without it).
std::string required(const TiXmlElement& plugin, const char* name, const std::string& key) {
  std::string text = childText(plugin, name, "");
  if (text.empty()) throw std::invalid_argument(key + ": <" + std::string(name) + "> is required");
  return text;
}

}  // namespace

/// gazebo_ros_kobuki (kobuki_gazebo_plugins, ROS 1): a DiffDriveController
/// named as the plugin on `left_wheel_joint_name` and
/// `right_wheel_joint_name`, `wheel_separation` and `wheel_diameter` (all
/// required, as the plugin's), `torque` as each wheel's most effort,
/// `velocity_command_timeout` (s) as its cmd_vel timeout; on the plugin's
/// topics under the robot's namespace: `mobile_base/commands/velocity` in,
/// `odom` out (odom -> base_footprint, pose covariance 0.1, 0.1 and 0.05 on
/// yaw), `publish_tf` for that transform on tf, at `update_rate` (0: every
/// step, as the plugin's default). Its IMU is the `<sensor type="imu">`
/// named `imu_name`, on its link: on `mobile_base/sensors/imu_data` headed
/// `base_link` at the same rate, its noise the sensor's `<imu><noise>`
/// `<rate>` and `<accel>` `<stddev>`. Kobuki's odometry takes its heading
/// from the gyro; here it is the wheels' (said). Its cliff, bumper and
/// wheel-drop events and its motor power and odometry reset topics are
/// kobuki_msgs', not in Debian 12: said and not run.
void readKobukiPlugin(const TiXmlElement& plugin, const Unread& unread, RobotDevices& out) {
  const std::string name = attribute(plugin, "name").empty() ? "kobuki" : attribute(plugin, "name");
  const std::string key = "<gazebo> <plugin name=\"" + name + "\">";
  const Numbers numbers(key);
  const double inf = std::numeric_limits<double>::infinity();
  ControllerEntry e;
  e.name = name;
  e.type = kDiffDriveType;
  e.key = key;
  DiffDriveEntry& d = e.drive.emplace();
  d.left = {required(plugin, "left_wheel_joint_name", key)};
  d.right = {required(plugin, "right_wheel_joint_name", key)};
  e.joints = {d.left[0], d.right[0]};
  e.joint_list = true;
  required(plugin, "wheel_separation", key);
  required(plugin, "wheel_diameter", key);
  required(plugin, "torque", key);
  required(plugin, "velocity_command_timeout", key);
  double separation = 0.0, diameter = 0.0, rate = 0.0;
  const Bounds size{0.0, core::ranges::kMaxExtent, true, "m"};
  numbers.at(&plugin, "wheel_separation", separation, size);
  numbers.at(&plugin, "wheel_diameter", diameter, size);
  d.wheel_separation = separation;
  d.wheel_radius = 0.5 * diameter;
  numbers.at(&plugin, "torque", d.settings.max_wheel_torque, Bounds{0.0, inf, true, "N*m"});
  numbers.at(&plugin, "velocity_command_timeout", d.settings.cmd_vel_timeout, Bounds{0.0, 1e6, false, "s"});
  numbers.rate(&plugin, "update_rate", rate);
  DriveTopics& t = d.topics;
  t.publish_rate = rate > 0.0 ? rate : core::ranges::kMaxPublishRate;  // capped at one a step
  t.under_controller = false;
  t.cmd_vel_topic = "mobile_base/commands/velocity";
  t.odom_topic = "odom";
  t.odom_frame_id = "odom";
  t.base_frame_id = "base_footprint";
  t.enable_odom_tf = childFlag(plugin, "publish_tf", false, key);
  t.pose_covariance_diagonal = {0.1, 0.1, 1e6, 1e6, 1e6, 0.05};
  t.twist_covariance_diagonal = t.pose_covariance_diagonal;
  out.controllers.push_back(std::move(e));
  unread("<plugin> libgazebo_ros_kobuki.so odometry heading from its gyro (from the wheels here)", name);
  unread(
      "<plugin> libgazebo_ros_kobuki.so cliff, bumper and wheel-drop events, motor power (kobuki_msgs is not in "
      "Debian 12)",
      name);
  // Its IMU: the sensor it names, published by the plugin.
  const std::string imu_name = required(plugin, "imu_name", key);
  std::string link;
  const TiXmlElement* sensor = imuSensor(plugin, imu_name, link);
  if (sensor == nullptr) {
    throw std::invalid_argument(key + " <imu_name>: the robot has no <sensor type=\"imu\" name=\"" + imu_name + "\">");
  }
  ImuEntry imu;
  imu.key = "<gazebo reference=\"" + link + "\"> <sensor name=\"" + imu_name + "\">";
  imu.link = link;
  const Numbers sensor_numbers(imu.key);
  if (const TiXmlElement* pose = sensor->FirstChildElement("pose")) {
    imu.settings.X_LS = sdfPose(sensor_numbers.read(*pose, "pose", 6));
  }
  imu.settings.rate = rate > 0.0 ? rate : inf;  // each of the plugin's updates; capped at one a step
  const Bounds sigma{0.0, inf, false, "(sigma)"};
  sensor_numbers.at(sensor, "imu/noise/rate/stddev", imu.settings.gyro_noise, sigma);
  sensor_numbers.at(sensor, "imu/noise/accel/stddev", imu.settings.accel_noise, sigma);
  imu.topic = "mobile_base/sensors/imu_data";
  imu.frame_id = "base_link";
  out.imus.push_back(std::move(imu));
}

}  // namespace rigid_body_sim::io::detail
