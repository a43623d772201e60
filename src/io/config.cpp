#include "rigid_body_sim/io/config.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <set>
#include <sstream>
#include <unordered_set>
#include <vector>

#include "controller_config.h"
#include "device_config.h"
#include "rigid_body_sim/core/bodies/setting_keys.h"
#include "rigid_body_sim/io/input_bounds.h"
#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/node_keys.h"
#include "rigid_body_sim/io/orientation.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "scene_config.h"
#include "setting_config.h"
#include "yaml_fields.h"
#include "yaml_split_load.h"

namespace rigid_body_sim::io {
namespace {

using core::Quat;
using core::Vec3;
using namespace yaml_fields;

constexpr int kMaxDeviceMemoryMiB = 1 << 20;  ///< devices.memory's largest: 1 TiB

/// A map from joint name to a number, in the file's order; names unique.
void jointValues(const YAML::Node& node, const std::string& key, std::vector<std::pair<std::string, double>>& out) {
  if (!node.IsMap()) fail(key, "expected a map from joint name to a number, got " + show(node));
  for (const auto& item : node) {
    const std::string name = item.first.IsScalar() ? item.first.Scalar() : "";
    if (name.empty()) fail(key, "a joint name must be a non-empty string, got " + show(item.first));
    const std::string at = join(key, name);
    for (const auto& [seen, unused] : out) {
      if (seen == name) fail(at, "joint '" + name + "' is given twice");
    }
    out.emplace_back(name, number(item.second, at));
  }
}

void parseInitial(const YAML::Node& node, core::LinkState& s, InitialJoints& joints,
                  const std::string& path = "initial") {
  requireKnownKeys(
      node, path,
      {"position", "rpy", "quaternion", "linear_velocity", "angular_velocity", "joint_positions", "joint_velocities"});
  if (node["joint_positions"]) jointValues(node["joint_positions"], path + ".joint_positions", joints.positions);
  if (node["joint_velocities"]) jointValues(node["joint_velocities"], path + ".joint_velocities", joints.velocities);
  if (node["position"]) s.p_WL = vec3(node["position"], path + ".position");
  s.q_WL = orientation(node, path);
  if (node["linear_velocity"]) s.v_WL = vec3(node["linear_velocity"], path + ".linear_velocity");
  if (node["angular_velocity"]) s.w_W = vec3(node["angular_velocity"], path + ".angular_velocity");
}

/// The `bodies` list, an entry at a time (a world config streams it in:
/// loadConfigFile). Names must be unique.
class BodyList {
 public:
  explicit BodyList(std::string base_dir) : base_dir_(std::move(base_dir)) {}

