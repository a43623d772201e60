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

#include "drive_config.h"
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

/// A hector plugin's `name` (three numbers, one per axis, as hector reads
/// them; one number is all three), if there, into `axes`; refused naming it
/// unless each is ≥ 0 (or any sign, `any_sign`).
void hectorAxes(const Numbers& numbers, const TiXmlElement& plugin, const std::string& name,
                std::array<double, 3>& axes, bool any_sign = false) {
  const TiXmlElement* e = plugin.FirstChildElement(name.c_str());
  if (e == nullptr) return;
  std::istringstream words(e->GetText() != nullptr ? e->GetText() : "");
  std::size_t n = 0;
  for (std::string w; words >> w;) ++n;
  const std::vector<double> x = numbers.read(*e, name, n == 1 ? 1 : 3);
  for (double v : x) {
    if (v < 0.0 && !any_sign) numbers.fail(name, e->GetText(), "each must be >= 0");
  }
  axes = n == 1 ? std::array<double, 3>{x[0], x[0], x[0]} : std::array<double, 3>{x[0], x[1], x[2]};
}

/// The largest of `axes`, and said to `unread` when they differ (the IMU
/// here has one σ for its three axes).
double oneForAllAxes(const std::array<double, 3>& axes, const std::string& element, const std::string& link,
                     const Unread& unread) {
  const double most = std::max({axes[0], axes[1], axes[2]});
  if (axes[0] != axes[1] || axes[1] != axes[2]) {
    unread("<plugin> libhector_gazebo_ros_imu.so <" + element + "> per axis (the largest for all three)", link);
  }
  return most;
}

/// The IMU of hector_gazebo_ros_imu's model plugin (Husky's, Jackal's):
/// on `bodyName` (none: the robot's base, as hector's first link),
/// `updateRate` (0 or none: every step), `topicName` ("imu"), `frameId`
/// (bodyName), `accelGaussianNoise` and `rateGaussianNoise` (or
/// `gaussianNoise` for both), and `accelDrift` and `rateDrift` with their
/// `DriftFrequency` (1/3600 Hz) as a bias random walk of density
/// drift·√(2·frequency): the Gauss-Markov drift hector documents, without
/// its return toward zero over 1/frequency (an hour by default).
/// `headingGaussianNoise` is the orientation's noise (about every axis;
/// hector's is yaw alone), `randomEngineSeed` the seed. Its readings follow
/// REP 145 as hector's do. A constant offset, heading drift, or the
/// calibration services are said, not run.
ImuEntry pluginHectorImu(const TiXmlElement& plugin, const Unread& unread) {
  ImuEntry imu;
  imu.key = "<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">";
  imu.link = childText(plugin, "bodyName", "");
  const std::string said = imu.link.empty() ? attribute(plugin, "name") : imu.link;
  const Numbers numbers(imu.key);
  double rate = 0.0, sigma = 0.0, seed = 0.0;
  numbers.rate(&plugin, "updateRate", rate);
  imu.settings.rate = rate > 0.0 ? rate : std::numeric_limits<double>::infinity();
  std::array<double, 3> accel{}, gyro{}, accel_drift{}, gyro_drift{}, heading{};
  std::array<double, 3> accel_f{}, gyro_f{};
  accel_f.fill(1.0 / 3600.0);
  gyro_f.fill(1.0 / 3600.0);
  hectorAxes(numbers, plugin, "accelGaussianNoise", accel);
  hectorAxes(numbers, plugin, "rateGaussianNoise", gyro);
  numbers.at(&plugin, "gaussianNoise", sigma, Bounds{0.0, std::numeric_limits<double>::infinity(), false, "(sigma)"});
  if (sigma > 0.0) accel.fill(sigma), gyro.fill(sigma);  // as hector: it overrides both
  hectorAxes(numbers, plugin, "accelDrift", accel_drift);
  hectorAxes(numbers, plugin, "rateDrift", gyro_drift);
  hectorAxes(numbers, plugin, "accelDriftFrequency", accel_f);
  hectorAxes(numbers, plugin, "rateDriftFrequency", gyro_f);
  numbers.at(&plugin, "headingGaussianNoise", heading[0], Bounds{0.0, 1.0, false, "rad"});
  imu.settings.accel_noise = oneForAllAxes(accel, "accelGaussianNoise", said, unread);
  imu.settings.gyro_noise = oneForAllAxes(gyro, "rateGaussianNoise", said, unread);
  const auto walk = [&](const std::array<double, 3>& drift, const std::array<double, 3>& f, const char* element) {
    std::array<double, 3> density{};
    for (int k = 0; k < 3; ++k) density[k] = drift[k] * std::sqrt(2.0 * f[k]);
    return oneForAllAxes(density, element, said, unread);
  };
  imu.settings.accel_bias_walk = walk(accel_drift, accel_f, "accelDrift");
  imu.settings.gyro_bias_walk = walk(gyro_drift, gyro_f, "rateDrift");
  imu.settings.orientation_noise = heading[0];
  numbers.at(&plugin, "randomEngineSeed", seed, Bounds{0.0, 4294967295.0, false, "(a seed)"});
  imu.settings.seed = static_cast<std::uint64_t>(seed);
  imu.topic = childTopic(plugin, "topicName", "imu", imu.key);
  imu.frame_id = childFrame(plugin, "frameId", imu.link, imu.key);
  for (const char* element : {"accelOffset", "rateOffset", "headingOffset", "headingDrift", "rpyOffset", "xyzOffset"}) {
    if (const TiXmlElement* e = plugin.FirstChildElement(element)) {
      std::istringstream words(e->GetText() != nullptr ? e->GetText() : "");
      for (std::string w; words >> w;) {
        if (std::strtod(w.c_str(), nullptr) != 0.0) {
          unread("<plugin> libhector_gazebo_ros_imu.so <" + std::string(element) + "> (not run)", said);
          break;
        }
      }
    }
  }
  if (plugin.FirstChildElement("serviceName") != nullptr) {
    unread("<plugin> libhector_gazebo_ros_imu.so <serviceName> (no calibration service here)", said);
  }
  return imu;
}

