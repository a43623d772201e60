#include "rigid_body_sim/io/config.h"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace rigid_body_sim::io {
namespace {

using core::Quat;
using core::Vec3;

std::string show(const YAML::Node& node) {
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

[[noreturn]] void fail(const std::string& key, const std::string& why) {
  throw ConfigError("config key '" + key + "': " + why);
}

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

/// Refuses keys outside `known` (a typo must not silently fall back to a default).
void requireKnownKeys(const YAML::Node& map, const std::string& path, const std::set<std::string>& known) {
  if (!map.IsMap()) fail(path.empty() ? "<root>" : path, "expected a map, got " + show(map));
  for (const auto& kv : map) {
    const std::string key = kv.first.as<std::string>();
    if (!known.count(key)) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      fail(join(path, key), "unknown key (known here: " + list + ")");
    }
  }
}

double number(const YAML::Node& node, const std::string& key) {
  double x = 0.0;
  try {
    if (!node.IsScalar()) throw YAML::Exception(YAML::Mark(), "");
    x = node.as<double>();
  } catch (const YAML::Exception&) {
    fail(key, "expected a number, got " + show(node));
  }
  if (!std::isfinite(x)) fail(key, "expected a finite number, got " + show(node));
  return x;
}

Vec3 vec3(const YAML::Node& node, const std::string& key) {
  if (!node.IsSequence() || node.size() != 3) fail(key, "expected [x, y, z], got " + show(node));
  return {number(node[0], key + "[0]"), number(node[1], key + "[1]"), number(node[2], key + "[2]")};
}

bool boolean(const YAML::Node& node, const std::string& key) {
  try {
    if (node.IsScalar()) return node.as<bool>();
  } catch (const YAML::Exception&) {
  }
  fail(key, "expected true or false, got " + show(node));
}

/// URDF convention: fixed axes X (roll), Y (pitch), Z (yaw): R = Rz Ry Rx.
Quat fromRpy(const Vec3& rpy) {
  return Quat(Eigen::AngleAxisd(rpy.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Vec3::UnitY()) *
              Eigen::AngleAxisd(rpy.x(), Vec3::UnitX()));
}

void parseDamping(const YAML::Node& node, core::Damping& d) {
  requireKnownKeys(node, "damping", {"linear", "angular", "linear_drag", "angular_drag"});
  if (node["linear"]) d.linear_rate = number(node["linear"], "damping.linear");
  if (node["angular"]) d.angular_rate = number(node["angular"], "damping.angular");
  if (node["linear_drag"]) d.linear_drag = number(node["linear_drag"], "damping.linear_drag");
  if (node["angular_drag"]) d.angular_drag = number(node["angular_drag"], "damping.angular_drag");
}

void parseInitial(const YAML::Node& node, core::LinkState& s) {
  requireKnownKeys(node, "initial", {"position", "rpy", "quaternion", "linear_velocity", "angular_velocity"});
  if (node["position"]) s.p_WL = vec3(node["position"], "initial.position");
  if (node["rpy"] && node["quaternion"]) fail("initial", "give initial.rpy or initial.quaternion, not both");
  if (node["rpy"]) s.q_WL = fromRpy(vec3(node["rpy"], "initial.rpy"));
  if (node["quaternion"]) {
    const YAML::Node q = node["quaternion"];
    const std::string key = "initial.quaternion";
    if (!q.IsSequence() || q.size() != 4) fail(key, "expected [x, y, z, w], got " + show(q));
    // geometry_msgs order (x, y, z, w); Eigen's constructor takes (w, x, y, z).
    const Quat value(number(q[3], key + "[3]"), number(q[0], key + "[0]"), number(q[1], key + "[1]"),
                     number(q[2], key + "[2]"));
    if (std::abs(value.norm() - 1.0) > 1e-3) {
      std::ostringstream os;
      os << value.norm();
      fail(key, "norm " + os.str() + " is not 1 (within 1e-3): " + show(q));
    }
    s.q_WL = value.normalized();
  }
  if (node["linear_velocity"]) s.v_WL = vec3(node["linear_velocity"], "initial.linear_velocity");
  if (node["angular_velocity"]) s.w_W = vec3(node["angular_velocity"], "initial.angular_velocity");
}

}  // namespace

SimConfig parseConfig(const YAML::Node& root) {
  SimConfig c;
  if (!root || root.IsNull()) return c;
  requireKnownKeys(root, "", {"dt", "gravity", "gyroscopic", "damping", "initial"});
  if (root["dt"]) c.model.dt = number(root["dt"], "dt");
  if (root["gravity"]) c.model.gravity_W = vec3(root["gravity"], "gravity");
  if (root["gyroscopic"]) c.model.gyroscopic = boolean(root["gyroscopic"], "gyroscopic");
  if (root["damping"]) parseDamping(root["damping"], c.model.damping);
  if (root["initial"]) parseInitial(root["initial"], c.initial);
  return c;
}

YAML::Node loadYamlFile(const std::string& path) {
  std::ifstream probe(path);
  if (!probe) throw ConfigError("cannot read config '" + path + "'");
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ConfigError("config '" + path + "' is not valid YAML: " + e.what());
  }
}

void applyOverride(YAML::Node& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw ConfigError("--set '" + assignment + "': expected KEY=VALUE, e.g. gravity=[0,0,0]");
  }
  const std::string key = assignment.substr(0, eq);
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(eq + 1));
  } catch (const YAML::Exception& e) {
    throw ConfigError("--set '" + assignment + "': the value is not YAML: " + e.what());
  }
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

core::Model buildModel(const SimConfig& config, const core::BodySpec& body) {
  core::ModelSpec spec = config.model;
  spec.bodies = {body};
  return core::Model(spec);
}

}  // namespace rigid_body_sim::io