  void add(const YAML::Node& entry, std::size_t i) {
    const std::string path = "bodies[" + std::to_string(i) + "]";
    requireKnownKeys(entry, path,
                     {"name", "urdf", "initial", "contact", "imu", "odom_noise", "cmd_vel", "controllers",
                      "gazebo_ros_control", "steer_bot_hardware_gazebo", "lidar", "depth_camera"});
    if (!entry["name"]) fail(path + ".name", "every body needs a name");
    if (!entry["urdf"]) fail(path + ".urdf", "every body needs a urdf (a file, or for the node a parameter)");
    BodyEntry b;
    b.name = text(entry["name"], path + ".name");
    const std::string bad_name = bodyNameProblem(b.name);
    if (!bad_name.empty()) fail(path + ".name", bad_name);
    if (!names_.insert(b.name).second) {
      fail(path + ".name", "'" + b.name + "' is already the name of another body");
    }
    b.urdf = text(entry["urdf"], path + ".urdf");
    const bool relative =
        b.urdf.front() != '/' && b.urdf.rfind("package://", 0) != 0 && b.urdf.rfind("file://", 0) != 0;
    if (relative && !base_dir_.empty()) b.urdf = base_dir_ + "/" + b.urdf;
    if (entry["initial"]) parseInitial(entry["initial"], b.initial, b.initial_joints, path + ".initial");
    if (entry["contact"]) {  // the body's own surface
      const YAML::Node surface = entry["contact"];
      requireKnownKeys(surface, path + ".contact", {"friction", "restitution"});
      if (surface["friction"]) b.friction = number(surface["friction"], path + ".contact.friction");
      if (surface["restitution"]) b.restitution = number(surface["restitution"], path + ".contact.restitution");
    }
    if (entry["imu"]) b.imu = parseImu(entry["imu"], path + ".imu");
    if (entry["odom_noise"]) b.odom_noise = parseOdomNoise(entry["odom_noise"], path + ".odom_noise");
    if (entry["cmd_vel"]) b.cmd_vel = parseDriver(entry["cmd_vel"], path + ".cmd_vel");
    if (entry["controllers"]) b.controllers = parseControllers(entry["controllers"], path + ".controllers");
    if (entry["lidar"]) b.lidars = parseLidars(entry["lidar"], path + ".lidar");
    if (entry["depth_camera"]) b.cameras = parseDepthCameras(entry["depth_camera"], path + ".depth_camera");
    if (entry["gazebo_ros_control"]) {
      applyPidGains(entry["gazebo_ros_control"], path + ".gazebo_ros_control", b.controllers);
    }
    if (entry["steer_bot_hardware_gazebo"]) {
      applySteerBot(entry["steer_bot_hardware_gazebo"], path + ".steer_bot_hardware_gazebo", b.controllers);
    }
    bodies_.push_back(std::move(b));
  }

  std::vector<BodyEntry> take() {
    bodies_.shrink_to_fit();
    return std::move(bodies_);
  }

