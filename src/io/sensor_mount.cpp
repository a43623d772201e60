// Where a robot's sensors sit: sensor_mount.h.
#include "rigid_body_sim/io/sensor_mount.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::io {

namespace {

/// The pose of `name` in link j's frame: j itself, or one of its fixed links (each posed in its parent's).
bool poseIn(const core::ArticulatedLink& link, const std::string& name, core::Pose& X) {
  if (link.name == name) {
    X = core::Pose{};
    return true;
  }
  for (const core::FixedLink& f : link.fixed_links) {
    if (f.name != name) continue;
    core::Pose X_LP;
    if (!poseIn(link, f.parent, X_LP)) return false;
    X = X_LP * f.X_PK;
    return true;
  }
  return false;
}

/// The moving link j carrying `link` (a link or a link lumped into one),
/// and X_LS of `pose` in `link` in j's frame; refused naming `key`.link.
void mount(const core::ArticulationModel& model, const std::string& link, const core::Pose& pose,
           const std::string& key, int& j, core::Pose& X_LS) {
  // As an IMU's: a sensor 1e39 m up published a cloud point at -inf.
  if (!(pose.translation.norm() <= core::ranges::kMaxExtent)) {
    throw ConfigError("config key '" + key + ".pose': the sensor is more than " +
                      std::to_string(static_cast<int>(core::ranges::kMaxExtent)) + " m from its link");
  }
  j = -1;
  for (std::size_t i = 0; i < model.links.size() && j < 0; ++i) {
    if (poseIn(model.links[i], link, X_LS)) j = static_cast<int>(i);
  }
  if (j < 0) {
    std::string names;
    for (const core::ArticulatedLink& l : model.links) {
      names += (names.empty() ? "'" : ", '") + l.name + "'";
      for (const core::FixedLink& f : l.fixed_links) names += ", '" + f.name + "'";
    }
    throw ConfigError("config key '" + key + ".link': robot '" + model.name + "' has no link '" + link +
                      "' (its links: " + names + ")");
  }
  X_LS = X_LS * pose;
}

/// Refuses a topic ROS cannot name: empty, or a character other than a
/// letter, digit, '_' or '/' (each sensor's `topic`, or a plugin's topicName).
void checkTopic(const std::string& topic, const std::string& key) {
  const bool named = !topic.empty() && std::all_of(topic.begin(), topic.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/';
  });
  if (!named) throw ConfigError(key + ": topic '" + topic + "' is no ROS name (letters, digits, '_' and '/')");
}

/// Whether `model` has a tf frame `name`: a link, or a link lumped into one.
bool hasFrame(const core::ArticulationModel& model, const std::string& name) {
  core::Pose X;
  for (const core::ArticulatedLink& link : model.links) {
    if (poseIn(link, name, X)) return true;
  }
  return false;
}

/// Refuses a rate outside the publish rates, naming `key`.
void checkRate(double rate, const std::string& key) {
  if (!(rate >= core::ranges::kMinRate && rate <= core::ranges::kMaxPublishRate)) {
    throw ConfigError(key + ": its rate " + std::to_string(rate) + " Hz is not within [" +
                      std::to_string(core::ranges::kMinRate) + ", " + std::to_string(core::ranges::kMaxPublishRate) +
                      "]");
  }
}

void mountOdometry(const std::vector<OdometryEntry>& entries, const core::ArticulationModel& model, double dt,
                   bool markup, std::vector<RobotOdometry>& out) {
  for (const OdometryEntry& e : entries) {
    checkTopic(e.topic, e.key);
    if (!e.ground_truth.empty()) checkTopic(e.ground_truth, e.key);
    const double rate = markup ? std::min({e.rate, 1.0 / dt, core::ranges::kMaxPublishRate}) : e.rate;
    if (rate != 0.0) checkRate(rate, e.key);
    if (e.noise) {
      try {
        core::validateOdomNoise(*e.noise, e.key);
      } catch (const std::invalid_argument& err) {
        throw ConfigError(err.what());
      }
    }
    RobotOdometry mounted{e, -1, {}};
    mounted.entry.rate = rate;
    mounted.entry.link = e.link.empty() ? model.links[0].name : e.link;
    // A link lumped into a moving one (hyq's trunk, tiago's base_link):
    // its frame's odometry, at its place in the moving link.
    mount(model, mounted.entry.link, core::Pose{}, e.key, mounted.link, mounted.X_LS);
    out.push_back(std::move(mounted));
  }
}

