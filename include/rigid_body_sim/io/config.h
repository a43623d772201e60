// Simulation settings from YAML (yaml-cpp): the keys of config/default.yaml.
// rbsim reads them from a file; the ROS node reads the same keys from its
// private parameters through the same parser. ROS-free.
#pragma once

#include <yaml-cpp/yaml.h>

#include <stdexcept>
#include <string>

#include "rigid_body_sim/core/model.h"
#include "rigid_body_sim/core/state.h"

namespace rigid_body_sim::io {

/// A config that cannot be used. The message names the key and the value.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SimConfig {
  /// dt, gravity, damping, gyroscopic, scene, contact, sleep (bodies come from URDF).
  core::ModelSpec model;
  /// Initial pose and twist of the root link frame, world frame.
  core::LinkState initial;
};

/// Parses a config tree. Missing keys keep the defaults documented in
/// config/default.yaml; unknown keys and bad values throw ConfigError.
SimConfig parseConfig(const YAML::Node& root);

/// Reads a YAML file (ConfigError if unreadable or not YAML).
YAML::Node loadYamlFile(const std::string& path);

/// Applies "a.b.c=VALUE" to the tree: VALUE is parsed as YAML
/// ("gravity=[0,0,0]", "gyroscopic=false"); missing maps are created.
void applyOverride(YAML::Node& root, const std::string& assignment);

/// Builds the model of one body with the config's settings (std::invalid_argument
/// from the model's validation names the field).
core::Model buildModel(const SimConfig& config, const core::BodySpec& body);

}  // namespace rigid_body_sim::io
