// A robot's `controllers` map: controller_config.h.
#include "controller_config.h"

#include <algorithm>
#include <set>
#include <utility>

#include "drive_config.h"
#include "yaml_fields.h"

namespace rigid_body_sim::io {

using namespace yaml_fields;

namespace {

/// control_toolbox's gains at `path`: p, i, d, i_clamp (each ≥ 0; p must be
/// given, as control_toolbox's Pid refuses gains without it; the others are
/// 0 if not given).
core::PidGains parseGains(const YAML::Node& node, const std::string& path) {
  if (!node.IsMap()) fail(path, "expected a map {p, i, d, i_clamp}");
  requireKnownKeys(node, path, {"p", "i", "d", "i_clamp"});
  if (!node["p"]) fail(join(path, "p"), "is missing: control_toolbox's Pid needs p (i, d and i_clamp default to 0)");
  core::PidGains g;
  for (const auto& [key, field] :
       {std::pair<const char*, double*>{"p", &g.p}, {"i", &g.i}, {"d", &g.d}, {"i_clamp", &g.i_clamp}}) {
    if (!node[key]) continue;
    *field = number(node[key], join(path, key));
    if (*field < 0.0) fail(join(path, key), "must be >= 0");
  }
  return g;
}

/// One controller of the map at `path`: `name` → `body`.
ControllerEntry parseController(const YAML::Node& name, const YAML::Node& body, const std::string& path) {
  ControllerEntry c;
  c.name = text(name, path);
  c.key = join(path, c.name);
  if (!body.IsMap()) fail(c.key, "expected a map {type, joint or joints, pid or gains}");
  const std::string type = body["type"] && body["type"].IsScalar() ? body["type"].Scalar() : "";
  if (type == kDiffDriveType || type == kMecanumType || type == kAckermannType) {
    c.type = type;
    c.drive = type == kMecanumType     ? parseMecanumDrive(body, c.key)
              : type == kAckermannType ? parseAckermannDrive(body, c.key)
                                       : parseDiffDrive(body, c.key);
    c.joints = c.drive->left;  // left then right: where gazebo_ros_control's pid_gains find them
    c.joints.insert(c.joints.end(), c.drive->right.begin(), c.drive->right.end());
    c.joints.insert(c.joints.end(), c.drive->steers.begin(), c.drive->steers.end());  // no controller's but this one
    c.joint_list = true;
    c.gains.assign(c.joints.size(), std::nullopt);
    c.unread = std::move(c.drive->unread);
    return c;
  }
  if (!body["type"]) fail(join(c.key, "type"), "every controller needs a type (as ros_controllers names it)");
  c.type = text(body["type"], join(c.key, "type"));
  // A JointTrajectoryController's keys for its action and state topics
  // (control_msgs, not in Debian 12), and velocity feed-forward.
  const std::set<std::string> trajectory = {"constraints",
                                            "state_publish_rate",
                                            "action_monitor_rate",
                                            "stop_trajectory_duration",
                                            "allow_partial_joints_goal",
                                            "velocity_ff"};
  const bool runs_trajectories = c.type.find("/JointTrajectoryController") != std::string::npos;
  for (const std::string& key : trajectory) {
    if (runs_trajectories && body[key]) {
      c.unread.push_back({join(c.key, key),
                          "the trajectory controller runs its command topic only: control_msgs' action and state "
                          "are not in Debian 12, and velocity feed-forward is not run"});
    }
  }
  std::set<std::string> known = {"type", "joint", "joints", "pid", "gains", "publish_rate"};
  if (runs_trajectories) known.insert(trajectory.begin(), trajectory.end());
  for (const std::string& k : keysNotRead(body, c.key, known)) {
    c.unread.push_back({k, "no ros_controllers controller of type " + c.type + " reads it"});
  }
  if (body["joint"] && body["joints"]) fail(c.key, "give joint (one) or joints (a group), not both");
  if (body["joint"]) c.joints = {text(body["joint"], join(c.key, "joint"))};
  if (body["joints"]) {
    c.joint_list = true;
    const YAML::Node& list = body["joints"];
    if (!list.IsSequence()) fail(join(c.key, "joints"), "expected a list of joint names");
    for (std::size_t k = 0; k < list.size(); ++k) {
      c.joints.push_back(text(list[k], join(c.key, "joints") + "[" + std::to_string(k) + "]"));
    }
  }
  c.gains.assign(c.joints.size(), std::nullopt);
  if (body["pid"]) {
    if (c.joints.size() != 1)
      fail(join(c.key, "pid"), "is for a one-joint controller; a group takes gains: {JOINT: {p, i, d}}");
    c.gains[0] = parseGains(body["pid"], join(c.key, "pid"));
  }
  if (body["gains"]) {
    const YAML::Node& gains = body["gains"];
    if (!gains.IsMap()) fail(join(c.key, "gains"), "expected a map from joint name to {p, i, d, i_clamp}");
    for (const auto& g : gains) {
      const std::string joint = text(g.first, join(c.key, "gains"));
      std::size_t k = 0;
      while (k < c.joints.size() && c.joints[k] != joint) ++k;
      if (k == c.joints.size()) fail(join(join(c.key, "gains"), joint), "is not one of the controller's joints");
      c.gains[k] = parseGains(g.second, join(join(c.key, "gains"), joint));
    }
  }
  if (body["publish_rate"]) c.publish_rate = publishRate(body["publish_rate"], join(c.key, "publish_rate"));
  return c;
}

}  // namespace

std::vector<ControllerEntry> parseControllers(const YAML::Node& node, const std::string& path) {
  if (!node.IsMap()) fail(path, "expected a map from controller name to {type, joint or joints, pid or gains}");
  std::vector<ControllerEntry> out;
  std::vector<std::string> problems;  // every controller's, said at once
  for (const auto& item : node) {
    try {
      out.push_back(parseController(item.first, item.second, path));
    } catch (const ConfigError& e) {
      problems.emplace_back(e.what());
    }
  }
  throwProblems(problems);
  return out;
}

void throwProblems(const std::vector<std::string>& problems) {
  if (problems.empty()) return;
  if (problems.size() == 1) throw ConfigError(problems.front());
  std::string all = std::to_string(problems.size()) + " problems: ";
  for (std::size_t i = 0; i < problems.size(); ++i) all += (i == 0 ? "" : "; ") + problems[i];
  throw ConfigError(all);
}

void applyPidGains(const YAML::Node& node, const std::string& path, std::vector<ControllerEntry>& entries) {
  if (!node.IsMap()) fail(path, "expected a map {pid_gains: {JOINT: {p, i, d, i_clamp}}}");
  requireKnownKeys(node, path, {"pid_gains"});
  const std::string gains_path = join(path, "pid_gains");
  const YAML::Node& gains = node["pid_gains"];
  if (!gains) return;
  if (!gains.IsMap()) fail(gains_path, "expected a map from joint name to {p, i, d, i_clamp}");
  for (const auto& g : gains) {
    const std::string joint = text(g.first, gains_path), key = join(gains_path, joint);
    ControllerEntry* owner = nullptr;
    std::size_t k = 0;
    for (ControllerEntry& e : entries) {
      for (std::size_t j = 0; j < e.joints.size(); ++j) {
        if (e.joints[j] == joint) {
          owner = &e;
          k = j;
        }
      }
    }
    if (owner == nullptr) fail(key, "no controller in `controllers` names joint '" + joint + "'");
    if (owner->type.rfind("position_controllers/", 0) != 0 && owner->type.rfind("velocity_controllers/", 0) != 0 &&
        !owner->drive) {
      fail(key, "joint '" + joint + "' is controller '" + owner->name + "''s, a " + owner->type +
                    ": it takes its own gains (gazebo_ros_control's pid_gains are for position_controllers, "
                    "velocity_controllers and a DiffDriveController's wheels)");
    }
    if (owner->gains[k]) fail(key, "joint '" + joint + "' has gains already, in " + owner->key);
    owner->gains[k] = parseGains(g.second, key);
  }
}

void applySteerBot(const YAML::Node& node, const std::string& path, std::vector<ControllerEntry>& entries) {
  if (!node.IsMap()) fail(path, "expected a map {rear_wheel, front_steer, virtual_rear_wheels, ...}");
  requireKnownKeys(node, path,
                   {"rear_wheel", "front_steer", "virtual_rear_wheels", "virtual_front_wheels", "virtual_front_steers",
                    "enable_ackermann_link", "wheel_separation_h", "wheel_separation_w"});
  const auto names = [&](const char* key) {
    std::vector<std::string> out;
    const YAML::Node& list = node[key];
    if (!list) return out;
    if (!list.IsSequence()) fail(join(path, key), "expected a list of joint names");
    for (std::size_t k = 0; k < list.size(); ++k)
      out.push_back(text(list[k], join(path, key) + "[" + std::to_string(k) + "]"));
    return out;
  };
  const std::string rear = node["rear_wheel"] ? text(node["rear_wheel"], join(path, "rear_wheel")) : "rear_wheel_joint";
  const std::string steer =
      node["front_steer"] ? text(node["front_steer"], join(path, "front_steer")) : "front_steer_joint";
  std::vector<std::string> wheels = names("virtual_rear_wheels");
  const std::vector<std::string> front = names("virtual_front_wheels");
  wheels.insert(wheels.end(), front.begin(), front.end());
  const std::vector<std::string> steers = names("virtual_front_steers");
  if (wheels.empty()) fail(join(path, "virtual_rear_wheels"), "is missing: the wheels that drive the car");
  if (steers.empty()) fail(join(path, "virtual_front_steers"), "is missing: the knuckles that steer the car");
  const auto match = std::find_if(entries.begin(), entries.end(), [&](const ControllerEntry& e) {
    return e.type == kAckermannType && e.drive && e.drive->left == std::vector<std::string>{rear} &&
           e.drive->steers == std::vector<std::string>{steer};
  });
  if (match == entries.end()) {
    fail(path, "no " + std::string(kAckermannType) + " has rear_wheel '" + rear + "' and front_steer '" + steer + "'");
  }
  DiffDriveEntry& d = *match->drive;
  d.left = wheels;
  d.steers = steers;
  if (!d.wheel_separation && node["wheel_separation_h"]) {
    d.wheel_separation = positiveNumber(node["wheel_separation_h"], join(path, "wheel_separation_h"));
  }
  if (node["wheel_separation_w"]) {
    positiveNumber(node["wheel_separation_w"], join(path, "wheel_separation_w"));
    match->unread.push_back({join(path, "wheel_separation_w"), "the track is the URDF's knuckles' here"});
  }
  if (node["enable_ackermann_link"] && !boolean(node["enable_ackermann_link"], join(path, "enable_ackermann_link"))) {
    match->unread.push_back({join(path, "enable_ackermann_link"), "false, a parallel linkage: Ackermann's is run"});
  }
  match->joints = wheels;
  match->joints.insert(match->joints.end(), steers.begin(), steers.end());
  match->gains.assign(match->joints.size(), std::nullopt);
}

}  // namespace rigid_body_sim::io
