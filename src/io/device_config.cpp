#include "device_config.h"

#include "yaml_fields.h"

namespace rigid_body_sim::io {

using namespace yaml_fields;

ImuEntry parseImu(const YAML::Node& node, const std::string& path) {
  requireKnownKeys(node, path,
                   {"frame_id", "link", "pose", "rate", "seed", "gyro_noise", "accel_noise", "gyro_bias_walk",
                    "accel_bias_walk", "orientation_noise"});
  ImuEntry imu;
  core::ImuSettings& s = imu.settings;
  imu.key = path;
  if (node["frame_id"]) imu.frame_id = text(node["frame_id"], path + ".frame_id");
  if (node["link"]) imu.link = text(node["link"], path + ".link");
  if (node["pose"]) {
    const YAML::Node pose = node["pose"];
    requireKnownKeys(pose, path + ".pose", {"position", "rpy", "quaternion"});
    if (pose["position"]) s.X_LS.translation = vec3(pose["position"], path + ".pose.position");
    s.X_LS.rotation = orientation(pose, path + ".pose");
  }
  const auto read = [&](const char* key, double& field) {
    if (node[key]) field = number(node[key], path + "." + key);
  };
  read("rate", s.rate);
  read("gyro_noise", s.gyro_noise);
  read("accel_noise", s.accel_noise);
  read("gyro_bias_walk", s.gyro_bias_walk);
  read("accel_bias_walk", s.accel_bias_walk);
  read("orientation_noise", s.orientation_noise);
  if (node["seed"]) {
    const int seed = integer(node["seed"], path + ".seed");
    if (seed < 0) fail(path + ".seed", "expected an integer >= 0, got " + show(node["seed"]));
    s.seed = static_cast<std::uint64_t>(seed);
  }
  return imu;
}

core::OdomNoiseSettings parseOdomNoise(const YAML::Node& node, const std::string& path) {
  requireKnownKeys(node, path, {"position", "orientation", "linear_velocity", "angular_velocity", "drift", "seed"});
  core::OdomNoiseSettings s;
  const auto read = [](const YAML::Node& map, const std::string& at, const char* key, double& field) {
    if (map[key]) field = number(map[key], at + "." + key);
  };
  read(node, path, "position", s.position);
  read(node, path, "orientation", s.orientation);
  read(node, path, "linear_velocity", s.linear_velocity);
  read(node, path, "angular_velocity", s.angular_velocity);
  if (node["drift"]) {
    const YAML::Node drift = node["drift"];
    requireKnownKeys(drift, path + ".drift", {"x", "y", "yaw"});
    read(drift, path + ".drift", "x", s.drift_x);
    read(drift, path + ".drift", "y", s.drift_y);
    read(drift, path + ".drift", "yaw", s.drift_yaw);
  }
  if (node["seed"]) {
    const int seed = integer(node["seed"], path + ".seed");
    if (seed < 0) fail(path + ".seed", "expected an integer >= 0, got " + show(node["seed"]));
    s.seed = static_cast<std::uint64_t>(seed);
  }
  try {
    core::validateOdomNoise(s, path);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(std::string("config key ") + e.what());
  }
  return s;
}

core::DriverSettings parseDriver(const YAML::Node& node, const std::string& path) {
  requireKnownKeys(node, path,
                   {"max_force", "max_torque", "linear_gain", "linear_integral_gain", "angular_gain",
                    "angular_integral_gain", "max_linear_speed", "max_angular_speed", "timeout", "planar"});
  core::DriverSettings s;
  const auto read = [&](const char* key, double& field) {
    if (node[key]) field = number(node[key], path + "." + key);
  };
  read("max_force", s.max_force);
  read("max_torque", s.max_torque);
  read("linear_gain", s.linear_gain);
  read("linear_integral_gain", s.linear_integral_gain);
  read("angular_gain", s.angular_gain);
  read("angular_integral_gain", s.angular_integral_gain);
  read("max_linear_speed", s.max_linear_speed);
  read("max_angular_speed", s.max_angular_speed);
  read("timeout", s.timeout);
  if (node["planar"]) s.planar = boolean(node["planar"], path + ".planar");
  try {
    core::validateDriver(s, path);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(std::string("config key ") + e.what());
  }
  return s;
}

void validateImuEntry(const ImuEntry& imu, double dt, const std::string& path) {
  try {
    core::validateImu(imu.settings, dt, path);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(std::string("config key ") + e.what());
  }
}

}  // namespace rigid_body_sim::io