 private:
  std::string base_dir_;
  std::vector<BodyEntry> bodies_;
  std::unordered_set<std::string> names_;
};

std::vector<BodyEntry> parseBodies(const YAML::Node& node, const std::string& base_dir) {
  if (!node.IsSequence()) fail("bodies", "expected a list of {name, urdf, initial} ([] for an empty world)");
  BodyList list(base_dir);
  for (std::size_t i = 0; i < node.size(); ++i) list.add(node[i], i);
  return list.take();
}

/// The bodies list parsed as the text was read, or the first refusal of an
/// entry (thrown where parsing the tree would have thrown it).
struct StreamedBodies {
  std::vector<BodyEntry> bodies;
  std::exception_ptr refused;
};

/// `streamed`: the bodies list read from the text, when `root` holds only
/// an empty stand-in for it.
SimConfig parseTree(const YAML::Node& root, const std::string& base_dir, StreamedBodies* streamed = nullptr) {
  SimConfig c;
  c.base_dir = base_dir;
  c.model.scene = {core::Sdf::plane(Vec3::UnitZ())};  // the ground, z = 0
  if (!root || root.IsNull()) return c;
  requireKnownKeys(root, "",
                   {"dt",
                    "gravity",
                    "gyroscopic",
                    "articulation_integrator",
                    "damping",
                    "initial",
                    "scene",
                    "contact",
                    "sleep",
                    "solver",
                    "limits",
                    "bodies",
                    "imu",
                    "odom_noise",
                    "cmd_vel",
                    "controllers",
                    "gazebo_ros_control",
                    "steer_bot_hardware_gazebo",
                    "urdf",
                    "devices",
                    "lidar",
                    "depth_camera",
                    "timeline"});
  parseSection(root, "", c.model);  // dt, gravity, gyroscopic, articulation_integrator
  if (root["timeline"]) c.timeline = parseTimeline(root["timeline"]);
  if (const YAML::Node urdf = root["urdf"]) {
    requireKnownKeys(urdf, "urdf", {"repair"});
    if (urdf["repair"]) c.urdf_repair = boolean(urdf["repair"], "urdf.repair");
  }
  if (const YAML::Node devices = root["devices"]) {
    requireKnownKeys(devices, "devices", {"memory"});
    if (devices["memory"]) {
      const int mib = integer(devices["memory"], "devices.memory");
      if (mib < 1 || mib > kMaxDeviceMemoryMiB) {
        fail("devices.memory",
             "must be within [1, " + std::to_string(kMaxDeviceMemoryMiB) + "] MiB, got " + show(devices["memory"]));
      }
      c.device_memory = static_cast<std::uintmax_t>(mib) << 20;
    }
  }
  parseSection(root, "damping", c.model);
  if (root["initial"]) parseInitial(root["initial"], c.initial, c.initial_joints);
  if (root["scene"]) c.model.scene = parseScene(root["scene"], base_dir);
  for (const char* section : {"contact", "sleep", "solver", "limits"}) parseSection(root, section, c.model);
  if (root["bodies"]) {
    if (root["initial"]) fail("initial", "with a bodies list, give each body its own bodies[i].initial");
    if (streamed && streamed->refused) std::rethrow_exception(streamed->refused);
    c.bodies = streamed ? std::move(streamed->bodies) : parseBodies(root["bodies"], base_dir);
    c.bodies_listed = true;
  }
  // A one-body or one-robot config's devices and controllers (a bodies list gives each entry its own).
  const auto single = [&root](const char* key, const char* whose, auto& into, const auto& parse) {
    if (!root[key]) return;
    if (root["bodies"]) fail(key, std::string("with a bodies list, give each ") + whose + " its own bodies[i]." + key);
    into = parse(root[key], key);
  };
  single("imu", "body", c.imu, parseImu);
  single("odom_noise", "body", c.odom_noise, parseOdomNoise);
  single("cmd_vel", "body", c.cmd_vel, parseDriver);
  single("controllers", "robot", c.controllers, parseControllers);
  single("lidar", "robot", c.lidars, parseLidars);
  single("depth_camera", "robot", c.cameras, parseDepthCameras);
  if (root["gazebo_ros_control"]) {
    if (root["bodies"]) {
      fail("gazebo_ros_control", "with a bodies list, give each robot its own bodies[i].gazebo_ros_control");
    }
    applyPidGains(root["gazebo_ros_control"], "gazebo_ros_control", c.controllers);
  }
  if (root["steer_bot_hardware_gazebo"]) {
    if (root["bodies"]) {
      fail("steer_bot_hardware_gazebo",
           "with a bodies list, give each robot its own bodies[i].steer_bot_hardware_gazebo");
    }
    applySteerBot(root["steer_bot_hardware_gazebo"], "steer_bot_hardware_gazebo", c.controllers);
  }
  // Sensors sample at most once a step: checked against the dt just read.
  if (c.imu) validateImuEntry(*c.imu, c.model.dt, "imu");
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    if (c.bodies[i].imu) validateImuEntry(*c.bodies[i].imu, c.model.dt, "bodies[" + std::to_string(i) + "].imu");
  }
  return c;
}

}  // namespace

SimConfig parseConfig(const YAML::Node& root, const std::string& base_dir) {
  try {
    return parseTree(root, base_dir);
  } catch (const YAML::Exception& e) {  // a conversion no check above foresaw: still a ConfigError
    throw ConfigError(std::string("config: ") + e.what());
  }
}

SimConfig parseConfigWithBodies(const YAML::Node& root, std::size_t count,
                                const std::function<YAML::Node(std::size_t)>& entry, const std::string& base_dir) {
  if (root["bodies"]) fail("bodies", "given twice: in the tree and apart");
  BodyList bodies(base_dir);
  StreamedBodies streamed;
  for (std::size_t i = 0; i < count && !streamed.refused; ++i) {
    try {
      bodies.add(entry(i), i);
    } catch (...) {  // refused after the keys parseTree checks first, as for the tree
      streamed.refused = std::current_exception();
    }
  }
  streamed.bodies = bodies.take();
  YAML::Node tree = YAML::Clone(root);
  tree["bodies"] = YAML::Node(YAML::NodeType::Sequence);  // the stand-in: the list is streamed
  try {
    return parseTree(tree, base_dir, &streamed);
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string("config: ") + e.what());
  }
}

