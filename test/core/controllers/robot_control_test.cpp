// A robot's control stage (docs/physics.md §11.15): the controllers' and the
// timed efforts summed and each joint's sum held within its limit, the
// step's own clip the same, and the base driver's wrench on the base link.
#include "rigid_body_sim/core/controllers/robot_control.h"

#include <gtest/gtest.h>

#include <vector>

#include "controlled_robot.h"

namespace rigid_body_sim::core {
namespace {

using test::Alone;
using test::kStep;

constexpr double kG = 9.81;

TEST(RobotControl, SumsTheControllersAndTheTimedEffortsEachWithinItsJointsLimit) {
  const ArticulationModel model = test::pendulum(2.0);
  RobotControl control;
  control.controllers = JointControllers(model, {{"hinge_effort", ControlMode::kEffort, {1}, {}}});
  std::vector<Clipped> clipped;
  ASSERT_TRUE(control.controllers.command(0, {1.5}, clipped));
  const ArticulationState rest = restState(model);
  JointEffortSchedule timed;
  ArticulationLoads out;
  control.loads(model, rest, 0.0, kStep, timed, 0, out);
  EXPECT_EQ(out.effort(0), 1.5);  // the controller's alone
  timed.add(0, 1, 1.0, 0.0);      // 1.5 + 1 N·m: held to 2
  control.loads(model, rest, 0.0, kStep, timed, 0, out);
  EXPECT_EQ(out.effort(0), 2.0);
  timed.clearAll();
  timed.add(0, 1, -5.0, 0.0);  // 1.5 − 5: held to −2
  timed.add(1, 1, 9.0, 0.0);   // another robot's: not this one's
  control.loads(model, rest, 0.0, kStep, timed, 0, out);
  EXPECT_EQ(out.effort(0), -2.0);
  EXPECT_TRUE(out.wrench_L.empty());  // no base driver
}

TEST(RobotControl, TheStepClipsAnEffortPastTheLimitAsTheStageDoes) {
  // 100 N·m given straight to the step moves the pendulum as 2 N·m does,
  // bit for bit: one clip, wherever the effort comes from.
  const ArticulationModel model = test::pendulum(2.0);
  Alone given(model, Vec3(0.0, 0.0, -kG)), held(model, Vec3(0.0, 0.0, -kG));
  ArticulationLoads past, within;
  past.effort = Eigen::VectorXd::Constant(1, 100.0);
  within.effort = Eigen::VectorXd::Constant(1, 2.0);
  for (int n = 0; n < 200; ++n) {
    given.step(past);
    held.step(within);
  }
  EXPECT_GT(held.robot().q(0), 0.01);  // it moved
  EXPECT_EQ(given.robot().q(0), held.robot().q(0));
  EXPECT_EQ(given.robot().v(0), held.robot().v(0));
}

TEST(RobotControl, ItsBaseDriverPushesTheBaseLinkAtItsMostForce) {
  // Two 1 kg bars, a floating base, asked for 0.5 m/s along x from rest:
  // the PI's force m (k_p e + k_i h e) = 2 (25 + 0.31) N is past the 10 N
  // most, so the base link gets 10 N along x, the moment through the centre
  // of mass; nothing on the other link.
  const ArticulationModel model = test::twoBars();
  RobotControl control;
  control.base_driver.emplace(DriverSettings{});
  control.base_driver->command(Vec3(0.5, 0.0, 0.0), Vec3::Zero(), 0.0);
  ArticulationLoads out;
  control.loads(model, restState(model), 0.0, kStep, JointEffortSchedule(), 0, out);
  ASSERT_EQ(out.wrench_L.size(), 2u);
  EXPECT_NEAR(out.wrench_L[0].tail<3>().x(), 10.0, 1e-12);
  EXPECT_NEAR(out.wrench_L[0].tail<3>().y(), 0.0, 1e-12);
  EXPECT_EQ(out.wrench_L[1], Vec6::Zero());
  EXPECT_EQ(out.effort(0), 0.0);  // no joint controller
  // Its driver gone, its wrench goes with it (a stale one would push on).
  control.base_driver.reset();
  control.loads(model, restState(model), 0.0, kStep, JointEffortSchedule(), 0, out);
  EXPECT_TRUE(out.wrench_L.empty());
}

}  // namespace
}  // namespace rigid_body_sim::core
