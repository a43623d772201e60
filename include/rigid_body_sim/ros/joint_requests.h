// Gazebo's joint services for the robots, with gazebo_msgs' fields:
// set_model_configuration (plus the velocities users ask for),
// get_joint_properties, apply_joint_effort and clear_joint_forces. Each request is checked whole before anything
// changes; a refusal names the field and the joint. Tested through the
// node (arm.test).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "rigid_body_sim/ApplyJointEffort.h"
#include "rigid_body_sim/ClearJointForces.h"
#include "rigid_body_sim/GetJointProperties.h"
#include "rigid_body_sim/SetModelConfiguration.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/ros/sim_clock.h"

namespace rigid_body_sim::node {

/// Puts the joints `names` of `model` at `positions`, with `velocities`
/// (none: at rest), in `state`; a mimic joint follows its leader. Returns
/// "" or why not, naming the field and index (joint_names, joint_positions,
/// joint_velocities: an unknown, mimic or repeated joint, a position
/// outside the limits, a velocity past them, a count that does not match),
/// and then `state` is unchanged. set_model_configuration's check, and
/// ~spawn_body's for a robot's joint_names.
std::string configureJoints(const core::ArticulationModel& model, const core::SpeedLimits& limits,
                            const std::vector<std::string>& names, const std::vector<double>& positions,
                            const std::vector<double>& velocities, core::ArticulationState& state);

class JointRequests {
 public:
  /// `placed(r)` after robot r was put somewhere: its controllers restart,
  /// the new state is published.
  JointRequests(core::Simulation& sim, const NodeTime& time, std::function<void(std::size_t)> placed)
      : sim_(sim), time_(time), placed_(std::move(placed)) {}

  bool setModelConfiguration(SetModelConfiguration::Request& req, SetModelConfiguration::Response& res);
  bool getJointProperties(GetJointProperties::Request& req, GetJointProperties::Response& res);
  bool applyJointEffort(ApplyJointEffort::Request& req, ApplyJointEffort::Response& res);
  bool clearJointForces(ClearJointForces::Request& req, ClearJointForces::Response& res);

 private:
  /// The robot named `name` ("" = the only one), or why not.
  std::optional<std::size_t> robot(const std::string& name, std::string& error) const;
  /// The robot and link of joint `name` ("JOINT" when one robot has it,
  /// or "ROBOT/JOINT"), or why not.
  std::optional<std::pair<std::size_t, int>> joint(const std::string& name, std::string& error) const;

  core::Simulation& sim_;
  const NodeTime& time_;
  std::function<void(std::size_t)> placed_;
};

}  // namespace rigid_body_sim::node
