// The force-torque sensors on robots' joints in the node (Gazebo's
// gazebo_ros_ft_sensor): each publishes, at its rate of sim time,
// geometry_msgs/WrenchStamped of what its joint carries onto its child link
// (core::ForceTorqueSensor, docs/physics.md §10.10), in that link's frame,
// stamped on the node's clock. Nothing is computed while nobody listens.
#pragma once

#include <ros/ros.h>

#include <Eigen/Dense>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation_step.h"
#include "rigid_body_sim/core/devices/force_torque.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/io/sensor_mount.h"
#include "rigid_body_sim/ros/counted_publisher.h"

namespace rigid_body_sim::node {

class JointWrenches {
 public:
  JointWrenches(const ros::NodeHandle& nh, double dt) : nh_(nh), dt_(dt) {}
  /// Robot r's sensors: topics under `prefix` (an absolute topic as it is),
  /// frames after `frame_prefix`.
  void addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                const std::vector<io::RobotForceTorque>& sensors);
  /// Robot r deleted: its topics close; the later robots move down by one.
  void removeRobot(std::size_t r) {
    robots_.erase(robots_.begin() + static_cast<std::ptrdiff_t>(r));
    frames_prefix_.erase(frames_prefix_.begin() + static_cast<std::ptrdiff_t>(r));
    handles_.erase(handles_.begin() + static_cast<std::ptrdiff_t>(r));  // after what it opened
  }
  /// After a reset: each noise from its seed.
  void restart();
  /// Before a step of `sim`: the velocities it starts from.
  void before(const core::Simulation& sim);
  /// After it: the readings due at step `steps`, from the step's loads on
  /// the robots' links (`robot_loads`, per robot, or none) and the contacts
  /// touching now, stamped `stamp`.
  void publish(const core::Simulation& sim, const std::vector<core::ArticulationLoads>& robot_loads, long long steps,
               const ros::Time& stamp);

 private:
  struct Port {
    core::ForceTorqueSensor sensor;
    std::string frame;  ///< the child link's, after the robot's tf_prefix
    long long every = 1;
    CountedPublisher wrench;
  };
  struct RobotPorts {
    std::vector<Port> ports;
    Eigen::VectorXd u_before;  ///< the velocity the last step started from
  };

  ros::NodeHandle nh_;
  double dt_;
  std::vector<RobotPorts> robots_;
  std::vector<std::string> frames_prefix_;                 ///< per robot, its tf_prefix
  std::vector<std::shared_ptr<ros::NodeHandle>> handles_;  ///< per robot, its own (ownHandle)
  core::ArticulationKinematics kin_;                       ///< reused by every reading
};

}  // namespace rigid_body_sim::node
