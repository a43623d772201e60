// A robot's controllers from the config: controllers.h.
#include "rigid_body_sim/io/controllers.h"

#include <stdexcept>

#include "controller_config.h"

namespace rigid_body_sim::io {
namespace {

struct TypeInfo {
  const char* name;
  core::ControlMode mode;
  bool group;
};

constexpr TypeInfo kTypes[] = {
    {"effort_controllers/JointEffortController", core::ControlMode::kEffort, false},
    {"effort_controllers/JointPositionController", core::ControlMode::kPosition, false},
    {"effort_controllers/JointVelocityController", core::ControlMode::kVelocity, false},
    {"effort_controllers/JointGroupEffortController", core::ControlMode::kEffort, true},
    {"effort_controllers/JointGroupPositionController", core::ControlMode::kPosition, true},
    {"velocity_controllers/JointVelocityController", core::ControlMode::kVelocity, false},
    {"velocity_controllers/JointGroupVelocityController", core::ControlMode::kVelocity, true},
    {"position_controllers/JointPositionController", core::ControlMode::kPosition, false},
    {"position_controllers/JointGroupPositionController", core::ControlMode::kPosition, true},
    // Every trajectory controller tracks its setpoints through effort (never by setting the joint).
    {"effort_controllers/JointTrajectoryController", core::ControlMode::kTrajectory, true},
    {"position_controllers/JointTrajectoryController", core::ControlMode::kTrajectory, true},
    {"velocity_controllers/JointTrajectoryController", core::ControlMode::kTrajectory, true},
};
constexpr const char* kJointState = "joint_state_controller/JointStateController";

[[noreturn]] void refuse(const std::string& key, const std::string& why) {
  throw ConfigError("config key '" + key + "': " + why);
}

/// The link index of the moving joint `name`, or refused naming `key`.
int jointIndex(const core::ArticulationModel& model, const std::string& name, const std::string& key) {
  std::string names;
  for (int j = 1; j <= model.jointCount(); ++j) {
    if (model.links[j].joint == name) return j;
    names += (names.empty() ? "'" : ", '") + model.links[j].joint + "'";
  }
  refuse(key, "robot '" + model.name + "' has no moving joint '" + name + "'" + core::heldJointNote(model, name) +
                  " (its joints: " + names + ")");
}

}  // namespace

std::vector<std::string> controllerTypes() {
  std::vector<std::string> out{kJointState};
  for (const TypeInfo& t : kTypes) out.emplace_back(t.name);
  return out;
}

namespace {

/// One controller of `entries` for `model`, into `out` and `specs`; each
/// refusal a ConfigError naming its key.
void addController(const ControllerEntry& e, const core::ArticulationModel& model, RobotControls& out,
                   std::vector<core::JointControllerSpec>& specs) {
  const std::string type_key = e.key + ".type";
  if (e.type == kJointState) {
    if (!e.joints.empty()) refuse(e.key, "a JointStateController takes no joints (it reports them all)");
    out.joint_state_rate = e.publish_rate.value_or(50.0);  // ros_controllers' examples' rate
    return;
  }
  const TypeInfo* info = nullptr;
  for (const TypeInfo& t : kTypes) {
    if (e.type == t.name) info = &t;
  }
  if (info == nullptr) {
    std::string known;
    for (const std::string& t : controllerTypes()) known += (known.empty() ? "" : ", ") + t;
    refuse(type_key, "'" + e.type + "' is not a controller type this project runs; the types: " + known);
  }
  if (e.publish_rate) refuse(e.key + ".publish_rate", "is a JointStateController's key");
  if (e.joints.empty() || info->group != e.joint_list) {
    refuse(e.key, "'" + e.type + "' takes " + (info->group ? "joints: [NAME, ...]" : "joint: NAME"));
  }
  core::JointControllerSpec spec;
  spec.name = e.name;
  spec.mode = info->mode;
  for (std::size_t k = 0; k < e.joints.size(); ++k) {
    const std::string key = e.key + (info->group ? ".joints[" + std::to_string(k) + "]" : ".joint");
    spec.joints.push_back(jointIndex(model, e.joints[k], key));
    if (info->mode == core::ControlMode::kEffort) continue;
    if (!e.gains[k]) {
      const bool interface_pid =
          e.type.rfind("position_controllers/", 0) == 0 || e.type.rfind("velocity_controllers/", 0) == 0;
      refuse(e.key + (info->group ? ".gains." + e.joints[k] : ".pid"),
             "'" + e.type + "' acts here through a PID on effort (never by setting the joint, as Gazebo's " +
                 "position interface does): give its gains {p, i, d, i_clamp}" +
                 (interface_pid ? " (here, or as gazebo_ros_control: {pid_gains: {" + e.joints[k] + ": ...}})" : ""));
    }
    spec.gains.push_back(*e.gains[k]);
  }
  specs.push_back(std::move(spec));
  out.group.push_back(info->group ? 1 : 0);
}

}  // namespace

RobotControls buildControls(const std::vector<ControllerEntry>& entries, const core::ArticulationModel& model) {
  RobotControls out;
  std::vector<core::JointControllerSpec> specs;
  std::vector<std::string> problems;  // every controller's, said at once
  for (const ControllerEntry& e : entries) {
    try {
      addController(e, model, out, specs);
    } catch (const ConfigError& error) {
      problems.emplace_back(error.what());
    }
  }
  throwProblems(problems);
  try {
    out.controllers = core::JointControllers(model, std::move(specs));
  } catch (const std::invalid_argument& err) {  // its message names the controller
    const ControllerEntry& e = entries.front();
    throw ConfigError("config key '" + e.key.substr(0, e.key.size() - e.name.size() - 1) + "': " + err.what());
  }
  return out;
}

RobotControls controlsOf(const YAML::Node& node, const std::string& path, const core::ArticulationModel& model,
                         bool in_namespace) {
  if (!in_namespace) return buildControls(parseControllers(node, path), model);
  if (!node.IsMap()) throw ConfigError("'" + path + "': expected a namespace (a map of parameters)");
  YAML::Node controllers(YAML::NodeType::Map);
  for (const auto& item : node) {
    if (item.second.IsMap() && item.second["type"]) controllers[item.first] = item.second;
  }
  std::vector<ControllerEntry> entries = parseControllers(controllers, path);
  if (const YAML::Node gazebo = node["gazebo_ros_control"]) {
    applyPidGains(gazebo, path + ".gazebo_ros_control", entries);
  }
  return buildControls(entries, model);
}

}  // namespace rigid_body_sim::io
