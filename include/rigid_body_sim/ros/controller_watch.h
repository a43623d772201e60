// A controller in trouble, said once: one that holds its joint at the
// URDF's effort limit, or drives it hard (half that or more) against a
// position limit, for a sustained time (an unstable gain, p = 1e9 bouncing a joint between its
// limits; a joint blocked by the world). ROS-free: the node logs what it returns.
#pragma once

#include <Eigen/Core>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/controllers/joint_control.h"

namespace rigid_body_sim::node {

class ControllerWatch {
 public:
  /// s of sim time a joint must stay saturated, or pressed against a limit,
  /// before it is said: a controller's transient (a step in its target)
  /// saturates for tens of milliseconds.
  static constexpr double kSustained = 1.0;
  /// rad or m: a joint this near a position limit is at it.
  static constexpr double kAtLimit = 1e-3;

  /// After one step of robot `r` (named `robot`): the efforts applied
  /// (within the limits, joint j at j − 1) and its state. Returns the
  /// sentences to warn with, each joint at most once for the node's life.
  std::vector<std::string> observe(std::size_t r, const std::string& robot, const core::ArticulationModel& model,
                                   const core::JointControllers& controllers, const core::ArticulationState& state,
                                   const Eigen::VectorXd& effort, double dt);

  /// The robot was put back (reset, a new configuration): its times start over.
  void restart(std::size_t r);
  /// Robot r was deleted: what was said of it is forgotten (a robot spawned
  /// again is watched afresh), the later robots move down by one.
  void removeRobot(std::size_t r);

 private:
  std::vector<std::vector<double>> saturated_;  ///< s, per robot and joint (a link index)
  std::vector<std::vector<double>> pressed_;    ///< s, per robot and joint
  std::set<std::pair<std::size_t, int>> said_;  ///< (robot, joint) already warned about
};

}  // namespace rigid_body_sim::node
