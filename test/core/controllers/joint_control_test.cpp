// Joint controllers through effort (docs/physics.md §11.10): control_toolbox's
// PID arithmetic, a pendulum held at its target against gravity by the
// effort gravity needs, a wheel spun up as the discrete first-order law
// says, limits, refusals and the restart a reset makes; each robot stepped
// as the node steps it (stepScene).
#include "rigid_body_sim/core/controllers/joint_control.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "../articulations/articulation_models.h"
#include "controlled_robot.h"
#include "rigid_body_sim/core/articulations/articulation_step.h"
#include "rigid_body_sim/core/articulations/scene.h"

namespace rigid_body_sim::core {
namespace {

using test::Alone;
using test::pendulum;

constexpr double kG = 9.81;
constexpr double kH = 1e-3;

TEST(Pid, IsControlToolboxArithmetic) {
  Pid pid({2.0, 10.0, 0.5, 0.03});
  // e = 1 over 1 ms: p e + i (1e-3) + d · 0 (no last error).
  EXPECT_DOUBLE_EQ(pid.command(1.0, kH), 2.0 + 0.01);
  // e = 0.5: ∫e = 1.5e-3, i term 0.015; ė = (0.5 − 1) / 1e-3 = −500.
  EXPECT_DOUBLE_EQ(pid.command(0.5, kH), 1.0 + 0.015 - 250.0);
  // The integral term stops at i_clamp: ∫e = 1.5e-3 + 0.01, i ∫e = 0.115 → 0.03.
  EXPECT_DOUBLE_EQ(pid.command(10.0, 0.0, 0.001), 20.0 + 0.03);
  pid.reset();
  EXPECT_DOUBLE_EQ(pid.command(1.0, kH), 2.0 + 0.01);
}

/// A wheel of inertia `I` alone, v⁺ = v + h u / I, asked for 1 rad/s from
/// rest under gains made for J = 27 I (a loaded TurtleBot3 wheel's): `steps`
/// steps of the servo (or of command(), clamped the same); the largest |error|
/// over the last half.
double freeWheel(bool servo, int steps) {
  constexpr double I = 2e-5, J = 27.0 * I, tau = 0.02, limit = 10.0;
  Pid pid({2.0 * J / tau, J / (tau * tau), 0.0, limit});
  double v = 0.0, worst = 0.0;
  for (int n = 0; n < steps; ++n) {
    const double e = 1.0 - v;
    if (n >= steps / 2) worst = std::max(worst, std::abs(e));
    const double u = servo ? pid.servo(e, kH, 1.0 / I, limit) : std::clamp(pid.command(e, kH), -limit, limit);
    v += kH * u / I;
  }
  return worst;
}

TEST(Pid, ItsServoIsStableOnAWheelFarLighterThanItsGainsWereMadeFor) {
  // p h / I = 2.7 > 2: command() overshoots more each step, to the limit.
  EXPECT_GT(freeWheel(false, 1000), 100.0);
  // The servo, implicit in p: the error shrinks to nothing.
  EXPECT_LT(freeWheel(true, 1000), 1e-6);
}

TEST(Pid, ItsServoDoesNotWindUpWhileHeldAtItsLimit) {
  // A wheel of 1 kg m^2 held stalled for 1 s (its speed 0) asking for 1 rad/s
  // with the effort held to 0.5 N m, then let go: with the integral kept from
  // growing while held, it comes up to 1 rad/s as from rest (a PI's own
  // overshoot, 3.4 % here); a wound-up one overshoots by the integral it gathered.
  const auto overshoot = [](bool anti_windup) {
    Pid pid({2.0, 1.0, 0.0, 100.0});
    const double limit = 0.5;
    for (int n = 0; n < 1000; ++n) {
      if (anti_windup) {
        EXPECT_EQ(pid.servo(1.0, kH, 1.0, limit), limit);
      } else {
        pid.command(1.0, kH);
      }
    }
    double v = 0.0, most = 0.0;
    for (int n = 0; n < 20000; ++n) {
      v += kH * pid.servo(1.0 - v, kH, 1.0, limit);
      most = std::max(most, v);
    }
    return most - 1.0;
  };
  EXPECT_LT(overshoot(true), 0.05);
  EXPECT_GT(overshoot(false), 0.3);
}

JointControllerSpec positionController(double p, double i, double d, double i_clamp) {
  return {"hinge_position", ControlMode::kPosition, {1}, {{p, i, d, i_clamp}}};
}

TEST(JointControllers, PositionPidHoldsAPendulumWithTheEffortGravityNeeds) {
  const ArticulationModel model = pendulum(20.0);
  JointControllers ctl(model, {positionController(100.0, 200.0, 10.0, 10.0)});
  Alone run(model, Vec3(0.0, 0.0, -kG));
  ArticulationState& s = run.robot();
  ctl.restart(s);
  std::vector<Clipped> clipped;
  ASSERT_TRUE(ctl.command(0, {0.6}, clipped));
  EXPECT_TRUE(clipped.empty());
  ArticulationLoads loads;
  for (int n = 0; n < 20000; ++n) {
    ctl.efforts(s, n * kH, kH, loads.effort);
    run.step(loads);
  }
  EXPECT_NEAR(s.q(0), 0.6, 1e-6);  // the integral took the steady error away
  EXPECT_NEAR(s.v(0), 0.0, 1e-6);
  // At rest the effort balances gravity: m g l sin q (the bob held out to the side).
  EXPECT_NEAR(std::abs(loads.effort(0)), 1.0 * kG * 0.5 * std::sin(0.6), 1e-4);
}

TEST(JointControllers, EffortsStayWithinTheLimit) {
  ArticulationModel model = pendulum(1.5);  // below m g l sin 0.6 = 2.77 N·m: it cannot get there
  model.links[1].damping = 0.5;             // N·m·s/rad: it settles where the held effort leaves it
  JointControllers ctl(model, {positionController(1000.0, 0.0, 0.0, 0.0)});
  Alone run(model, Vec3(0.0, 0.0, -kG));
  ArticulationState& s = run.robot();
  ctl.restart(s);
  std::vector<Clipped> clipped;
  ASSERT_TRUE(ctl.command(0, {0.6}, clipped));
  ArticulationLoads loads;
  double most = 0.0;
  for (int n = 0; n < 20000; ++n) {
    ctl.efforts(s, n * kH, kH, loads.effort);
    most = std::max(most, std::abs(loads.effort(0)));
    run.step(loads);
  }
  EXPECT_EQ(most, 1.5);
  // It hangs where 1.5 N·m holds it: m g l sin q = 1.5.
  EXPECT_NEAR(s.q(0), std::asin(1.5 / (kG * 0.5)), 1e-6);
}

// A wheel about z (gravity has no torque about it), inertia I, under a
// velocity controller with gain p only: v_{n+1} = v_n + h p (ω − v_n) / I,
// from v_1 = h p ω / (2 I) (the first step's velocity is at its middle,
// §11.5), so v_n = ω (1 − (1 − h p / (2 I)) (1 − h p / I)^(n − 1)).
TEST(JointControllers, VelocityPidSpinsAWheelUpAsTheFirstOrderLaw) {
  ArticulationModel model = test::oneJoint(JointType::Continuous, "wheel", "axle", Vec3::Zero(), Vec3::UnitZ());
  const double I = 0.02, p = 0.5, omega = 3.0;
  model.links[1].mass.mass = 1.0;
  model.links[1].mass.I_C_F = Vec3(0.01, 0.01, I).asDiagonal();
  model.links[1].limits.effort = 100.0;
  checkArticulation(model);
  JointControllers ctl(model, {{"axle_velocity", ControlMode::kVelocity, {1}, {{p, 0.0, 0.0, 0.0}}}});
  Alone run(model, Vec3(0.0, 0.0, -kG));
  ArticulationState& s = run.robot();
  std::vector<Clipped> clipped;
  ASSERT_TRUE(ctl.command(0, {omega}, clipped));
  ArticulationLoads loads;
  for (int n = 1; n <= 200; ++n) {
    ctl.efforts(s, n * kH, kH, loads.effort);
    run.step(loads);
    ASSERT_NEAR(s.v(0), omega * (1.0 - (1.0 - 0.5 * kH * p / I) * std::pow(1.0 - kH * p / I, n - 1)), 1e-12) << n;
  }
}

TEST(JointControllers, CommandsAreClippedToTheLimitsAndNonFiniteOnesRefused) {
  ArticulationModel model = pendulum(5.0);
  model.links[1].limits.velocity = 2.0;
  JointControllers position(model, {positionController(1.0, 0.0, 0.0, 0.0)});
  std::vector<Clipped> clipped;
  ASSERT_TRUE(position.command(0, {4.0}, clipped));  // past upper = 3
  ASSERT_EQ(clipped.size(), 1u);
  EXPECT_EQ(clipped[0].joint, 1);
  EXPECT_EQ(clipped[0].what, "position range");
  ArticulationState s = restState(model);
  Eigen::VectorXd effort;
  position.efforts(s, 0.0, kH, effort);
  EXPECT_DOUBLE_EQ(effort(0), 3.0);  // p (3 − 0): the target held at 3
  // NaN, infinity and a wrong count change nothing.
  for (const std::vector<double>& bad :
       {std::vector<double>{std::nan("")}, std::vector<double>{std::numeric_limits<double>::infinity()},
        std::vector<double>{1.0, 2.0}, std::vector<double>{}}) {
    EXPECT_FALSE(position.command(0, bad, clipped));
  }
  position.efforts(s, 0.0, kH, effort);
  EXPECT_DOUBLE_EQ(effort(0), 3.0);
  JointControllers velocity(model, {{"v", ControlMode::kVelocity, {1}, {{1.0, 0.0, 0.0, 0.0}}}});
  clipped.clear();
  ASSERT_TRUE(velocity.command(0, {-7.0}, clipped));
  ASSERT_EQ(clipped.size(), 1u);
  EXPECT_EQ(clipped[0].what, "velocity");
  velocity.efforts(s, 0.0, kH, effort);
  EXPECT_DOUBLE_EQ(effort(0), -2.0);
}

// A joint with no <limit> (legal for a continuous joint) has no bound to
// clip a command to: a finite 1e308 made the PID's effort inf and its rate
// NaN. Commands beyond ranges.h's kMaxCommand* are refused, changing
// nothing; the largest taken keep every effort finite.
TEST(JointControllers, AbsurdCommandsAreRefusedAndUnlimitedJointsStayFinite) {
  ArticulationModel model = test::oneJoint(JointType::Continuous, "wheel", "axle", Vec3::Zero(), Vec3::UnitZ());
  model.links[1].mass.mass = 1.0;
  model.links[1].mass.I_C_F = Vec3(0.01, 0.01, 0.02).asDiagonal();
  checkArticulation(model);
  ASSERT_TRUE(std::isinf(model.links[1].limits.effort) && std::isinf(model.links[1].limits.velocity));
  const PidGains g{10.0, 1.0, 0.1, 1e3};
  for (const auto& [mode, absurd, most] :
       {std::tuple{ControlMode::kEffort, 1e7, 1e6}, std::tuple{ControlMode::kVelocity, 1e308, 1e4},
        std::tuple{ControlMode::kPosition, -1e308, 1e6}}) {
    JointControllers ctl(model, {{"c", mode, {1}, {g}}});
    std::vector<Clipped> clipped;
    EXPECT_FALSE(ctl.command(0, {absurd}, clipped));
    EXPECT_EQ(ctl.commandJoint(1, mode, absurd, clipped).rfind("absurd", 0), 0u);
    ASSERT_TRUE(ctl.command(0, {most}, clipped));
    ArticulationState s = restState(model);
    Eigen::VectorXd effort;
    for (int k = 1; k <= 50; ++k) {
      ctl.efforts(s, k * kH, kH, effort);
      ASSERT_TRUE(effort.allFinite()) << "mode " << static_cast<int>(mode) << ", step " << k;
    }
  }
}

TEST(JointControllers, RefusesWhatItCannotDrive) {
  ArticulationModel model = test::twoBars();
  model.links[1].limits.effort = 10.0;
  const auto refused = [&](std::vector<JointControllerSpec> specs, const std::string& expected) {
    try {
      JointControllers c(model, std::move(specs));
      ADD_FAILURE() << "accepted; expected: " << expected;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  refused({{"a", ControlMode::kEffort, {1}, {}}, {"b", ControlMode::kEffort, {1}, {}}},
          "controller 'b': joint 'elbow' is already controller 'a''s");
  refused({{"a", ControlMode::kPosition, {1}, {}}}, "controller 'a': needs PID gains");
  refused({{"a", ControlMode::kVelocity, {1}, {{-1.0, 0.0, 0.0, 0.0}}}}, "must be finite and >= 0");
  refused({{"a", ControlMode::kEffort, {0}, {}}}, "joint index 0");
  refused({{"a", ControlMode::kEffort, {}, {}}}, "names no joint");
  ArticulationModel gripper = test::twoBars();
  gripper.links[1].mimic.joint = 1;  // follows itself: only the check's shape matters here
  try {
    JointControllers c(gripper, {{"g", ControlMode::kEffort, {1}, {}}});
    ADD_FAILURE() << "a mimic joint was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mimics"), std::string::npos) << e.what();
  }
}

// One joint of a group is set alone; the others keep their targets; a
// joint nobody owns, another mode or NaN is refused and changes nothing.
TEST(JointControllers, OneJointOfAGroupIsSetAlone) {
  ArticulationModel model = test::twoBars();
  model.links[1].limits.effort = 5.0;
  JointControllers ctl(model, {{"all", ControlMode::kEffort, {1}, {}}});
  std::vector<Clipped> clipped;
  ArticulationState s = restState(model);
  Eigen::VectorXd effort;
  EXPECT_EQ(ctl.commandJoint(1, ControlMode::kEffort, 9.0, clipped), "");
  ASSERT_EQ(clipped.size(), 1u);  // held to 5
  ctl.efforts(s, 0.0, kH, effort);
  EXPECT_EQ(effort(0), 5.0);
  EXPECT_EQ(ctl.commandJoint(1, ControlMode::kPosition, 1.0, clipped),
            "its controller 'all' takes effort, not position");
  EXPECT_EQ(ctl.commandJoint(1, ControlMode::kEffort, std::nan(""), clipped), "not finite");
  JointControllers none(model, {});
  EXPECT_EQ(none.commandJoint(1, ControlMode::kEffort, 1.0, clipped), "no controller owns it");
  ctl.efforts(s, 0.0, kH, effort);
  EXPECT_EQ(effort(0), 5.0);
}

// A reset: integrals go, a position controller holds where the robot now is.
TEST(JointControllers, RestartHoldsTheJointsWhereTheyAre) {
  const ArticulationModel model = pendulum(20.0);
  JointControllers ctl(model, {positionController(100.0, 200.0, 10.0, 10.0)});
  Alone run(model, Vec3(0.0, 0.0, 0.0));
  ArticulationState& s = run.robot();
  std::vector<Clipped> clipped;
  ASSERT_TRUE(ctl.command(0, {0.6}, clipped));
  ArticulationLoads loads;
  for (int n = 0; n < 3000; ++n) {
    ctl.efforts(s, n * kH, kH, loads.effort);
    run.step(loads);  // no gravity: at rest means no effort
  }
  ArticulationState put = restState(model);
  put.q(0) = -0.4;
  ctl.restart(put);
  ctl.efforts(put, 0.0, kH, loads.effort);
  EXPECT_EQ(loads.effort(0), 0.0);  // no error, no integral: nothing drives it back to 0.6
}

// A trajectory controller on the pendulum, against gravity: at each
// point's time the bob is where the point says (PID on the error from the
// setpoint and on the velocity error, ros_controllers' effort joint).
TEST(JointControllers, ATrajectoryReachesItsPointsAtTheirTimes) {
  const ArticulationModel model = pendulum(20.0);
  JointControllers ctl(model, {{"arm", ControlMode::kTrajectory, {1}, {{400.0, 400.0, 40.0, 10.0}}}});
  Alone run(model, Vec3(0.0, 0.0, -kG));
  ArticulationState& s = run.robot();
  ctl.restart(s);
  std::vector<Clipped> clipped;
  int dropped = -1;
  const std::vector<TrajectoryPoint> points{{1.0, {0.4}, {0.3}, {}}, {2.0, {0.8}, {0.0}, {}}, {3.0, {0.2}, {}, {}}};
  ASSERT_EQ(ctl.followTrajectory(0, 0.0, 0.0, points, clipped, dropped), "");
  EXPECT_EQ(dropped, 0);
  ArticulationLoads loads;
  std::vector<double> reached;
  for (int n = 0; n < 6000; ++n) {
    if (n % 1000 == 0 && n > 0 && n <= 3000) reached.push_back(s.q(0));
    ctl.efforts(s, n * kH, kH, loads.effort);
    run.step(loads);
  }
  reached.push_back(s.q(0));
  ASSERT_EQ(reached.size(), 4u);
  EXPECT_NEAR(reached[0], 0.4, 0.01);
  EXPECT_NEAR(reached[1], 0.8, 0.01);
  EXPECT_NEAR(reached[2], 0.2, 0.01);
  EXPECT_NEAR(reached[3], 0.2, 1e-3);  // held 3 s after the last point, the integral at work
  std::printf("pendulum trajectory: %.5f %.5f %.5f rad at 1, 2, 3 s for 0.4, 0.8, 0.2; %.6f at 6 s\n", reached[0],
              reached[1], reached[2], reached[3]);
}

// Trajectory controllers take trajectories only; positions past the range
// are held to it; a restart holds where the joints are.
TEST(JointControllers, TrajectoriesAreCheckedClippedAndRestarted) {
  const ArticulationModel model = pendulum(20.0);
  JointControllers ctl(model, {{"arm", ControlMode::kTrajectory, {1}, {{10.0, 0.0, 0.0, 0.0}}}});
  JointControllers position(model, {positionController(1.0, 0.0, 0.0, 0.0)});
  std::vector<Clipped> clipped;
  int dropped = 0;
  EXPECT_FALSE(ctl.command(0, {0.5}, clipped));
  EXPECT_EQ(ctl.commandJoint(1, ControlMode::kPosition, 0.5, clipped),
            "its controller 'arm' takes trajectories, not position");
  EXPECT_EQ(position.followTrajectory(0, 0.0, 0.0, {{1.0, {0.5}, {}, {}}}, clipped, dropped),
            "controller 'hinge_position' takes no trajectories");
  EXPECT_EQ(ctl.followTrajectory(0, 0.0, 0.0, {{1.0, {0.5, 1.0}, {}, {}}}, clipped, dropped),
            "points[0].positions has 2 values for 1 joints");
  EXPECT_EQ(ctl.followTrajectory(0, 5.0, 0.0, {{1.0, {0.5}, {}, {}}}, clipped, dropped).rfind("every point is past", 0),
            0u);
  EXPECT_TRUE(clipped.empty());
  ASSERT_EQ(ctl.followTrajectory(0, 0.0, 0.0, {{1.0, {4.0}, {}, {}}}, clipped, dropped), "");
  ASSERT_EQ(clipped.size(), 1u);
  EXPECT_EQ(clipped[0].what, "position range");
  EXPECT_EQ(ctl.trajectory(0).sample(1.0, 0).position, 3.0);  // held at the upper limit
  ArticulationState put = restState(model);
  put.q(0) = -0.4;
  ctl.restart(put);
  Eigen::VectorXd effort;
  ctl.efforts(put, 0.5, kH, effort);
  EXPECT_EQ(effort(0), 0.0);  // holding where it was put
  EXPECT_EQ(ctl.trajectory(0).sample(1.0, 0).position, -0.4);
}

}  // namespace
}  // namespace rigid_body_sim::core
