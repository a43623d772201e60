// The odometry of robots' links in the node: a robot's `odom_noise` (its
// base on `odom` with the noise, exact on `ground_truth`) and Gazebo's
// gazebo_ros_p3d, each a nav_msgs/Odometry of its link at its rate of sim
// time (core/devices/odom_noise.h, docs/physics.md §10.2): the pose in the
// world frame, the twist in the link's axes (child_frame_id), stamped on
// the node's clock. The noise is drawn whether or not anyone listens.
#pragma once

#include <ros/ros.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/devices/odom_noise.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/io/sensor_mount.h"
#include "rigid_body_sim/ros/counted_publisher.h"

namespace rigid_body_sim::node {

class LinkOdometry {
 public:
  /// Each odometry of rate 0 at `publish_rate` Hz; `world_frame` heads every message.
  LinkOdometry(const ros::NodeHandle& nh, double dt, double publish_rate, std::string world_frame)
      : nh_(nh), dt_(dt), publish_rate_(publish_rate), world_frame_(std::move(world_frame)) {}
  /// Robot r's odometry: topics under `prefix` (an absolute topic as it
  /// is), child frames after `frame_prefix`.
  void addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                const std::vector<io::RobotOdometry>& odometry);
  /// Robot r deleted: its topics close; the later robots move down by one.
  void removeRobot(std::size_t r) {
    robots_.erase(robots_.begin() + static_cast<std::ptrdiff_t>(r));
    handles_.erase(handles_.begin() + static_cast<std::ptrdiff_t>(r));  // after what it opened
  }
  /// After a reset: each drift from zero.
  void restart();
  /// The reports due at step `steps` of `sim`'s state (sim time t), stamped `stamp`.
  void publish(const core::Simulation& sim, long long steps, double t, const ros::Time& stamp);

 private:
  struct Port {
    int link = 0;
    core::Pose X_LS;  ///< the reported frame in that link
    long long every = 1;
    std::string child;  ///< the link's frame: the twist's axes
    std::optional<core::OdomNoise> noise;
    double last = 0.0;  ///< s of sim time of its last report (the drift's)
    CountedPublisher odom, truth;
  };

  ros::NodeHandle nh_;
  double dt_, publish_rate_;
  std::string world_frame_;
  std::vector<std::vector<Port>> robots_;
  std::vector<std::shared_ptr<ros::NodeHandle>> handles_;  ///< per robot, its own (ownHandle)
  core::ArticulationKinematics kin_;                       ///< reused by every report
};

}  // namespace rigid_body_sim::node
