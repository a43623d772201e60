// A config's pieces given as text (config.h): a request's YAML map for one
// device or driver, a YAML file or text read whole, and the command line's
// KEY=VALUE overrides.
#include <sstream>
#include <string>
#include <vector>

#include "device_config.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/input_bounds.h"
#include "yaml_fields.h"
#include "yaml_split_load.h"

namespace rigid_body_sim::io {

using namespace yaml_fields;

namespace {

/// `parse` of the YAML text `yaml` (a map given in a request), any YAML
/// error a ConfigError naming `path`.
template <class Parse>
auto fromText(const std::string& yaml, const std::string& path, const Parse& parse) {
  try {
    return parse(loadYamlText(yaml, path));
  } catch (const YAML::Exception& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

}  // namespace

ImuEntry parseImuText(const std::string& yaml, const std::string& path, double dt) {
  return fromText(yaml, path, [&](const YAML::Node& node) {
    ImuEntry imu = parseImu(node, path);
    validateImuEntry(imu, dt, path);
    return imu;
  });
}

core::OdomNoiseSettings parseOdomNoiseText(const std::string& yaml, const std::string& path) {
  return fromText(yaml, path, [&](const YAML::Node& node) { return parseOdomNoise(node, path); });
}

core::DriverSettings parseDriverText(const std::string& yaml, const std::string& path) {
  return fromText(yaml, path, [&](const YAML::Node& node) { return parseDriver(node, path); });
}

YAML::Node loadYamlFile(const std::string& path) {
  return loadYamlText(readInput<ConfigError>(path, InputCaps::kConfigBytes, "config"), "config '" + path + "'");
}

YAML::Node loadYamlText(const std::string& text, const std::string& source) {
  const std::string problem = yamlProblem(text);
  if (!problem.empty()) throw ConfigError(source + ": " + problem);
  try {
    return loadSplittingSequence(text, "", {}).root;
  } catch (const YAML::Exception& e) {
    throw ConfigError(source + " is not valid YAML: " + e.what());
  }
}

void applyOverride(YAML::Node& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw ConfigError("--set '" + assignment + "': expected KEY=VALUE, e.g. gravity=[0,0,0]");
  }
  const std::string key = assignment.substr(0, eq);
  const YAML::Node value = loadYamlText(assignment.substr(eq + 1), "--set '" + assignment + "': the value");
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) {
    if (part.empty()) throw ConfigError("--set '" + assignment + "': empty key component");
    parts.push_back(part);
  }
  if (!root || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  // yaml-cpp nodes are references: walk with reset(), never with '='.
  YAML::Node node;
  node.reset(root);
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (!node.IsMap()) fail(key, "cannot set '" + parts[i] + "' inside a value that is not a map");
    YAML::Node child = node[parts[i]];
    if (!child.IsDefined() || child.IsNull()) child = YAML::Node(YAML::NodeType::Map);
    node.reset(child);
  }
  if (!node.IsMap()) fail(key, "cannot set '" + parts.back() + "' inside a value that is not a map");
  node[parts.back()] = value;
}

}  // namespace rigid_body_sim::io
