// A config's timeline: timeline.h.
#include "rigid_body_sim/io/timeline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/io/controllers.h"
#include "yaml_fields.h"

namespace rigid_body_sim::io {

using namespace yaml_fields;

namespace {

/// `joint_effort: {joint_name, effort, duration}` of entry `entry` into `c`,
/// as apply_joint_effort checks its request.
void parseJointEffort(const YAML::Node& effort, const std::string& key, const YAML::Node& entry, TimedCommand& c) {
  const std::string at = key + ".joint_effort";
  if (!effort.IsMap())
    fail(at, "expected a map such as {joint_name: J, effort: 1.0, duration: 0.5}, got " + show(effort));
  requireKnownKeys(effort, at, {"joint_name", "effort", "duration"});
  if (entry["until"]) fail(key + ".until", "a joint effort lasts its joint_effort.duration: give that instead");
  if (entry["controller"]) fail(key + ".controller", "a joint effort acts on its joint_name, beside any controller");
  for (const char* field : {"joint_name", "effort", "duration"}) {
    if (!effort[field]) fail(at + "." + field, "every joint effort needs it");
  }
  c.joint_effort = true;
  c.joint = text(effort["joint_name"], at + ".joint_name");
  c.effort = number(effort["effort"], at + ".effort");
  if (std::abs(c.effort) > core::ranges::kMaxCommandEffort) {
    fail(at + ".effort", "must be within 1e6 N*m or N, got " + show(effort["effort"]));
  }
  c.duration = number(effort["duration"], at + ".duration");
  if (c.duration == 0.0 || std::abs(c.duration) > core::ranges::kMaxDuration) {
    fail(at + ".duration",
         "must be > 0 (for that long) or < 0 (to the end), within 1e6 s, got " + show(effort["duration"]));
  }
}

/// A list of numbers at `key`.
std::vector<double> numbers(const YAML::Node& list, const std::string& key) {
  if (!list.IsSequence()) fail(key, "expected a list of numbers, got " + show(list));
  std::vector<double> out;
  for (std::size_t k = 0; k < list.size(); ++k) out.push_back(number(list[k], key + "[" + std::to_string(k) + "]"));
  return out;
}

/// `trajectory: {joint_names, points}` of entry `entry` into `c`, as a
/// trajectory_msgs/JointTrajectory (a time_from_start in s, or {secs, nsecs}).
void parseTrajectory(const YAML::Node& trajectory, const std::string& key, const YAML::Node& entry, TimedCommand& c) {
  const std::string at = key + ".trajectory";
  if (!trajectory.IsMap()) {
    fail(at, "expected a map such as {joint_names: [a], points: [{positions: [1], time_from_start: 2}]}, got " +
                 show(trajectory));
  }
  requireKnownKeys(trajectory, at, {"joint_names", "points"});
  if (entry["until"]) fail(key + ".until", "a trajectory runs by its points' times: give it once");
  if (!entry["controller"]) fail(key + ".controller", "a trajectory is for a trajectory controller: name it");
  const YAML::Node names = trajectory["joint_names"], points = trajectory["points"];
  if (!names || !names.IsSequence()) fail(at + ".joint_names", "expected the list of the controller's joints");
  for (std::size_t k = 0; k < names.size(); ++k) {
    c.joint_names.push_back(text(names[k], at + ".joint_names[" + std::to_string(k) + "]"));
  }
  if (!points || !points.IsSequence() || points.size() == 0) {
    fail(at + ".points", "expected a list of one or more waypoints");
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string p = at + ".points[" + std::to_string(i) + "]";
    const YAML::Node point = points[i];
    if (!point.IsMap()) fail(p, "expected a map such as {positions: [1], time_from_start: 2}, got " + show(point));
    requireKnownKeys(point, p, {"positions", "velocities", "accelerations", "effort", "time_from_start"});
    if (point["effort"]) fail(p + ".effort", "an effort trajectory controller takes no efforts; leave it out");
    if (!point["positions"]) fail(p + ".positions", "every waypoint needs its positions");
    if (!point["time_from_start"]) fail(p + ".time_from_start", "every waypoint needs its time (s)");
    core::TrajectoryPoint w;
    w.position = numbers(point["positions"], p + ".positions");
    if (point["velocities"]) w.velocity = numbers(point["velocities"], p + ".velocities");
    if (point["accelerations"]) w.acceleration = numbers(point["accelerations"], p + ".accelerations");
    const YAML::Node time = point["time_from_start"];
    if (time.IsMap()) {
      requireKnownKeys(time, p + ".time_from_start", {"secs", "nsecs"});
      w.time = (time["secs"] ? integer(time["secs"], p + ".time_from_start.secs") : 0) +
               1e-9 * (time["nsecs"] ? integer(time["nsecs"], p + ".time_from_start.nsecs") : 0);
    } else {
      w.time = number(time, p + ".time_from_start");
    }
    if (w.time < 0.0 || w.time > core::ranges::kMaxDuration) {
      fail(p + ".time_from_start", "must be within [0, 1e6] s, got " + show(time));
    }
    c.points.push_back(std::move(w));
  }
  c.trajectory = true;
}

TimedCommand parseEntry(const YAML::Node& node, const std::string& key) {
  if (!node.IsMap()) fail(key, "expected a map such as {t: 1.0, cmd_vel: {linear: [0.5, 0, 0]}}, got " + show(node));
  requireKnownKeys(node, key,
                   {"t", "until", "robot", "body", "controller", "cmd_vel", "command", "trajectory", "joint_effort"});
  TimedCommand c;
  c.key = key;
  if (!node["t"]) fail(key + ".t", "every entry needs its time (s of sim time)");
  c.t = number(node["t"], key + ".t");
  if (c.t < 0.0 || c.t > core::ranges::kMaxDuration) {
    fail(key + ".t", "must be within [0, 1e6] s, got " + show(node["t"]));
  }
  c.until = c.t;
  if (node["until"]) {
    c.until = number(node["until"], key + ".until");
    if (c.until <= c.t || c.until > core::ranges::kMaxDuration) {
      fail(key + ".until", "must be after t and at most 1e6 s, got " + show(node["until"]));
    }
  }
  if (node["robot"]) c.robot = text(node["robot"], key + ".robot");
  if (node["controller"]) c.controller = text(node["controller"], key + ".controller");
  if (node["body"]) {
    c.body = text(node["body"], key + ".body");
    if (!node["cmd_vel"]) fail(key + ".body", "a body takes a cmd_vel (its velocity driver's), nothing else");
    if (node["robot"]) fail(key + ".robot", "an entry is for a body or a robot: not both");
    if (node["controller"]) fail(key + ".controller", "a body has one velocity driver: name no controller");
  }
  const int kinds = static_cast<int>(static_cast<bool>(node["cmd_vel"])) +
                    static_cast<int>(static_cast<bool>(node["command"])) +
                    static_cast<int>(static_cast<bool>(node["trajectory"])) +
                    static_cast<int>(static_cast<bool>(node["joint_effort"]));
  if (kinds != 1) {
    fail(key,
         "needs one of cmd_vel (a twist), command (a controller's values), trajectory (a trajectory controller's "
         "waypoints) and joint_effort (an effort on a joint)");
  }
  if (const YAML::Node effort = node["joint_effort"]) {
    parseJointEffort(effort, key, node, c);
  } else if (const YAML::Node trajectory = node["trajectory"]) {
    parseTrajectory(trajectory, key, node, c);
  } else if (const YAML::Node twist = node["cmd_vel"]) {
    requireKnownKeys(twist, key + ".cmd_vel", {"linear", "angular"});
    c.cmd_vel = true;
    if (twist["linear"]) c.linear = vec3(twist["linear"], key + ".cmd_vel.linear");
    if (twist["angular"]) c.angular = vec3(twist["angular"], key + ".cmd_vel.angular");
  } else {
    c.values = numbers(node["command"], key + ".command");
    if (c.values.empty()) fail(key + ".command", "expected a list of numbers, got none");
  }
  return c;
}

}  // namespace

std::vector<TimedCommand> parseTimeline(const YAML::Node& list) {
  if (!list.IsSequence()) fail("timeline", "expected a list of commands, got " + show(list));
  std::vector<TimedCommand> out;
  for (std::size_t i = 0; i < list.size(); ++i)
    out.push_back(parseEntry(list[i], "timeline[" + std::to_string(i) + "]"));
  return out;
}

namespace {

/// The names of the joints of `spec`, a controller of `robot`, in its order.
std::vector<std::string> jointNames(const core::SceneRobot& robot, const core::JointControllerSpec& spec) {
  std::vector<std::string> names;
  for (const int j : spec.joints) names.push_back(robot.model.links[static_cast<std::size_t>(j)].joint);
  return names;
}

/// A trajectory entry's points in the order of the joints of `spec`, a
/// controller of `robot`; ConfigError naming the entry's field if its
/// joint names or points do not fit it.
std::vector<core::TrajectoryPoint> orderedPoints(const TimedCommand& c, const core::SceneRobot& robot,
                                                 const core::JointControllerSpec& spec) {
  std::vector<core::TrajectoryPoint> points = c.points;
  const std::string problem = core::orderTrajectory(jointNames(robot, spec), c.joint_names, points);
  if (!problem.empty()) fail(c.key + ".trajectory", "'" + c.controller + "': " + problem);
  const std::string bad = core::JointTrajectory::check(points, spec.joints.size());
  if (!bad.empty()) fail(c.key + ".trajectory", "'" + c.controller + "': " + bad);
  return points;
}

/// What `c` drives of robot `robot`'s controls: a drive's or a joint
/// controller's index, −1 for the base driver; ConfigError naming the
/// entry's field otherwise.
int targetOf(const TimedCommand& c, const core::SceneRobot& robot, const RobotControls& rc) {
  const std::string who = "robot '" + robot.name + "'";
  const std::vector<core::JointControllerSpec>& specs = rc.controllers.specs();
  int joint_controller = -1;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    if (specs[k].name == c.controller) joint_controller = static_cast<int>(k);
  }
  if (c.cmd_vel) {
    if (c.controller.empty()) {
      if (rc.base_driver) return -1;
      if (rc.drives.size() == 1) return 0;
      fail(c.key + ".controller", who + " has " + std::to_string(rc.drives.size()) +
                                      " wheeled-base controllers and no base driver: name the one it is for");
    }
    for (std::size_t d = 0; d < rc.drives.size(); ++d) {
      if (rc.drives[d].spec().name == c.controller) return static_cast<int>(d);
    }
    fail(c.key + ".controller", joint_controller >= 0
                                    ? "'" + c.controller + "' is a joint controller: give it a command, not a cmd_vel"
                                    : who + " has no wheeled-base controller '" + c.controller + "'");
  }
  if (joint_controller < 0) fail(c.key + ".controller", who + " has no joint controller '" + c.controller + "'");
  const core::JointControllerSpec& spec = specs[static_cast<std::size_t>(joint_controller)];
  const bool follows = spec.mode == core::ControlMode::kTrajectory;
  if (follows != c.trajectory) {
    fail(c.trajectory ? c.key + ".trajectory" : c.key + ".command",
         "'" + c.controller +
             (follows ? "' follows trajectories: give it a trajectory, not a command"
                      : "' follows no trajectory: give it a command"));
  }
  if (c.trajectory) {
    orderedPoints(c, robot, spec);
    return joint_controller;
  }
  if (c.values.size() != spec.joints.size()) {
    fail(c.key + ".command", "'" + c.controller + "' takes " + std::to_string(spec.joints.size()) +
                                 " values (one per joint), got " + std::to_string(c.values.size()));
  }
  return joint_controller;
}

/// The link of the joint a joint effort `c` acts on in robot `robot`;
/// ConfigError naming the entry's field if it moves no such joint.
int jointOf(const TimedCommand& c, const core::SceneRobot& robot) {
  const int j = core::linkOfJoint(robot.model, c.joint);
  if (j < 0) {
    fail(c.key + ".joint_effort.joint_name", "robot '" + robot.name + "' has no moving joint '" + c.joint + "'" +
                                                 core::heldJointNote(robot.model, c.joint));
  }
  return j;
}

/// The index in `robots` of the robot named `name`, or their count.
std::size_t robotNamed(const std::vector<core::SceneRobot>& robots, const std::string& name) {
  std::size_t r = 0;
  while (r < robots.size() && robots[r].name != name) ++r;
  return r;
}

}  // namespace

