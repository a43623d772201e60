// The IMUs on robots' links in the node: each sampled at its rate of sim
// time from its link's motion (core::Imu, docs/physics.md §10.1), whether
// or not anyone listens (its noise stays seeded), and published as
// sensor_msgs/Imu (REP 145) on its topic, stamped on the node's clock. The
// message is built by a plain function the bodies' IMUs share.
#pragma once

#include <ros/ros.h>
#include <sensor_msgs/Imu.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/devices/imu.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/io/sensor_mount.h"
#include "rigid_body_sim/ros/counted_publisher.h"

namespace rigid_body_sim::node {

/// sensor_msgs/Imu of a reading: each covariance diagonal σ² of its settings' noise.
sensor_msgs::Imu imuMessage(const core::ImuReading& r, const core::ImuSettings& s, const std::string& frame,
                            const ros::Time& stamp);

/// Link `link`'s pose and twist in `kin` as a LinkState (the world's axes).
core::LinkState linkStateOf(const core::ArticulationKinematics& kin, int link);

class LinkImus {
 public:
  LinkImus(const ros::NodeHandle& nh, double dt) : nh_(nh), dt_(dt) {}
  /// Robot r of `sim` (the last added) and its IMUs: their topics under
  /// `prefix` (an absolute topic as it is), frames after `frame_prefix`;
  /// each starts from the robot's state now.
  void addRobot(const core::Simulation& sim, std::size_t r, const std::string& prefix, const std::string& frame_prefix,
                const std::vector<io::RobotImu>& imus);
  /// Robot r deleted: its IMUs' topics close; the later robots move down by one.
  void removeRobot(std::size_t r) {
    robots_.erase(robots_.begin() + static_cast<std::ptrdiff_t>(r));
    handles_.erase(handles_.begin() + static_cast<std::ptrdiff_t>(r));  // after what it opened
  }
  /// Robot r was put somewhere (set_model_configuration, a reset): the next
  /// period of each of its IMUs starts now (a jump is no acceleration).
  void restart(const core::Simulation& sim, std::size_t r);
  /// The IMUs due at step `steps` of `sim`'s state, stamped `stamp`.
  void sample(const core::Simulation& sim, long long steps, const ros::Time& stamp);

 private:
  struct Port {
    core::Imu imu;
    int link = 0;
    long long every = 1;
    std::string frame;
    CountedPublisher publisher;
  };

  ros::NodeHandle nh_;
  double dt_;
  std::vector<std::vector<Port>> robots_;
  std::vector<std::shared_ptr<ros::NodeHandle>> handles_;  ///< per robot, its own (ownHandle)
  core::ArticulationKinematics kin_;                       ///< reused by every sample
};

}  // namespace rigid_body_sim::node
