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
#include "rigid_body_sim/core/simulation.h"
#include "rigid_body_sim/ros/sim_clock.h"

namespace rigid_body_sim::node {

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
