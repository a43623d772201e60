// The plugins that move a robot's base as a whole: base_plugins.h.
#include "base_plugins.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::io::detail {

namespace {

/// force_based_move, and Clearpath's copy of it (Ridgeback's, Dingo's).
bool forceBased(const std::string& file) {
  return file == "libgazebo_ros_force_based_move.so" || file == "libridgeback_ros_force_based_move.so";
}

}  // namespace

bool isBaseMovePlugin(const std::string& file) { return file == "libgazebo_ros_planar_move.so" || forceBased(file); }

/// Both plugins (gazebo_plugins' ROS 1 sources): `commandTopic` ("cmd_vel")
/// takes a twist in the base's heading (x, y and the yaw rate; the rest of
/// the twist is not driven), held until the next (`cmdTimeout` > 0: for
/// that long); `odometryTopic` ("odom") at `odometryRate` (20 Hz) reports
/// the truth of `robotBaseFrame` ("base_footprint", a link of the robot or
/// one fixed to it) in `odometryFrame` ("odom", where the world is), and
/// `publishOdometryTf` (true) puts odom -> robotBaseFrame on tf.
///
/// planar_move sets the model's velocity each step, without limit; here a
/// wrench drives the base there (core::VelocityDriver's PI at its default
/// gains, 20 ms to settle), within 2 g of the robot's mass and 40 rad/s² of
/// its yaw inertia, so friction and contacts still act. force_based_move
/// pushes with `x_velocity_p_gain` and `y_velocity_p_gain` (10000 N per
/// m/s; the larger of the two here, said when they differ) and
/// `yaw_velocity_p_gain` (100 N·m per rad/s), its own P law, within the same limits.
/// Clearpath's copy (libridgeback_ros_force_based_move.so, Ridgeback's and
/// Dingo's) reads the same, its timeout `cmdVelTimeOut`.
void readBaseMovePlugin(const TiXmlElement& plugin, const Unread& unread, RobotDevices& out) {
  const std::string file = attribute(plugin, "filename");
  const std::string name = attribute(plugin, "name");
  const std::string key = "<gazebo> <plugin name=\"" + name + "\">";
  if (out.base_drive) {
    throw std::invalid_argument(key + ": a second plugin driving the base (" + out.base_drive->key +
                                " drives it already)");
  }
  const Numbers numbers(key);
  const double inf = std::numeric_limits<double>::infinity();
  BaseDriveEntry drive;
  drive.key = key;
  drive.topic = childTopic(plugin, "commandTopic", "cmd_vel", key);
  core::DriverSettings& s = drive.settings;
  s.planar = true;
  // None in the plugin: the world's limits.* hold, whatever they are set to.
  s.max_linear_speed = s.max_angular_speed = core::ranges::kMaxSpeedLimit;
  double timeout = -1.0;
  numbers.at(&plugin, "cmdTimeout", timeout, Bounds{-inf, 1e6, false, "s (<= 0: held)"});
  numbers.at(&plugin, "cmdVelTimeOut", timeout, Bounds{-inf, 1e6, false, "s (<= 0: held)"});
  s.timeout = timeout > 0.0 ? timeout : 0.0;
  if (forceBased(file)) {
    double gx = 10000.0, gy = 10000.0, gyaw = 100.0;
    const Bounds gain{0.0, 1e7, true, "N per m/s"}, yaw_gain{0.0, 1e7, true, "N*m per rad/s"};
    numbers.at(&plugin, "x_velocity_p_gain", gx, gain);
    numbers.at(&plugin, "y_velocity_p_gain", gy, gain);
    numbers.at(&plugin, "yaw_velocity_p_gain", gyaw, yaw_gain);
    if (gx != gy)
      unread("<plugin> " + file + " <x_velocity_p_gain> unlike <y_velocity_p_gain> (the larger for both)", name);
    drive.force_gain = std::max(gx, gy);
    drive.torque_gain = gyaw;
    s.linear_integral_gain = s.angular_integral_gain = 0.0;  // its P law alone
  }
  OdometryEntry odom;
  odom.key = key;
  odom.link = childText(plugin, "robotBaseFrame", "base_footprint");
  odom.topic = childTopic(plugin, "odometryTopic", "odom", key);
  odom.frame_id = childFrame(plugin, "odometryFrame", "odom", key);
  double rate = 20.0;
  numbers.rate(&plugin, "odometryRate", rate);
  odom.rate = rate > 0.0 ? rate : inf;  // 0: every step
  odom.on_tf = childFlag(plugin, "publishOdometryTf", true, key);
  out.base_drive = std::move(drive);
  out.odometry.push_back(std::move(odom));
}

}  // namespace rigid_body_sim::io::detail