Timeline::Timeline(std::vector<TimedCommand> entries, const std::vector<core::SceneRobot>& robots, double dt,
                   const std::vector<RobotControls>& controls, BodyDrivers bodies)
    : bodies_(std::move(bodies)) {
  for (TimedCommand& c : entries) {
    if (!c.body.empty()) {
      if (!bodies_ || bodies_(c.body) == nullptr) {
        fail(c.key + ".body",
             "no free body '" + c.body + "' with a cmd_vel (its velocity driver's settings) in the world");
      }
      const double due = c.t;  // as a message on its topic at t
      entries_.push_back({std::move(c), "", due});
      continue;
    }
    std::size_t r = 0;
    if (c.robot.empty()) {
      if (robots.size() != 1) {
        fail(c.key + ".robot", "a world of " + std::to_string(robots.size()) +
                                   " robots: name the one it is for (or the body, body: NAME, for a body's cmd_vel)");
      }
    } else {
      r = robotNamed(robots, c.robot);
      if (r == robots.size()) fail(c.key + ".robot", "no robot '" + c.robot + "' in the world");
    }
    // Refused now, not when it is due.
    if (c.joint_effort) {
      jointOf(c, robots[r]);
    } else {
      targetOf(c, robots[r], controls.at(r));
    }
    // A joint effort acts from its own t: given before the step that holds it.
    const double due = c.joint_effort ? c.t - dt : c.t;
    entries_.push_back({std::move(c), robots[r].name, due});
  }
  std::stable_sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.due < b.due; });
}