std::string shownName(const std::string& text) {
  std::string out = text.substr(0, kMaxShownLength);
  for (char& c : out) {
    if (c < 0x20 || c > 0x7e) c = '?';
  }
  if (text.size() > kMaxShownLength) out += "... (" + std::to_string(text.size()) + " characters)";
  return out;
}

std::string frameIdProblem(const std::string& frame) {
  if (frame.empty()) return "is empty: a tf frame id names a frame";
  const bool ok = std::all_of(frame.begin(), frame.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.' || c == '/';
  });
  if (!ok || frame.size() > kMaxShownLength) {
    return "'" + shownName(frame) + "' is no tf frame id: letters, digits, '_', '-', '.' and '/', at most " +
           std::to_string(kMaxShownLength);
  }
  if (frame.front() == '/')
    return "'" + frame + "' starts with '/', which tf2 refuses in a frame id: write '" + frame.substr(1) + "'";
  return {};
}

std::string bodyNameProblem(const std::string& name) {
  if (name.empty()) return "name is empty: give the body a name";
  const bool letters = std::all_of(name.begin(), name.end(),
                                   [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; });
  if (!letters || std::isalpha(static_cast<unsigned char>(name.front())) == 0 || name.size() > kMaxBodyNameLength) {
    return "name '" + shownName(name) +
           "': a body's name starts with a letter and holds only letters, digits and '_', at most " +
           std::to_string(kMaxBodyNameLength) + " (it names topics and tf frames)";
  }
  return {};
}

SimConfig parseConfigText(const std::string& yaml, const std::string& source, const std::vector<std::string>& overrides,
                          const std::string& base_dir, std::vector<std::string>* node_keys) {
  const std::string problem = yamlProblem(yaml);
  if (!problem.empty()) throw ConfigError(source + ": " + problem);
  BodyList bodies(base_dir);
  StreamedBodies streamed;
  SplitLoad load = [&] {
    try {
      return loadSplittingSequence(yaml, "bodies", [&](const YAML::Node& entry, std::size_t i) {
        if (streamed.refused) return;
        try {
          bodies.add(entry, i);
        } catch (...) {  // refused after the keys parseTree checks first, as for the tree
          streamed.refused = std::current_exception();
        }
      });
    } catch (const YAML::Exception& e) {
      throw ConfigError(source + " is not valid YAML: " + e.what());
    }
  }();
  bool replaced = false;  // an override gives the bodies list itself
  for (const std::string& s : overrides) {
    applyOverride(load.root, s);
    replaced = replaced || s.compare(0, s.find_first_of(".="), "bodies") == 0;
  }
  streamed.bodies = bodies.take();
  std::optional<double> publish_rate;  // the one node key the simulation's devices read
  if (node_keys != nullptr && load.root.IsMap()) {
    const YAML::Node& root = load.root;  // const: a look-up that adds nothing
    if (root["publish_rate"]) publish_rate = publishRate(root["publish_rate"], "publish_rate");
    for (const std::string& key : nodeKeys()) {
      if (!root[key]) continue;
      node_keys->push_back(key);
      load.root.remove(key);
    }
  }
  try {
    SimConfig config = parseTree(load.root, base_dir, load.split && !replaced ? &streamed : nullptr);
    if (publish_rate) config.publish_rate = *publish_rate;
    return config;
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string("config: ") + e.what());
  }
}

SimConfig loadConfigFile(const std::string& path, const std::vector<std::string>& overrides,
                         const std::string& base_dir, std::vector<std::string>* node_keys) {
  return parseConfigText(readInput<ConfigError>(path, InputCaps::kConfigBytes, "config"), "config '" + path + "'",
                         overrides, base_dir, node_keys);
}

}  // namespace rigid_body_sim::io