/// The receivers and magnetometers of `entries` (E: GnssEntry or
/// MagnetometerEntry, their settings checked by `check`) on their links, a
/// rate capped at one a step as Gazebo's.
template <typename E, typename Mounted, typename Check>
void mountEarthSensors(const std::vector<E>& entries, const core::ArticulationModel& model, double dt,
                       const Check& check, std::vector<Mounted>& out) {
  for (const E& e : entries) {
    checkTopic(e.topic, e.key);
    Mounted mounted{e, -1, {}};
    E& m = mounted.entry;
    m.rate = e.rate > 0.0 ? std::min({e.rate, 1.0 / dt, core::ranges::kMaxPublishRate}) : 0.0;
    if (m.rate != 0.0) checkRate(m.rate, e.key);
    try {
      check(m.settings, e.key);
    } catch (const std::invalid_argument& err) {
      throw ConfigError(err.what());
    }
    if (m.link.empty()) m.link = model.links[0].name;
    if (m.frame_id.empty()) m.frame_id = m.link;
    mount(model, m.link, core::Pose{}, e.key, mounted.link, mounted.X_LS);
    out.push_back(std::move(mounted));
  }
}

void mountContactSensors(const std::vector<ContactSensorEntry>& entries, const core::ArticulationModel& model,
                         double dt, std::vector<RobotContactSensor>& out) {
  for (const ContactSensorEntry& e : entries) {
    checkTopic(e.topic, e.key);
    RobotContactSensor mounted{e, -1, {}};
    mounted.entry.rate = e.rate > 0.0 ? std::min({e.rate, 1.0 / dt, core::ranges::kMaxPublishRate}) : 0.0;
    if (mounted.entry.rate != 0.0) checkRate(mounted.entry.rate, e.key);
    core::Pose X_LK;  // the sensor's link K, in the moving link
    mount(model, e.link, core::Pose{}, e.key, mounted.link, X_LK);
    if (!e.frame_id.empty()) {  // a frame of the robot: where it sits in the sensor's link
      int j = -1;
      core::Pose X_JF;
      mount(model, e.frame_id, core::Pose{}, e.key + " <frameName>", j, X_JF);
      if (j != mounted.link) {
        throw ConfigError(e.key + " <frameName> '" + e.frame_id + "': not a frame of link '" + e.link +
                          "' (its contacts are given in the world or in a frame fixed to it)");
      }
      mounted.X_LS = X_JF;
    }
    out.push_back(std::move(mounted));
  }
}

