// A robot's controllers from the config: controllers.h.
#include "rigid_body_sim/io/controllers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "controller_config.h"
#include "drive_config.h"
#include "steering_geometry.h"

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
  std::vector<std::string> out{kJointState, kDiffDriveType, kMecanumType, kAckermannType};
  for (const TypeInfo& t : kTypes) out.emplace_back(t.name);
  return out;
}

namespace {

/// The wheel radius ros_controllers reads: the first collision of `link`, a cylinder's or a sphere's.
double urdfWheelRadius(const core::ArticulatedLink& link, const std::string& key) {
  if (!link.collision.empty()) {
    const core::CollisionShape& shape = link.collision.front();
    if (shape.kind == core::CollisionShape::Kind::kCylinder || shape.kind == core::CollisionShape::Kind::kSphere) {
      return shape.radius;
    }
  }
  refuse(key, "is not given, and link '" + link.name +
                  "''s first collision is no cylinder or sphere to read it from (as ros_controllers reads it): "
                  "give wheel_radius (m)");
}

void finishDrive(const ControllerEntry& e, const core::ArticulationModel& model, core::DiffDriveSpec spec,
                 RobotControls& out);

/// A DiffDriveController of `model` (or a MecanumDriveController, an AckermannSteeringController), into `out`.
void addDrive(const ControllerEntry& e, const core::ArticulationModel& model, RobotControls& out) {
  const DiffDriveEntry& d = *e.drive;
  core::DiffDriveSpec spec;
  spec.name = e.name;
  spec.settings = d.settings;
  const bool steered = !d.steers.empty();
  // A steered base's keys: the AckermannSteeringController's, or the tricycle plugin's.
  const char* driven_key = !steered ? "left_wheel" : d.speed_at_steered_wheel ? "actuatedWheelJoint" : "rear_wheel";
  const char* steers_key = d.speed_at_steered_wheel ? "steeringJoint" : "front_steer";
  detail::SteeredJoints steering;
  for (const auto& [names, joints, side] :
       {std::tuple{&d.left, &spec.left, driven_key}, std::tuple{&d.right, &spec.right, "right_wheel"},
        std::tuple{&d.steers, &steering.steers, steers_key},
        std::tuple{&d.fixed_axle, &steering.fixed_axle, "encoderWheelLeftJoint, encoderWheelRightJoint"}}) {
    for (std::size_t k = 0; k < names->size(); ++k) {
      const std::string key = e.key + "." + side + (names->size() > 1 ? "[" + std::to_string(k) + "]" : "");
      joints->push_back(jointIndex(model, (*names)[k], key));
    }
  }
  const core::ArticulatedLink& left = model.links[spec.left.front()];
  spec.wheel_radius = d.wheel_radius ? *d.wheel_radius : urdfWheelRadius(left, e.key + ".wheel_radius");
  if (steered) {
    steering.driven = spec.left;
    steering.driven_key = e.key + "." + driven_key;
    steering.steers_key = e.key + "." + steers_key;
    spec.steering = detail::steeringOf(model, steering, d.wheel_separation.value_or(0.0));
    spec.steering->wheelbase *= d.settings.wheel_separation_multiplier;
    spec.steering->speed_at_steered_wheel = d.speed_at_steered_wheel;
    spec.steering->steering_speed = d.steering_speed;
    spec.wheel_separation = spec.steering->wheelbase;
    spec.settings.wheel_separation_multiplier = 1.0;
    return finishDrive(e, model, std::move(spec), out);
  }
  const core::ArticulatedLink& right = model.links[spec.right.front()];
  spec.mecanum = d.mecanum;
  // As ros_controllers: the first wheels' joint origins apart (in their
  // parents' frames); a mecanum base's, as mecanum_drive_controller: each
  // wheel's |x| + |y|, their mean twice.
  double spans = 0.0;
  for (const std::vector<int>* side : {&spec.left, &spec.right}) {
    for (const int j : *side) {
      const core::Vec3& o = model.links[j].X_PJ.translation;
      spans += 0.5 * (std::abs(o.x()) + std::abs(o.y()));
    }
  }
  const double urdf_separation = d.mecanum ? spans : (left.X_PJ.translation - right.X_PJ.translation).norm();
  spec.wheel_separation = d.wheel_separation.value_or(urdf_separation);
  if (!(spec.wheel_separation > 0.0)) {
    refuse(e.key + ".wheel_separation", "is not given, and the wheels' joints '" + left.joint + "' and '" +
                                            right.joint + "' are at one place: give wheel_separation (m)");
  }
  finishDrive(e, model, std::move(spec), out);
}

/// A drive's wheel gains (gazebo_ros_control's pid_gains where given, the
/// default for the rest), then the drive itself, into `out`.
void finishDrive(const ControllerEntry& e, const core::ArticulationModel& model, core::DiffDriveSpec spec,
                 RobotControls& out) {
  const DiffDriveEntry& d = *e.drive;
  const bool any_gains = std::any_of(e.gains.begin(), e.gains.end(), [](const auto& g) { return g.has_value(); });
  if (any_gains) {  // pid_gains for some wheels: the others get the default
    const std::vector<int> wheels = [&] {
      std::vector<int> all = spec.left;
      all.insert(all.end(), spec.right.begin(), spec.right.end());
      return all;
    }();
    for (std::size_t w = 0; w < wheels.size(); ++w) {
      const double radius = spec.wheel_radius * (w < spec.left.size() ? d.settings.left_wheel_radius_multiplier
                                                                      : d.settings.right_wheel_radius_multiplier);
      spec.gains.push_back(
          e.gains[w].value_or(core::defaultWheelGains(model, wheels[w], radius, static_cast<int>(wheels.size()))));
    }
  }
  try {
    out.drives.emplace_back(model, std::move(spec));
  } catch (const std::invalid_argument& err) {
    refuse(e.key, err.what());
  }
  out.drive_topics.push_back(d.topics);
}

/// One controller of `entries` for `model`, into `out` and `specs`; each
/// refusal a ConfigError naming its key.
void addController(const ControllerEntry& e, const core::ArticulationModel& model, RobotControls& out,
                   std::vector<core::JointControllerSpec>& specs) {
  if (e.drive) return addDrive(e, model, out);
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

/// One line naming every key of `entries` not read here, grouped by why; none if there are none.
std::vector<std::string> unreadNote(const std::vector<ControllerEntry>& entries) {
  std::vector<std::pair<std::string, std::string>> by_why;  // why, its keys
  std::size_t count = 0;
  for (const ControllerEntry& e : entries) {
    for (const UnreadKey& u : e.unread) {
      auto group = std::find_if(by_why.begin(), by_why.end(), [&](const auto& g) { return g.first == u.why; });
      if (group == by_why.end()) group = by_why.insert(by_why.end(), {u.why, ""});
      group->second += (group->second.empty() ? "" : ", ") + u.key;
      ++count;
    }
  }
  if (count == 0) return {};
  std::string line = std::to_string(count) + " controller key" + (count == 1 ? "" : "s") +
                     " not read here (as ROS lets a parameter nobody reads be): ";
  for (std::size_t g = 0; g < by_why.size(); ++g) {
    line += (g == 0 ? "" : "; ") + by_why[g].second + " (" + by_why[g].first + ")";
  }
  return {line};
}

/// The first controller of `running` that has one of `e`'s joints, or null.
const ControllerEntry* ownerOfAJoint(const ControllerEntry& e, const std::vector<const ControllerEntry*>& running) {
  for (const ControllerEntry* r : running) {
    for (const std::string& joint : e.joints) {
      if (std::find(r->joints.begin(), r->joints.end(), joint) != r->joints.end()) return r;
    }
  }
  return nullptr;
}

/// The line saying that `stopped` (each with the controller that has its joints) do not run.
std::string stoppedNote(const std::vector<std::pair<const ControllerEntry*, const ControllerEntry*>>& stopped) {
  std::string names;
  for (const auto& [e, owner] : stopped) {
    names += (names.empty() ? "" : ", ") + ("'" + e->name + "' (a joint of '" + owner->name + "')");
  }
  return std::to_string(stopped.size()) + " controller" + (stopped.size() == 1 ? "" : "s") +
         " loaded stopped, as controller_manager's spawner leaves a controller whose joints another has: " + names +
         "; the first in the file runs";
}

}  // namespace

RobotControls buildControls(const std::vector<ControllerEntry>& entries, const core::ArticulationModel& model) {
  RobotControls out;
  std::vector<core::JointControllerSpec> specs;
  std::vector<std::string> problems;  // every controller's, said at once
  // A joint is one running controller's. A config's later controller on it
  // is loaded stopped (checked, then left out); a plugin of the URDF's
  // markup always runs, so one on a controller's joint is refused.
  std::vector<const ControllerEntry*> running;
  std::vector<std::pair<const ControllerEntry*, const ControllerEntry*>> stopped;
  for (const ControllerEntry& e : entries) {
    const ControllerEntry* owner = ownerOfAJoint(e, running);
    try {
      if (owner != nullptr && e.key.rfind("<gazebo>", 0) == 0) {
        refuse(e.key, "its joints are already controller '" + owner->name + "''s");
      }
      if (owner == nullptr) {
        addController(e, model, out, specs);
        running.push_back(&e);
        continue;
      }
      RobotControls unused;
      std::vector<core::JointControllerSpec> unused_specs;
      addController(e, model, unused, unused_specs);
      stopped.emplace_back(&e, owner);
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
  out.notes = unreadNote(entries);
  if (!stopped.empty()) out.notes.push_back(stoppedNote(stopped));
  return out;
}

RobotControls controlsOf(const YAML::Node& node, const std::string& path, const core::ArticulationModel& model,
                         bool in_namespace, const std::vector<ControllerEntry>& markup) {
  const auto with_markup = [&markup](std::vector<ControllerEntry> entries) {
    entries.insert(entries.end(), markup.begin(), markup.end());
    return entries;
  };
  if (!in_namespace) return buildControls(with_markup(parseControllers(node, path)), model);
  if (!node.IsMap()) throw ConfigError("'" + path + "': expected a namespace (a map of parameters)");
  YAML::Node controllers(YAML::NodeType::Map);
  for (const auto& item : node) {
    if (item.second.IsMap() && item.second["type"]) controllers[item.first] = item.second;
  }
  std::vector<ControllerEntry> entries = parseControllers(controllers, path);
  if (const YAML::Node gazebo = node["gazebo_ros_control"]) {
    applyPidGains(gazebo, path + ".gazebo_ros_control", entries);
  }
  if (const YAML::Node steer_bot = node["steer_bot_hardware_gazebo"]) {
    applySteerBot(steer_bot, path + ".steer_bot_hardware_gazebo", entries);
  }
  return buildControls(with_markup(std::move(entries)), model);
}

void addBaseDrive(const std::optional<core::DriverSettings>& cmd_vel, const std::optional<BaseDriveEntry>& markup,
                  const core::ArticulationModel& model, const std::string& key, RobotControls& controls) {
  if (!cmd_vel && !markup) return;
  const std::string where = cmd_vel ? "config key '" + key + "cmd_vel'" : markup->key;
  if (model.fixed_base) {
    throw ConfigError(where + ": robot '" + model.name +
                      "' is fixed to the world (its root link is 'world'): no base to drive");
  }
  if (cmd_vel && markup) {
    throw ConfigError(where + ": robot '" + model.name + "''s markup drives its base already (" + markup->key +
                      "): give one of the two");
  }
  if (cmd_vel) {
    controls.base_driver.emplace(*cmd_vel);
    controls.base_driver_topic = "cmd_vel";
    return;
  }
  core::DriverSettings s = markup->settings;
  const core::SpatialInertia all = core::robotInertia_B(model, core::kinematics(model, core::restState(model)));
  const core::Vec3 c = all.h / all.mass;
  const double yaw_inertia = all.I_O(2, 2) - all.mass * (c.x() * c.x() + c.y() * c.y());
  constexpr double kMostAcceleration = 2.0 * 9.81, kMostYawAcceleration = 40.0;  // m/s², rad/s²
  s.max_force = std::clamp(kMostAcceleration * all.mass, 1e-6, 1e6);
  s.max_torque = std::clamp(kMostYawAcceleration * yaw_inertia, 1e-6, 1e6);
  if (markup->force_gain > 0.0) s.linear_gain = std::min(markup->force_gain / all.mass, 1e4);
  if (markup->torque_gain > 0.0 && yaw_inertia > 0.0) s.angular_gain = std::min(markup->torque_gain / yaw_inertia, 1e4);
  try {
    core::validateDriver(s, markup->key);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(e.what());
  }
  controls.base_driver.emplace(s);
  controls.base_driver_topic = markup->topic;
}

}  // namespace rigid_body_sim::io
