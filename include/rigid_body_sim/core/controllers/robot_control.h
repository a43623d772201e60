// A robot's control stage (docs/physics.md §11.15), as ros_control runs a
// robot's controllers: once a step, from the state before it, every
// controller reads the joints and writes an effort; the efforts are summed
// with the timed ones (apply_joint_effort), each joint's sum held within its
// URDF effort limit, and the base's velocity driver adds its wrench. After
// the step the drives read their wheels for odometry. ROS-free: the node
// turns messages into the controllers' commands, rbsim its timeline.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/articulations/articulation_step.h"
#include "rigid_body_sim/core/articulations/joint_effort_schedule.h"
#include "rigid_body_sim/core/controllers/diff_drive.h"
#include "rigid_body_sim/core/controllers/joint_control.h"
#include "rigid_body_sim/core/devices/velocity_driver.h"

namespace rigid_body_sim::core {

/// Every joint of `model` within its effort limit (joint j at j − 1): the
/// one clip of a robot's efforts (JointLimits::heldEffort), the control
/// stage's sum and the step's input alike.
void holdEfforts(const ArticulationModel& model, Eigen::VectorXd& effort);

/// What drives one robot: its joint controllers, its wheeled bases' drives
/// and its floating base's velocity driver (a body's `cmd_vel` on the whole
/// robot). Each is optional; a robot with none gets only its timed efforts.
struct RobotControl {
  JointControllers controllers;               ///< every commanding joint controller
  std::vector<DiffDrive> drives;              ///< DiffDriveController and its kin, in the map's order
  std::optional<VelocityDriver> base_driver;  ///< its floating base toward a commanded twist

  /// Robot `robot`'s loads for the step [t, t + h) of `model` at `state`:
  /// `out.effort` the controllers' and drives' efforts plus `timed`'s for
  /// this robot, each joint's sum within its limit; `out.wrench_L` the base
  /// driver's wrench on the base link (empty without one). `out`'s other
  /// fields are left as they are.
  void loads(const ArticulationModel& model, const ArticulationState& state, double t, double h,
             const JointEffortSchedule& timed, std::size_t robot, ArticulationLoads& out);
  /// After the step: each drive's odometry from where it left the wheels.
  void observe(const ArticulationState& state, double h);
  /// After a reset or a new configuration: every controller starts again
  /// from `state` (no integral, position targets where the joints are); a
  /// drive's odometry at zero if `zero_odometry`, else going on.
  void restart(const ArticulationState& state, bool zero_odometry);

 private:
  ArticulationKinematics kin_;  ///< the base driver's, reused from step to step
};

}  // namespace rigid_body_sim::core
