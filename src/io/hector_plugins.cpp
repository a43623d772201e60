// The model plugins of hector_gazebo_plugins: hector_plugins.h.
#include "hector_plugins.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace rigid_body_sim::io::detail {

namespace {

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

}  // namespace

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

}  // namespace rigid_body_sim::io::detail
