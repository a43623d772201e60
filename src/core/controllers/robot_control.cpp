// A robot's control stage (robot_control.h): docs/physics.md §11.15.
#include "rigid_body_sim/core/controllers/robot_control.h"

namespace rigid_body_sim::core {

void holdEfforts(const ArticulationModel& model, Eigen::VectorXd& effort) {
  for (int j = 1; j <= model.jointCount(); ++j) effort(j - 1) = model.links[j].limits.heldEffort(effort(j - 1));
}

void RobotControl::loads(const ArticulationModel& model, const ArticulationState& state, double t, double h,
                         const JointEffortSchedule& timed, std::size_t robot, ArticulationLoads& out) {
  Eigen::VectorXd& effort = out.effort;
  controllers.efforts(state, t, h, effort);  // zero where none acts
  if (effort.size() != model.jointCount()) effort.setZero(model.jointCount());
  for (DiffDrive& drive : drives) drive.efforts(state, t, h, effort);
  timed.addEfforts(robot, t, h, effort);
  holdEfforts(model, effort);
  if (base_driver) {
    kinematics(model, state, kin_);
    out.wrench_L.assign(model.links.size(), Vec6::Zero());
    out.wrench_L[0] = baseLoad(*base_driver, model, kin_, t, h);
  } else {
    out.wrench_L.clear();
  }
}

void RobotControl::observe(const ArticulationState& state, double h) {
  for (DiffDrive& drive : drives) drive.observe(state, h);
}

void RobotControl::restart(const ArticulationState& state, bool zero_odometry) {
  controllers.restart(state);
  for (DiffDrive& drive : drives) drive.restart(state, zero_odometry);
}

}  // namespace rigid_body_sim::core
