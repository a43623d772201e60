// A steered base's geometry from its URDF: steering_geometry.h.
#include "steering_geometry.h"

#include <cmath>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io::detail {

namespace {

/// The steering joint (an index into `steers`) that carries link `j`, or −1.
int carriedBy(const core::ArticulationModel& model, int j, const std::vector<int>& steers) {
  for (int at = j; at > 0; at = model.links[at].parent) {
    for (std::size_t k = 0; k < steers.size(); ++k) {
      if (steers[k] == at) return static_cast<int>(k);
    }
  }
  return -1;
}

}  // namespace

core::SteeringSpec steeringOf(const core::ArticulationModel& model, const SteeredJoints& joints, double wheelbase) {
  const core::ArticulationKinematics rest = core::kinematics(model, core::restState(model));
  const auto at = [&](int j) -> const core::Vec3& { return rest.X_BL[j].p_PC; };  // a joint's origin in the base
  core::SteeringSpec s;
  s.joints = joints.steers;
  // The fixed axle's centre.
  std::vector<int> axle = joints.fixed_axle;
  if (axle.empty()) {
    for (const int j : joints.driven) {
      if (carriedBy(model, j, joints.steers) < 0) axle.push_back(j);
    }
  }
  if (axle.empty()) {
    throw ConfigError("config key '" + joints.driven_key +
                      "': every driven wheel steers, so none places the fixed axle");
  }
  core::Vec3 centre = core::Vec3::Zero();
  for (const int j : axle) centre += at(j) / static_cast<double>(axle.size());
  double mean_x = 0.0;
  for (std::size_t k = 0; k < joints.steers.size(); ++k) {
    const int j = joints.steers[k];
    const core::Vec3 axis = rest.X_BL[j].R_PC * model.links[j].axis_J.normalized();
    if (std::abs(axis.z()) < std::cos(25.0 * M_PI / 180.0)) {
      throw ConfigError("config key '" + joints.steers_key + "': joint '" + model.links[j].joint +
                        "''s axis is not within 25 degrees of the base's z, so it does not steer the base");
    }
    s.joint_x.push_back(at(j).x() - centre.x());
    s.joint_y.push_back(at(j).y() - centre.y());
    s.joint_sign.push_back(axis.z() > 0.0 ? 1.0 : -1.0);
    mean_x += s.joint_x.back() / static_cast<double>(joints.steers.size());
  }
  s.wheelbase = wheelbase > 0.0 ? wheelbase : mean_x;
  if (!(s.wheelbase > 0.0)) {
    throw ConfigError("config key '" + joints.steers_key + "': the steering joints are not ahead of the fixed axle (" +
                      std::to_string(mean_x) + " m): give the wheelbase");
  }
  for (const int j : joints.driven) {
    s.wheel_x.push_back(at(j).x() - centre.x());
    s.wheel_y.push_back(at(j).y() - centre.y());
    s.wheel_steer.push_back(carriedBy(model, j, joints.steers));
  }
  return s;
}

}  // namespace rigid_body_sim::io::detail