/// hector's error model of a reading (its SensorModel3): `offset`, `drift`,
/// `driftFrequency` and `gaussianNoise`, each after `prefix` ("velocity":
/// `velocityOffset`, ...) with a capital, one number or one per axis.
core::SensorErrorSettings hectorError(const Numbers& numbers, const TiXmlElement& plugin, const std::string& prefix) {
  const auto name = [&](std::string n) {
    if (!prefix.empty()) n[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(n[0])));
    return prefix + n;
  };
  std::array<double, 3> offset{}, drift{}, frequency{}, noise{};
  frequency.fill(1.0 / 3600.0);
  hectorAxes(numbers, plugin, name("offset"), offset, true);
  hectorAxes(numbers, plugin, name("drift"), drift);
  hectorAxes(numbers, plugin, name("driftFrequency"), frequency);
  hectorAxes(numbers, plugin, name("gaussianNoise"), noise);
  const auto vec = [](const std::array<double, 3>& a) { return core::Vec3(a[0], a[1], a[2]); };
  return core::SensorErrorSettings{vec(offset), vec(drift), vec(frequency), vec(noise)};
}

/// What hector_gazebo_ros_gps and hector_gazebo_ros_magnetic read alike,
/// into `e`: `bodyName` (none: the base), `frameId` (the link's),
/// `updateRate` (none: e.rate as it is; 0: every step), and
/// `referenceHeading` (deg) into `heading`.
template <typename Entry>
void readHectorSensor(const TiXmlElement& plugin, const Numbers& numbers, double& heading, Entry& e) {
  e.key = "<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">";
  e.link = childText(plugin, "bodyName", "");
  e.frame_id = childFrame(plugin, "frameId", e.link, e.key);
  numbers.rate(&plugin, "updateRate", e.rate);
  numbers.at(&plugin, "referenceHeading", heading, Bounds{-360.0, 360.0, false, "deg"});
}

