// Gazebo's joint services: joint_requests.h.
#include "rigid_body_sim/ros/joint_requests.h"

#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <vector>

#include "request_checks.h"

namespace rigid_body_sim::node {
namespace {

std::string robotNames(const core::Scene& scene) {
  std::string names;
  for (const core::SceneRobot& r : scene.robots()) names += (names.empty() ? "'" : ", '") + r.name + "'";
  return names.empty() ? "none" : names;
}

std::string number(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

}  // namespace

std::optional<std::size_t> JointRequests::robot(const std::string& name, std::string& error) const {
  const std::vector<core::SceneRobot>& robots = sim_.scene.robots();
  if (name.empty() && robots.size() == 1) return 0;
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (robots[r].name == name) return r;
  }
  error = "model_name: " +
          (name.empty() ? std::string("there are several robots, or none: give one")
                        : "no robot '" + io::shownName(name) + "'") +
          " (the robots: " + robotNames(sim_.scene) + ")";
  return std::nullopt;
}

std::optional<std::pair<std::size_t, int>> JointRequests::joint(const std::string& name, std::string& error) const {
  const std::vector<core::SceneRobot>& robots = sim_.scene.robots();
  std::optional<std::pair<std::size_t, int>> found;
  int matches = 0;
  for (std::size_t r = 0; r < robots.size(); ++r) {
    const std::string& robot_name = robots[r].name;
    const bool scoped = name.rfind(robot_name + "/", 0) == 0;
    const int j = core::linkOfJoint(robots[r].model, scoped ? name.substr(robot_name.size() + 1) : name);
    if (j < 0) continue;
    if (scoped) return std::make_pair(r, j);
    found = std::make_pair(r, j);
    ++matches;
  }
  if (matches == 1) return found;
  error = "joint_name: " + (matches > 1 ? "several robots have a joint '" + name + "': give ROBOT/" + name
                                        : "no robot has a moving joint '" + io::shownName(name) +
                                              "' (the robots: " + robotNames(sim_.scene) + ")");
  return std::nullopt;
}

std::string configureJoints(const core::ArticulationModel& model, const core::SpeedLimits& limits,
                            const std::vector<std::string>& names, const std::vector<double>& positions,
                            const std::vector<double>& velocities, core::ArticulationState& state) {
  const std::size_t n = names.size();
  if (positions.size() != n) {
    return "joint_positions: " + std::to_string(positions.size()) + " values for " + std::to_string(n) + " joint_names";
  }
  if (!velocities.empty() && velocities.size() != n) {
    return "joint_velocities: " + std::to_string(velocities.size()) + " values for " + std::to_string(n) +
           " joint_names (give one per joint, or none: at rest)";
  }
  core::ArticulationState now = state;
  std::set<int> named;
  for (std::size_t k = 0; k < n; ++k) {
    const std::string& name = names[k];
    const std::string at = "[" + std::to_string(k) + "]";
    const int j = core::linkOfJoint(model, name);
    if (j < 0) {
      return "joint_names" + at + ": robot '" + model.name + "' has no moving joint '" + io::shownName(name) + "'" +
             core::heldJointNote(model, name);
    }
    const core::ArticulatedLink& link = model.links[j];
    if (link.mimic.joint >= 0) {
      return "joint_names" + at + ": joint '" + name + "' mimics '" + model.links[link.mimic.joint].joint +
             "': set that one (a mimic joint follows it)";
    }
    if (!named.insert(j).second) return "joint_names" + at + ": joint '" + name + "' is named twice";
    const double q = positions[k];
    const bool bounded = link.type != core::JointType::Continuous;
    if (!std::isfinite(q) || (bounded && (q < link.limits.lower || q > link.limits.upper)) || std::abs(q) > 1e6) {
      return "joint_positions" + at + ": joint '" + name + "' = " + number(q) + " is " +
             (bounded ? "outside its limits [" + number(link.limits.lower) + ", " + number(link.limits.upper) + "]"
                      : "not a finite angle within 1e6 rad");
    }
    const double v = velocities.empty() ? 0.0 : velocities[k];
    const double top =
        std::min(link.limits.velocity,
                 link.type == core::JointType::Prismatic ? limits.max_linear_speed : limits.max_angular_speed);
    if (!std::isfinite(v) || std::abs(v) > top) {
      return "joint_velocities" + at + ": joint '" + name + "' = " + number(v) + " is faster than its velocity limit " +
             number(top) + " (the URDF's, or limits.max_*_speed)";
    }
    now.q(j - 1) = q;
    now.v(j - 1) = v;
  }
  for (int j = 1; j <= model.jointCount(); ++j) {  // a mimic joint follows its leader
    const core::Mimic& mimic = model.links[j].mimic;
    if (mimic.joint < 0 || named.count(mimic.joint) == 0) continue;
    now.q(j - 1) = mimic.multiplier * now.q(mimic.joint - 1) + mimic.offset;
    now.v(j - 1) = mimic.multiplier * now.v(mimic.joint - 1);
  }
  state = now;
  return {};
}

bool JointRequests::setModelConfiguration(SetModelConfiguration::Request& req, SetModelConfiguration::Response& res) {
  res.success = false;
  const auto r = robot(req.model_name, res.status_message);
  if (!r) return true;
  const core::ArticulationModel& model = sim_.scene.robots()[*r].model;
  core::ArticulationState now = sim_.robots[*r];
  res.status_message =
      configureJoints(model, sim_.model().limits(), req.joint_names, req.joint_positions, req.joint_velocities, now);
  if (!res.status_message.empty()) return true;
  sim_.placeRobot(*r, now);
  placed_(*r);
  res.success = true;
  res.status_message = "robot '" + model.name + "': " + std::to_string(req.joint_names.size()) + " joints set";
  return true;
}

bool JointRequests::getJointProperties(GetJointProperties::Request& req, GetJointProperties::Response& res) {
  res.success = false;
  const auto found = joint(req.joint_name, res.status_message);
  if (!found) return true;
  const auto [r, j] = *found;
  const core::ArticulatedLink& link = sim_.scene.robots()[r].model.links[j];
  switch (link.type) {
    case core::JointType::Revolute:
      res.type = GetJointProperties::Response::REVOLUTE;
      break;
    case core::JointType::Continuous:
      res.type = GetJointProperties::Response::CONTINUOUS;
      break;
    case core::JointType::Prismatic:
      res.type = GetJointProperties::Response::PRISMATIC;
      break;
  }
  res.damping = {link.damping};
  res.position = {sim_.robots[r].q(j - 1)};
  res.rate = {sim_.robots[r].v(j - 1)};
  res.success = true;
  res.status_message = "joint '" + link.joint + "' of robot '" + sim_.scene.robots()[r].name + "'";
  return true;
}

bool JointRequests::applyJointEffort(ApplyJointEffort::Request& req, ApplyJointEffort::Response& res) {
  res.success = false;
  const auto found = joint(req.joint_name, res.status_message);
  if (!found) return true;
  const auto [r, j] = *found;
  if (!std::isfinite(req.effort) || std::abs(req.effort) > kMaxForce) {
    res.status_message = "effort: " + number(req.effort) + " is not a finite effort within 1e6 N*m or N";
    return true;
  }
  const double duration = req.duration.toSec();
  if (duration == 0.0) {
    res.status_message =
        "duration 0 applies nothing: give duration > 0 (for that long) or < 0 (until "
        "clear_joint_forces)";
    return true;
  }
  std::string when;
  const std::optional<double> start = startOf(req.start_time, time_, when, res.status_message);
  if (!start) return true;
  sim_.joint_efforts.add(r, j, req.effort, *start,
                         duration > 0.0 ? *start + duration : std::numeric_limits<double>::infinity());
  res.success = true;
  const core::SceneRobot& robot = sim_.scene.robots()[r];
  res.status_message = "effort " + number(req.effort) + " on joint '" + robot.model.links[j].joint + "' of robot '" +
                       robot.name + "' " + when + " " +
                       (duration > 0.0 ? "for " + number(duration) + " s" : std::string("until cleared"));
  return true;
}

bool JointRequests::clearJointForces(ClearJointForces::Request& req, ClearJointForces::Response& res) {
  res.success = false;
  const auto found = joint(req.joint_name, res.status_message);
  if (!found) return true;
  const auto [r, j] = *found;
  const std::size_t n = sim_.joint_efforts.clear(r, j);
  res.success = true;
  res.status_message =
      std::to_string(n) + " efforts on joint '" + sim_.scene.robots()[r].model.links[j].joint + "' cleared";
  return true;
}

}  // namespace rigid_body_sim::node
