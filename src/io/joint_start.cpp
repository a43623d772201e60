// A robot's joints at the start: joint_start.h.
#include "rigid_body_sim/io/joint_start.h"

#include <cmath>
#include <sstream>

namespace rigid_body_sim::io {
namespace {

/// The link whose joint is `name`, or -1.
int jointIndex(const core::ArticulationModel& model, const std::string& name) {
  for (std::size_t i = 1; i < model.links.size(); ++i) {
    if (model.links[i].joint == name) return static_cast<int>(i);
  }
  return -1;
}

[[noreturn]] void refuse(const std::string& key, const std::string& joint, double value, const std::string& why) {
  std::ostringstream os;
  os << "config key '" << key << "." << joint << "' = " << value << ": " << why;
  throw ConfigError(os.str());
}

}  // namespace

void startJoints(const core::ArticulationModel& model, const InitialJoints& initial, const core::SpeedLimits& limits,
                 const std::string& key, core::ArticulationState& state) {
  core::ArticulationState next = state;
  const auto find = [&](const std::string& map, const std::string& name, double value) {
    const int i = jointIndex(model, name);
    if (i < 0) {
      refuse(key + "." + map, name, value,
             "robot '" + model.name + "' has no moving joint of that name" + core::heldJointNote(model, name));
    }
    if (model.links[i].mimic.joint > 0) {
      refuse(key + "." + map, name, value,
             "a mimic joint follows joint '" + model.links[model.links[i].mimic.joint].joint + "': set that one");
    }
    return i;
  };
  for (const auto& [name, q] : initial.positions) {
    const int i = find("joint_positions", name, q);
    const core::JointLimits& lim = model.links[i].limits;
    if (q < lim.lower || q > lim.upper) {
      std::ostringstream range;
      range << "outside the joint's limits [" << lim.lower << ", " << lim.upper << "]";
      refuse(key + ".joint_positions", name, q, range.str());
    }
    next.q(i - 1) = q;
  }
  for (const auto& [name, v] : initial.velocities) {
    const int i = find("joint_velocities", name, v);
    const bool slides = model.links[i].type == core::JointType::Prismatic;
    const double most = slides ? limits.max_linear_speed : limits.max_angular_speed;
    if (std::abs(v) > most) {
      std::ostringstream why;
      why << "faster than limits." << (slides ? "max_linear_speed" : "max_angular_speed") << " = " << most;
      refuse(key + ".joint_velocities", name, v, why.str());
    }
    next.v(i - 1) = v;
  }
  for (std::size_t i = 1; i < model.links.size(); ++i) {
    const core::Mimic& mimic = model.links[i].mimic;
    if (mimic.joint <= 0) continue;
    next.q(i - 1) = mimic.multiplier * next.q(mimic.joint - 1) + mimic.offset;
    next.v(i - 1) = mimic.multiplier * next.v(mimic.joint - 1);
  }
  state = next;
}

}  // namespace rigid_body_sim::io