/// hector_gazebo_ros_gps's model plugin (Husky's, Jackal's): what
/// readHectorSensor reads (4 Hz), `topicName` ("fix"), `velocityTopicName`
/// ("fix_velocity"), `referenceLatitude`, `referenceLongitude` (49.9, 8.9
/// deg), `referenceHeading` (0: x north, y west), `referenceAltitude` (0
/// m), `status` and `service` (STATUS_FIX, SERVICE_GPS), the position's
/// error model and the velocity's (`velocity...`). Without a world's
/// spherical coordinates here, `useWorldSphericalCoordinates` is said; so
/// are the dropouts and jumps, not run.
GnssEntry pluginHectorGps(const TiXmlElement& plugin, const Unread& unread) {
  GnssEntry g;
  const Numbers numbers("<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">");
  core::GeoReference& r = g.settings.reference;
  readHectorSensor(plugin, numbers, r.heading, g);
  numbers.at(&plugin, "referenceLatitude", r.latitude, Bounds{-89.0, 89.0, false, "deg"});
  numbers.at(&plugin, "referenceLongitude", r.longitude, Bounds{-180.0, 180.0, false, "deg"});
  numbers.at(&plugin, "referenceAltitude", r.altitude, Bounds{-1e5, 1e6, false, "m"});
  g.topic = childTopic(plugin, "topicName", "fix", g.key);
  g.velocity_topic = childTopic(plugin, "velocityTopicName", "fix_velocity", g.key);
  g.settings.position = hectorError(numbers, plugin, "");
  g.settings.velocity = hectorError(numbers, plugin, "velocity");
  int status = 0, service = 1;
  numbers.count(&plugin, "status", status, Bounds{-1.0, 2.0, false, "(a NavSatStatus status)"});
  numbers.count(&plugin, "service", service, Bounds{0.0, 15.0, false, "(NavSatStatus service bits)"});
  g.status = status;
  g.service = service;
  const std::string said = g.link.empty() ? attribute(plugin, "name") : g.link;
  if (childFlag(plugin, "useWorldSphericalCoordinates", false, g.key)) {
    unread("<plugin> libhector_gazebo_ros_gps.so <useWorldSphericalCoordinates> (no world's; its reference elements)",
           said);
  }
  for (const char* element : {"delayedStartMaxS", "dropoutSet", "jumpSet"}) {
    if (plugin.FirstChildElement(element) != nullptr) {
      unread("<plugin> libhector_gazebo_ros_gps.so <" + std::string(element) + "> (no dropouts or jumps here)", said);
    }
  }
  return g;
}

/// hector_gazebo_ros_magnetic's model plugin: what readHectorSensor reads
/// (every step), `topicName` ("magnetic"), `magnitude` (1), `referenceHeading`
/// (90: x east), `declination` (0°), `inclination` (60°),
/// `useMagneticFieldMsgs` (false: geometry_msgs/Vector3Stamped).
MagnetometerEntry pluginHectorMagnetic(const TiXmlElement& plugin) {
  MagnetometerEntry m;
  const Numbers numbers("<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">");
  core::MagnetometerSettings& s = m.settings;
  readHectorSensor(plugin, numbers, s.heading, m);
  numbers.at(&plugin, "magnitude", s.magnitude, Bounds{0.0, 1e6, false, "(the field's unit)"});
  numbers.at(&plugin, "declination", s.declination, Bounds{-180.0, 180.0, false, "deg"});
  numbers.at(&plugin, "inclination", s.inclination, Bounds{-90.0, 90.0, false, "deg"});
  m.topic = childTopic(plugin, "topicName", "magnetic", m.key);
  m.field_message = childFlag(plugin, "useMagneticFieldMsgs", false, m.key);
  s.error = hectorError(numbers, plugin, "");
  return m;
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
         file == "libhector_gazebo_ros_magnetic.so" || isMimicPlugin(file);
}

void readModelPlugin(const TiXmlElement& plugin, const Unread& unread, RobotDevices& out) {
  const std::string file = attribute(plugin, "filename");
  const std::string link = childText(plugin, "bodyName", "");
  if (file == "libgazebo_ros_diff_drive.so") {
    out.controllers.push_back(pluginDrive(plugin, unread));
  } else if (file == "libgazebo_ros_skid_steer_drive.so") {
    out.controllers.push_back(pluginSkidSteer(plugin, unread));
  } else if (file == "libhector_gazebo_ros_imu.so") {  // without bodyName: the base
    out.imus.push_back(pluginHectorImu(plugin, unread));
  } else if (file == "libhector_gazebo_ros_gps.so") {
    out.gnss.push_back(pluginHectorGps(plugin, unread));
  } else if (file == "libhector_gazebo_ros_magnetic.so") {
    out.magnetometers.push_back(pluginHectorMagnetic(plugin));
  } else if (isMimicPlugin(file)) {
    out.mimics.push_back(pluginMimic(plugin));
  } else if (file == "libgazebo_ros_control.so") {  // the controllers' namespace; they run every step
    const std::string where = "<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">";
    if (!childText(plugin, "robotNamespace", "").empty()) {  // empty: the root, as none
      out.robot_namespace = childTopic(plugin, "robotNamespace", "", where);
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
