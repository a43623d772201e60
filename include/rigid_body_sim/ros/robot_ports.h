// What the node publishes of its robots: each robot's sensor_msgs/JointState
// (`joint_states`, `NAME/joint_states` in a world) for robot_state_publisher
// to turn into its links' tf, and the transform world -> base link of a
// robot whose base floats. The messages are built by plain functions
// (tested without a master); the class sends them.
#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_broadcaster.h>

#include <functional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/simulation.h"
#include "rigid_body_sim/ros/counted_publisher.h"

namespace rigid_body_sim::node {

/// One robot's names and topics.
struct RobotPorts {
  std::string name;    ///< the robot's (its entry's, or its URDF's alone)
  std::string prefix;  ///< its topics' ("" alone, "NAME/" in a world)
  /// Its base link's frame, named as in the URDF (robot_state_publisher
  /// names the other links so), or "" for a robot fixed to the world (the
  /// URDF's root is then `world`, and robot_state_publisher roots it there).
  std::string base_frame;
  CountedPublisher joint_states;
  long long every = 1;  ///< joint_states every this many steps
};

/// sensor_msgs/JointState of `state`: every moving joint of `robot` in its
/// model's order (mimic joints too), positions as the step keeps them
/// (continuous joints unwrapped, as gazebo_ros_control reports them),
/// velocities, and `effort` (N·m or N, per joint; empty: zero); then each
/// held joint (core::HeldJoint) at its position, at rest.
sensor_msgs::JointState jointStateMessage(const core::ArticulationModel& robot, const core::ArticulationState& state,
                                          const Eigen::VectorXd& effort, const ros::Time& stamp);

/// The base frame the node puts on tf for `robot` (world_frame -> it):
/// its base link's, or "" for a URDF rooted at `world`.
std::string placedBase(const core::ArticulationModel& robot);

/// The transform `world_frame` -> `ports.base_frame` of `state`'s base.
geometry_msgs::TransformStamped baseTransform(const core::ArticulationState& state, const RobotPorts& ports,
                                              const std::string& world_frame, const ros::Time& stamp);

/// Refuses (io::ConfigError) robots whose frames tf would confuse: a link
/// of two robots with one name (robot_state_publisher publishes URDF names
/// as they are: give each robot's URDF its own, as with a xacro prefix), or
/// a robot's link named as the world frame or as one of `body_frames`.
void checkRobotFrames(const core::Scene& scene, const std::string& world_frame,
                      const std::vector<std::string>& body_frames);

class RobotPublisher {
 public:
  /// Advertises each robot's joint_states on `nh` (under "NAME/" when
  /// `several` things are in the world), at `rate(r)` Hz of sim time (its
  /// joint_state_controller's), or `publish_rate` where that is 0.
  RobotPublisher(const ros::NodeHandle& nh, const core::Scene& scene, bool several, std::string world_frame, double dt,
                 double publish_rate, const std::function<double(std::size_t)>& rate);

  /// A robot added to the world (~spawn_body): its joint_states under
  /// `prefix`, at `hz` Hz of sim time.
  void addRobot(const core::SceneRobot& robot, const std::string& prefix, double hz);

  /// Robot r's joint states (efforts `applied[r]`) and floating base,
  /// stamped `now`: every robot, or with `steps` ≥ 0 those due at that step.
  void publish(const core::Simulation& sim, const std::vector<Eigen::VectorXd>& applied, const ros::Time& now,
               long long steps = -1);

  const std::vector<RobotPorts>& robots() const { return robots_; }

 private:
  ros::NodeHandle nh_;
  std::string world_frame_;
  double dt_;
  std::vector<RobotPorts> robots_;
  std::vector<geometry_msgs::TransformStamped> bases_;
  tf2_ros::TransformBroadcaster tf_;
};

}  // namespace rigid_body_sim::node
