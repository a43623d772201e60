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
#include <memory>
#include <string>
#include <vector>

#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/ros/counted_publisher.h"

namespace rigid_body_sim::node {

/// One robot's names and topics.
struct RobotPorts {
  std::string name;    ///< the robot's (its entry's, or its URDF's alone)
  std::string prefix;  ///< its topics' ("" alone, "NAME/" in a world)
  /// Its links' tf frames: the URDF's names after its tf_prefix ("" or
  /// "PREFIX/"), as robot_state_publisher names them (framePrefix).
  std::string frame_prefix;
  std::vector<std::string> frames;  ///< every link's but a `world` root's
  /// Its base link's frame, or "" for a robot fixed to the world (the
  /// URDF's root is then `world`, and robot_state_publisher roots it there).
  std::string base_frame;
  std::shared_ptr<ros::NodeHandle> nh;  ///< its own (ownHandle), for its topics
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

/// The tf_prefix of robot `robot`'s frames, "" or "PREFIX/": the
/// `tf_prefix` parameter robot_state_publisher (1.15, as in Melodic) finds
/// searching up from the robot's namespace (/NAME/tf_prefix, then
/// /tf_prefix), which is how ROS 1 runs two copies of one URDF, and what
/// Gazebo's ROS plugins read: each robot in its namespace, its frames
/// PREFIX/LINK.
std::string framePrefix(const ros::NodeHandle& nh, const std::string& robot);

/// The tf frames of `robot`'s links after `frame_prefix` ("" or "PREFIX/"),
/// but a `world` root's (robot_state_publisher's root, the world itself).
std::vector<std::string> robotFrames(const core::ArticulationModel& robot, const std::string& frame_prefix);

/// Refuses (io::ConfigError) robots whose frames tf would confuse: a frame
/// of two robots (robot_state_publisher publishes the URDF's names after
/// the robot's tf_prefix: give each robot its own), or a robot's frame
/// named as the world frame or as one of `body_frames`.
void checkRobotFrames(const std::vector<RobotPorts>& robots, const std::string& world_frame,
                      const std::vector<std::string>& body_frames);

/// The prefix of a robot's controllers' topics and joint_states: its
/// gazebo_ros_control `robotNamespace` with a '/' after it ("/rrbot" ->
/// "/rrbot/"), or `otherwise` ("NAME/" in a world, "" alone) when it has none.
std::string robotTopicPrefix(const std::string& robot_namespace, const std::string& otherwise);

class RobotPublisher {
 public:
  /// Advertises each robot's joint_states on `nh` (under `prefixes[r]`,
  /// robotTopicPrefix's), at `rate(r)` Hz of sim time (its
  /// joint_state_controller's), or `publish_rate` where that is 0.
  RobotPublisher(const ros::NodeHandle& nh, const core::Scene& scene, const std::vector<std::string>& prefixes,
                 std::string world_frame, double dt, double publish_rate,
                 const std::function<double(std::size_t)>& rate);

  /// A robot added to the world (~spawn_body): its joint_states under
  /// `prefix`, at `hz` Hz of sim time, its frames after `frame_prefix`.
  void addRobot(const core::SceneRobot& robot, const std::string& prefix, double hz, const std::string& frame_prefix);
  /// Robot r's base is on tf from its drives' odometry as odom -> FRAME,
  /// one of `frames`: the node no longer puts world -> base there (tf
  /// allows one parent), and its ground truth stays on ~body_states. A frame
  /// of `frames` that is not its base is warned of (tf would give it two parents).
  void leaveBase(std::size_t r, const std::vector<std::string>& frames);
  /// Robot r deleted (~delete_body): its joint_states unadvertised, its
  /// base no longer on tf; the later robots move down by one.
  void removeRobot(std::size_t r) { robots_.erase(robots_.begin() + static_cast<std::ptrdiff_t>(r)); }

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