void Timeline::giveBody(const TimedCommand& c, double t, std::vector<std::string>& said) const {
  core::VelocityDriver* driver = bodies_(c.body);
  if (driver == nullptr) {
    said.push_back(c.key + ": body '" + c.body + "' is gone: not given");
  } else if (driver->command(c.linear, c.angular, t)) {
    said.push_back(c.key + ": held to body '" + c.body + "''s cmd_vel.max_linear_speed and max_angular_speed");
  }
}

void Timeline::give(const Entry& e, double t, const std::vector<core::SceneRobot>& robots,
                    std::vector<RobotControls>& controls, core::JointEffortSchedule& efforts,
                    std::vector<std::string>& said) const {
  const TimedCommand& c = e.command;
  if (!c.body.empty()) return giveBody(c, t, said);
  const std::size_t r = robotNamed(robots, e.robot);
  if (r == robots.size()) {
    said.push_back(c.key + ": robot '" + e.robot + "' is gone: not given");
    return;
  }
  RobotControls& rc = controls.at(r);
  int target = 0;
  try {  // a robot of that name spawned since, with other controllers or joints
    target = c.joint_effort ? jointOf(c, robots[r]) : targetOf(c, robots[r], rc);
  } catch (const ConfigError& error) {
    said.push_back(error.what());
    return;
  }
  bool held = false;
  if (c.joint_effort) {  // from its own t, as apply_joint_effort's start_time, off the step grid too
    efforts.add(r, target, c.effort, c.t,
                c.duration > 0.0 ? c.t + c.duration : std::numeric_limits<double>::infinity());
  } else if (c.trajectory) {  // as a JointTrajectory stamped 0 received at t
    const std::size_t k = static_cast<std::size_t>(target);
    std::vector<core::Clipped> clipped;
    int dropped = 0;
    const std::string problem = rc.controllers.followTrajectory(
        k, t, t, orderedPoints(c, robots[r], rc.controllers.specs()[k]), clipped, dropped);
    if (!problem.empty()) said.push_back(c.key + ": " + problem + ": not given");
    held = !clipped.empty();
  } else if (c.cmd_vel && target < 0) {
    held = rc.base_driver->command(c.linear, c.angular, t);
  } else if (c.cmd_vel) {
    held = !rc.drives.at(static_cast<std::size_t>(target)).command(c.linear.x(), c.angular.z(), t, c.linear.y());
  } else {
    std::vector<core::Clipped> clipped;
    held = !rc.controllers.command(static_cast<std::size_t>(target), c.values, clipped) || !clipped.empty();
  }
  if (held) said.push_back(c.key + ": held to its controller's limits, or refused beyond them");
}

std::vector<std::string> Timeline::apply(double t, const std::vector<core::SceneRobot>& robots,
                                         std::vector<RobotControls>& controls, core::JointEffortSchedule& efforts) {
  std::vector<std::string> said;
  const auto ended = [&](std::size_t k) { return !(t < entries_[k].command.until); };
  held_.erase(std::remove_if(held_.begin(), held_.end(), ended), held_.end());
  for (const std::size_t k : held_) give(entries_[k], t, robots, controls, efforts, said);
  for (; next_ < entries_.size() && entries_[next_].due <= t; ++next_) {
    const Entry& e = entries_[next_];
    // A new command for a controller ends one held for it.
    const auto replaced = [&](std::size_t k) {
      const TimedCommand& h = entries_[k].command;
      return entries_[k].robot == e.robot && h.body == e.command.body && h.controller == e.command.controller &&
             h.cmd_vel == e.command.cmd_vel;
    };
    if (!e.command.joint_effort) held_.erase(std::remove_if(held_.begin(), held_.end(), replaced), held_.end());
    give(e, t, robots, controls, efforts, said);
    if (t < e.command.until) held_.push_back(next_);
  }
  return said;
}

}  // namespace rigid_body_sim::io
