#include "device_config.h"

#include <initializer_list>
#include <string>
#include <utility>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "yaml_fields.h"

namespace rigid_body_sim::io {
namespace {

using namespace yaml_fields;

/// Each key of `fields` that `node` has, into its number (path.key in errors).
void readNumbers(const YAML::Node& node, const std::string& path,
                 std::initializer_list<std::pair<const char*, double*>> fields) {
  for (const auto& [key, field] : fields) {
    if (node[key]) *field = number(node[key], path + "." + key);
  }
}

/// `path`.seed: an integer ≥ 0.
void readSeed(const YAML::Node& node, const std::string& path, std::uint64_t& seed) {
  if (!node["seed"]) return;
  const int value = integer(node["seed"], path + ".seed");
  if (value < 0) fail(path + ".seed", "expected an integer >= 0, got " + show(node["seed"]));
  seed = static_cast<std::uint64_t>(value);
}

/// The core's check `check`, its std::invalid_argument as a ConfigError.
template <class Check>
void checked(const Check& check) {
  try {
    check();
  } catch (const std::invalid_argument& e) {
    throw ConfigError(std::string("config key ") + e.what());
  }
}

}  // namespace

ImuEntry parseImu(const YAML::Node& node, const std::string& path) {
  requireKnownKeys(node, path,
                   {"frame_id", "link", "topic", "pose", "rate", "seed", "gyro_noise", "accel_noise", "gyro_bias_walk",
                    "accel_bias_walk", "orientation_noise"});
  ImuEntry imu;
  core::ImuSettings& s = imu.settings;
  imu.key = path;
  if (node["frame_id"]) imu.frame_id = frameId(node["frame_id"], path + ".frame_id");
  if (node["link"]) imu.link = text(node["link"], path + ".link");
  if (node["topic"]) imu.topic = text(node["topic"], path + ".topic");
  if (node["pose"]) {
    const YAML::Node pose = node["pose"];
    requireKnownKeys(pose, path + ".pose", {"position", "rpy", "quaternion"});
    if (pose["position"]) s.X_LS.translation = vec3(pose["position"], path + ".pose.position");
    s.X_LS.rotation = orientation(pose, path + ".pose");
  }
  readNumbers(node, path,
              {{"rate", &s.rate},
               {"gyro_noise", &s.gyro_noise},
               {"accel_noise", &s.accel_noise},
               {"gyro_bias_walk", &s.gyro_bias_walk},
               {"accel_bias_walk", &s.accel_bias_walk},
               {"orientation_noise", &s.orientation_noise}});
  readSeed(node, path, s.seed);
  return imu;
}

namespace {

/// `pose` ({position, rpy | quaternion}) at `path`.
core::Pose parsePose(const YAML::Node& pose, const std::string& path) {
  requireKnownKeys(pose, path, {"position", "rpy", "quaternion"});
  core::Pose X;
  if (pose["position"]) X.translation = vec3(pose["position"], path + ".position");
  X.rotation = orientation(pose, path);
  return X;
}

/// `rate` within the publish rates.
void checkRate(double rate, const std::string& key) {
  if (!(rate >= core::ranges::kMinRate && rate <= core::ranges::kMaxPublishRate)) {
    fail(key, "must be within [" + std::to_string(core::ranges::kMinRate) + ", " +
                  std::to_string(core::ranges::kMaxPublishRate) + "] Hz");
  }
}

DepthCameraEntry parseDepthCamera(const YAML::Node& node, const std::string& path) {
  if (!node.IsMap()) fail(path, "expected a map {link, topic, rate, width, height, hfov, ...}");
  requireKnownKeys(node, path,
                   {"link", "frame_id", "pose", "topic", "rate", "width", "height", "hfov", "min_depth", "max_depth",
                    "noise", "seed", "encoding"});
  DepthCameraEntry c;
  c.key = path;
  if (!node["link"]) fail(path + ".link", "is missing: the robot's link the camera looks from");
  c.link = text(node["link"], path + ".link");
  if (node["topic"]) c.topic = text(node["topic"], path + ".topic");
  if (node["frame_id"]) c.frame_id = frameId(node["frame_id"], path + ".frame_id");
  if (node["pose"]) c.pose = parsePose(node["pose"], path + ".pose");
  if (node["encoding"]) {
    const std::string e = text(node["encoding"], path + ".encoding");
    if (e != "32FC1" && e != "16UC1") fail(path + ".encoding", "'" + e + "': 32FC1 (m) or 16UC1 (mm)");
    c.millimetres = e == "16UC1";
  }
  core::DepthCameraSettings& s = c.settings;
  readNumbers(node, path,
              {{"rate", &c.rate},
               {"hfov", &s.hfov},
               {"min_depth", &s.min_depth},
               {"max_depth", &s.max_depth},
               {"noise", &s.noise}});
  if (node["width"]) s.width = integer(node["width"], path + ".width");
  if (node["height"]) s.height = integer(node["height"], path + ".height");
  readSeed(node, path, s.seed);
  checkRate(c.rate, path + ".rate");
  checked([&] {
    try {
      core::checkDepthCamera(s);
    } catch (const std::invalid_argument& e) {  // "depth camera: FIELD ...": named under the entry's key
      throw std::invalid_argument("'" + path + "': " + std::string(e.what()).substr(14));
    }
  });
  return c;
}

LidarEntry parseLidar(const YAML::Node& node, const std::string& path) {
  if (!node.IsMap()) fail(path, "expected a map {link, topic, rate, samples, min_angle, max_angle, ...}");
  requireKnownKeys(
      node, path,
      {"link", "frame_id", "pose", "topic", "rate", "samples", "min_angle", "max_angle", "vertical_samples",
       "vertical_min_angle", "vertical_max_angle", "min_range", "max_range", "noise", "seed"});
  LidarEntry l;
  l.key = path;
  if (!node["link"]) fail(path + ".link", "is missing: the robot's link the lidar scans from");
  l.link = text(node["link"], path + ".link");
  if (node["topic"]) l.topic = text(node["topic"], path + ".topic");
  if (node["frame_id"]) l.frame_id = frameId(node["frame_id"], path + ".frame_id");
  if (node["pose"]) l.pose = parsePose(node["pose"], path + ".pose");
  core::LidarSettings& s = l.settings;
  readNumbers(node, path,
              {{"rate", &l.rate},
               {"min_angle", &s.min_angle},
               {"max_angle", &s.max_angle},
               {"vertical_min_angle", &s.vertical_min_angle},
               {"vertical_max_angle", &s.vertical_max_angle},
               {"min_range", &s.min_range},
               {"max_range", &s.max_range},
               {"noise", &s.noise}});
  if (node["samples"]) s.samples = integer(node["samples"], path + ".samples");
  if (node["vertical_samples"]) s.vertical_samples = integer(node["vertical_samples"], path + ".vertical_samples");
  readSeed(node, path, s.seed);
  checkRate(l.rate, path + ".rate");
  checked([&] {
    try {
      core::checkLidar(s);
    } catch (const std::invalid_argument& e) {  // "lidar: FIELD ...": named under the entry's key
      throw std::invalid_argument("'" + path + "': " + std::string(e.what()).substr(7));
    }
  });
  return l;
}

}  // namespace

std::vector<LidarEntry> parseLidars(const YAML::Node& node, const std::string& path) {
  if (!node.IsSequence()) return {parseLidar(node, path)};
  std::vector<LidarEntry> out;
  for (std::size_t k = 0; k < node.size(); ++k)
    out.push_back(parseLidar(node[k], path + "[" + std::to_string(k) + "]"));
  return out;
}

std::vector<DepthCameraEntry> parseDepthCameras(const YAML::Node& node, const std::string& path) {
  if (!node.IsSequence()) return {parseDepthCamera(node, path)};
  std::vector<DepthCameraEntry> out;
  for (std::size_t k = 0; k < node.size(); ++k) {
    out.push_back(parseDepthCamera(node[k], path + "[" + std::to_string(k) + "]"));
  }
  return out;
}

core::OdomNoiseSettings parseOdomNoise(const YAML::Node& node, const std::string& path) {
  requireKnownKeys(node, path, {"position", "orientation", "linear_velocity", "angular_velocity", "drift", "seed"});
  core::OdomNoiseSettings s;
  readNumbers(node, path,
              {{"position", &s.position},
               {"orientation", &s.orientation},
               {"linear_velocity", &s.linear_velocity},
               {"angular_velocity", &s.angular_velocity}});
  if (node["drift"]) {
    requireKnownKeys(node["drift"], path + ".drift", {"x", "y", "yaw"});
    readNumbers(node["drift"], path + ".drift", {{"x", &s.drift_x}, {"y", &s.drift_y}, {"yaw", &s.drift_yaw}});
  }
  readSeed(node, path, s.seed);
  checked([&] { core::validateOdomNoise(s, path); });
  return s;
}

core::DriverSettings parseDriver(const YAML::Node& node, const std::string& path) {
  requireKnownKeys(node, path,
                   {"max_force", "max_torque", "linear_gain", "linear_integral_gain", "angular_gain",
                    "angular_integral_gain", "max_linear_speed", "max_angular_speed", "timeout", "planar"});
  core::DriverSettings s;
  readNumbers(node, path,
              {{"max_force", &s.max_force},
               {"max_torque", &s.max_torque},
               {"linear_gain", &s.linear_gain},
               {"linear_integral_gain", &s.linear_integral_gain},
               {"angular_gain", &s.angular_gain},
               {"angular_integral_gain", &s.angular_integral_gain},
               {"max_linear_speed", &s.max_linear_speed},
               {"max_angular_speed", &s.max_angular_speed},
               {"timeout", &s.timeout}});
  if (node["planar"]) s.planar = boolean(node["planar"], path + ".planar");
  checked([&] { core::validateDriver(s, path); });
  return s;
}

void validateImuEntry(const ImuEntry& imu, double dt, const std::string& path) {
  checked([&] { core::validateImu(imu.settings, dt, path); });
}

}  // namespace rigid_body_sim::io