/// "12 MiB" (rounded up).
std::string mib(std::uintmax_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

void mountLidars(const std::vector<LidarEntry>& entries, const core::ArticulationModel& model, DeviceMemory& memory,
                 RobotSensors& out) {
  for (const LidarEntry& e : entries) {
    try {  // a URDF's markup is checked here; the config's was when it was read
      core::checkLidar(e.settings);
    } catch (const std::invalid_argument& err) {
      throw ConfigError(e.key + ": " + err.what());
    }
    checkRate(e.rate, e.key);
    checkTopic(e.topic, e.key);
    RobotLidar mounted{e, -1, {}};
    mount(model, e.link, e.pose, e.key, mounted.link, mounted.X_LS);
    const std::uintmax_t bytes = core::lidarBytes(e.settings);
    memory.take(bytes, e.key);
    out.bytes += bytes;
    out.lidars.push_back(std::move(mounted));
  }
}

void mountCameras(const std::vector<DepthCameraEntry>& entries, const core::ArticulationModel& model,
                  DeviceMemory& memory, RobotSensors& out) {
  for (const DepthCameraEntry& e : entries) {
    checkTopic(e.topic, e.key);
    // Each under the camera's namespace, or from the root ('/...') as
    // Gazebo's camera plugins allow (ROS resolves such a name as it is).
    for (const std::string* t : {&e.image_topic, &e.info_topic, &e.points_topic}) checkTopic(*t, e.key);
    checkRate(e.rate, e.key);
    try {  // a URDF's markup is checked here; the config's was when it was read
      core::checkDepthCamera(e.settings);
    } catch (const std::invalid_argument& err) {
      throw ConfigError(e.key + ": " + err.what());
    }
    RobotCamera mounted{e, -1, {}};
    mount(model, e.link, e.pose, e.key, mounted.link, mounted.X_LS);
    const std::uintmax_t bytes = core::depthCameraBytes(e.settings);
    memory.take(bytes, e.key);
    out.bytes += bytes;
    out.cameras.push_back(std::move(mounted));
  }
}

void mountImus(const std::vector<ImuEntry>& entries, const core::ArticulationModel& model, double dt, bool markup,
               std::vector<RobotImu>& out) {
  for (const ImuEntry& e : entries) {
    checkTopic(e.topic, e.key);
    RobotImu mounted{e, -1};
    ImuEntry& m = mounted.entry;
    if (markup) {  // Gazebo samples at most once a step
      m.settings.rate = std::min(m.settings.rate, 1.0 / dt);
      try {
        core::validateImu(m.settings, dt, e.key);
      } catch (const std::invalid_argument& err) {
        throw ConfigError(err.what());
      }
    }
    if (m.link.empty()) m.link = !m.frame_id.empty() && hasFrame(model, m.frame_id) ? m.frame_id : model.links[0].name;
    if (m.frame_id.empty()) m.frame_id = m.link;
    mount(model, m.link, e.settings.X_LS, e.key, mounted.link, m.settings.X_LS);
    out.push_back(std::move(mounted));
  }
}

/// The force-torque sensors of `entries` on the moving joints they name,
/// a rate capped at one a step; one on no moving joint into `notes`.
void mountForceTorques(const std::vector<ForceTorqueEntry>& entries, const core::ArticulationModel& model, double dt,
                       std::vector<RobotForceTorque>& out, std::vector<std::string>& notes) {
  for (const ForceTorqueEntry& e : entries) {
    checkTopic(e.topic, e.key);
    try {
      core::checkForceTorque(e.settings);
    } catch (const std::invalid_argument& err) {
      throw ConfigError(e.key + ": " + err.what());
    }
    RobotForceTorque mounted{e, -1};
    mounted.entry.rate = e.rate > 0.0 ? std::min(e.rate, 1.0 / dt) : 0.0;
    std::string joints;
    for (std::size_t i = 1; i < model.links.size(); ++i) {
      if (model.links[i].joint == e.joint) mounted.link = static_cast<int>(i);
      joints += (joints.empty() ? "'" : ", '") + model.links[i].joint + "'";
    }
    if (mounted.link < 0) {
      notes.push_back(e.key + " libgazebo_ros_ft_sensor.so: robot '" + model.name + "' has no moving joint '" +
                      e.joint +
                      "' (a fixed joint is lumped, as Gazebo lumps it, and the plugin does not load; its moving "
                      "joints: " +
                      joints + "): not run");
      continue;
    }
    out.push_back(std::move(mounted));
  }
}

/// The note for a device that casts `rays` rays `rate` times a second of
/// sim time, if that passes kRaysKeepingRealTime; "" otherwise.
std::string rayCostNote(const std::string& what, const std::string& key, double rays, double rate) {
  const double per_second = rays * rate;
  if (per_second <= kRaysKeepingRealTime) return "";
  std::ostringstream os;
  os.precision(3);
  os << what << " '" << key << "' casts " << per_second / 1e6
     << " M rays a second of sim time while it is subscribed; one core here casts about 9 M a second among 100 "
        "bodies and 50 M against one plane (bench/README.md, Range sensors): expect the node below real time "
        "while it is subscribed (fewer rays or a lower rate keep it)";
  return os.str();
}

}  // namespace

void DeviceMemory::take(std::uintmax_t bytes, const std::string& key) {
  if (bytes > budget || used > budget - bytes) {
    throw ConfigError("config key '" + key + "': the device would hold " + mib(bytes) +
                      ", and the devices may hold devices.memory = " + mib(budget) + " in all (" + mib(used) +
                      " of it counted before this one): give it fewer rays or pixels, or raise devices.memory");
  }
  used += bytes;
}

