// The robots' controllers in the node: robot_commands.h.
#include "rigid_body_sim/ros/robot_commands.h"

#include <std_msgs/Float64.h>
#include <std_msgs/Float64MultiArray.h>

#include <algorithm>

namespace rigid_body_sim::node {

RobotCommands::RobotCommands(const ros::NodeHandle& nh, std::vector<io::RobotControls> controls,
                             const core::Simulation& sim, bool several)
    : controls_(std::move(controls)) {
  ros::NodeHandle handle(nh);
  const std::vector<core::SceneRobot>& robots = sim.scene.robots();
  controls_.resize(robots.size());
  applied_.resize(robots.size());
  for (std::size_t r = 0; r < robots.size(); ++r) {
    robot_names_.push_back(robots[r].name);
    std::vector<std::string> joints;
    for (const core::ArticulatedLink& link : robots[r].model.links) joints.push_back(link.joint);
    joint_names_.push_back(std::move(joints));
    const std::string prefix = several ? robots[r].name + "/" : "";
    const std::vector<core::JointControllerSpec>& specs = controls_[r].controllers.specs();
    for (std::size_t c = 0; c < specs.size(); ++c) {
      const std::string topic = prefix + specs[c].name + "/command";
      if (controls_[r].group[c] != 0) {
        subscribers_.push_back(handle.subscribe<std_msgs::Float64MultiArray>(
            topic, 10, [this, r, c](const std_msgs::Float64MultiArray::ConstPtr& m) { command(r, c, m->data); }));
      } else {
        subscribers_.push_back(handle.subscribe<std_msgs::Float64>(
            topic, 10, [this, r, c](const std_msgs::Float64::ConstPtr& m) { command(r, c, {m->data}); }));
      }
      ROS_INFO("sim_node: robot '%s': controller '%s' on %s", robots[r].name.c_str(), specs[c].name.c_str(),
               handle.resolveName(topic).c_str());
    }
  }
  restart(sim);
}

void RobotCommands::command(std::size_t r, std::size_t c, const std::vector<double>& values) {
  core::JointControllers& controllers = controls_[r].controllers;
  const core::JointControllerSpec& spec = controllers.specs()[c];
  std::vector<core::Clipped> clipped;
  if (!controllers.command(c, values, clipped)) {
    ROS_WARN("sim_node: robot '%s': controller '%s': a command of %zu values, %zu expected and each finite: dropped",
             robot_names_[r].c_str(), spec.name.c_str(), values.size(), spec.joints.size());
    return;
  }
  for (const core::Clipped& k : clipped) {
    const std::string joint = robot_names_[r] + "/" + joint_names_[r][k.joint];
    if (!warned_.insert({joint, k.what}).second) continue;
    ROS_WARN(
        "sim_node: robot '%s': controller '%s': a command for joint '%s' is past its URDF %s limit: held to "
        "it (said once per joint)",
        robot_names_[r].c_str(), spec.name.c_str(), joint_names_[r][k.joint].c_str(), k.what.c_str());
  }
}

void RobotCommands::loadsFor(const core::Simulation& sim, double t, std::vector<core::ArticulationLoads>& loads) {
  loads.resize(controls_.size());
  const double dt = sim.model().dt();
  for (std::size_t r = 0; r < controls_.size(); ++r) {
    const core::ArticulationModel& model = sim.scene.robots()[r].model;
    Eigen::VectorXd& effort = applied_[r];
    controls_[r].controllers.efforts(sim.robots[r], dt, effort);  // zero where none acts
    if (effort.size() != model.jointCount()) effort.setZero(model.jointCount());
    sim.joint_efforts.addEfforts(r, t, dt, effort);
    for (int j = 1; j <= model.jointCount(); ++j) {  // the sum within the limit, as reported
      effort(j - 1) = std::clamp(effort(j - 1), -model.links[j].limits.effort, model.links[j].limits.effort);
    }
    loads[r].effort = effort;
  }
}

void RobotCommands::restart(const core::Simulation& sim) {
  for (std::size_t r = 0; r < controls_.size(); ++r) restart(sim, r);
}

void RobotCommands::restart(const core::Simulation& sim, std::size_t r) {
  controls_.at(r).controllers.restart(sim.robots[r]);
  applied_[r].resize(0);
}

}  // namespace rigid_body_sim::node