RobotSensors mountSensors(const RobotDevices& config, const RobotDevices& markup, const core::ArticulationModel& model,
                          double dt, DeviceMemory& memory) {
  RobotSensors out;
  const std::uintmax_t before = memory.used;
  try {
    for (const auto& [sensors, from_markup] : {std::pair{&config, false}, std::pair{&markup, true}}) {
      mountImus(sensors->imus, model, dt, from_markup, out.imus);
      mountLidars(sensors->lidars, model, memory, out);
      mountCameras(sensors->cameras, model, memory, out);
      mountOdometry(sensors->odometry, model, dt, from_markup, out.odometry);
      mountEarthSensors(sensors->gnss, model, dt, core::validateGnss, out.gnss);
      for (const GnssEntry& g : sensors->gnss) checkTopic(g.velocity_topic, g.key);
      mountEarthSensors(sensors->magnetometers, model, dt, core::validateMagnetometer, out.magnetometers);
      mountContactSensors(sensors->contact_sensors, model, dt, out.contact_sensors);
      mountForceTorques(sensors->force_torques, model, dt, out.force_torques, out.notes);
    }
    for (const RobotLidar& l : out.lidars) {
      const core::LidarSettings& s = l.entry.settings;
      out.notes.push_back(rayCostNote("lidar", l.entry.key, double(s.samples) * s.vertical_samples, l.entry.rate));
    }
    for (const RobotCamera& c : out.cameras) {
      const core::DepthCameraSettings& s = c.entry.settings;
      out.notes.push_back(rayCostNote("depth camera", c.entry.key, double(s.width) * s.height, c.entry.rate));
    }
    out.notes.erase(std::remove(out.notes.begin(), out.notes.end(), std::string()), out.notes.end());
  } catch (...) {
    memory.used = before;  // refused: none of this robot's devices is counted
    throw;
  }
  return out;
}

core::LinkSensors linkSensors(const RobotSensors& sensors, const core::ArticulationModel& model,
                              const core::ArticulationState& now, double dt, double odometry_rate) {
  core::LinkSensors out(dt);
  for (const RobotImu& m : sensors.imus) out.addImu(m.entry.settings, m.link, model, now);
  for (const RobotOdometry& o : sensors.odometry) {
    out.addOdometry(o.entry.noise, {o.link, o.X_LS}, o.entry.rate > 0.0 ? o.entry.rate : odometry_rate);
  }
  for (const RobotGnss& g : sensors.gnss) out.addGnss(g.entry.settings, {g.link, g.X_LS}, g.entry.rate);
  for (const RobotMagnetometer& m : sensors.magnetometers) {
    out.addMagnetometer(m.entry.settings, {m.link, m.X_LS}, m.entry.rate);
  }
  for (const RobotLidar& l : sensors.lidars) {
    std::optional<core::RangeFinderSettings> finder;
    if (l.entry.range) finder = l.entry.range->settings;
    out.addLidar(l.entry.settings, finder, {l.link, l.X_LS}, l.entry.rate);
  }
  for (const RobotCamera& c : sensors.cameras) out.addDepthCamera(c.entry.settings, {c.link, c.X_LS}, c.entry.rate);
  for (const RobotForceTorque& f : sensors.force_torques) out.addForceTorque(f.entry.settings, f.link, f.entry.rate);
  for (const RobotContactSensor& c : sensors.contact_sensors) {
    out.addContactSensor({c.link, c.X_LS}, c.entry.frame_id.empty(), c.entry.rate);
  }
  return out;
}

core::BodySensors bodySensors(const core::BodyModel& body, const std::optional<ImuEntry>& imu,
                              const std::optional<core::OdomNoiseSettings>& odom_noise, double dt) {
  core::BodySensors sensors(dt);
  if (imu) {
    const std::optional<core::Pose> X_LK = core::linkPose(body, imu->link);
    if (!X_LK) {
      std::string names = "'" + body.link + "'";
      for (const core::FixedLink& f : body.fixed_links) names += ", '" + f.name + "'";
      throw ConfigError("config key '" + imu->key + ".link' = '" + imu->link + "': no such link of body '" + body.name +
                        "' (its links: " + names + ")");
    }
    core::ImuSettings settings = imu->settings;
    settings.X_LS = *X_LK * imu->settings.X_LS;
    sensors.addImu(settings);
  }
  if (odom_noise) sensors.addOdometryNoise(*odom_noise);
  return sensors;
}

}  // namespace rigid_body_sim::io
