// A force-torque sensor on a joint (core/devices/force_torque.h, docs/physics.md
// §10.10): what the joint carries onto its child link against closed forms, a
// rod held still and a rod swinging free, and the wrench of a step's contacts.
#include "rigid_body_sim/core/devices/force_torque.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../articulations/articulation_models.h"

namespace rigid_body_sim::test {
namespace {

using core::Vec6;

constexpr double kG = 9.81, kMass = 2.0, kHalf = 0.2;  // kg; the rod's centre is kHalf m from the pivot
const Vec3 kSize(0.4, 0.04, 0.04);

/// A 2 kg rod of 0.4 m on a pivot about y, 1 m up, its centre 0.2 m along its x.
ArticulationModel rod() {
  ArticulationModel model = oneJoint(JointType::Revolute, "rod", "pivot", Vec3(0.0, 0.0, 1.0), Vec3::UnitY());
  model.links[1].mass = boxMass(kMass, kSize, Vec3(kHalf, 0.0, 0.0));
  model.links[1].limits.lower = -10.0;
  model.links[1].limits.upper = 10.0;
  core::checkArticulation(model);
  return model;
}

core::ArticulationState at(const ArticulationModel& model, double q, double v) {
  core::ArticulationState s = core::restState(model);
  s.q(0) = q;
  s.v(0) = v;
  return s;
}

/// Gravity in the rod's axes at angle q (its x turns to (cos q, 0, -sin q) in the world).
Vec3 gravityInRod(double q) { return {kG * std::sin(q), 0.0, -kG * std::cos(q)}; }

TEST(ForceTorque, ARodHeldStillLoadsItsJointWithItsWeightAndItsMoment) {
  const ArticulationModel model = rod();
  const double q = 0.3;
  const core::ArticulationState s = at(model, q, 0.0);
  const core::ArticulationKinematics kin = core::kinematics(model, s);
  core::ForceTorqueSensor sensor(1, {});
  const Eigen::VectorXd u = core::generalizedVelocity(model, s);
  const Vec6 w = sensor.reading(model, kin, u, u, 1e-3, Vec3(0.0, 0.0, -kG), {});
  // The joint holds the weight up, and its moment about the pivot: -c x m g.
  const Vec3 force = -kMass * gravityInRod(q);
  const Vec3 torque = -Vec3(kHalf, 0.0, 0.0).cross(kMass * gravityInRod(q));
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(w(3 + k), force(k), 1e-12) << k;
    EXPECT_NEAR(w(k), torque(k), 1e-12) << k;
  }
  EXPECT_NEAR(w(1), -kMass * kG * kHalf * std::cos(q), 1e-12);  // about the axis: what a motor must give
}

TEST(ForceTorque, ARodSwingingFreeLoadsItsJointWithItsCentripetalAndTangentialForceAlone) {
  const ArticulationModel model = rod();
  const double q = 0.3, omega = 2.0, h = 1e-3;
  const core::ArticulationState s = at(model, q, omega);
  const Vec3 g(0.0, 0.0, -kG);
  const Eigen::VectorXd udot = core::forwardDynamics(model, s, Eigen::VectorXd::Zero(1), g);
  // Closed form: gravity's moment about the pivot over its inertia there.
  const double inertia = kMass * (kSize.x() * kSize.x() + kSize.z() * kSize.z()) / 12.0 + kMass * kHalf * kHalf;
  const double alpha = kMass * kG * kHalf * std::cos(q) / inertia;
  ASSERT_NEAR(udot(0), alpha, 1e-12);
  const Eigen::VectorXd u = core::generalizedVelocity(model, s);
  core::ForceTorqueSensor sensor(1, {});
  const Vec6 w = sensor.reading(model, core::kinematics(model, s), u, u - h * udot, h, g, {});
  // The centre's acceleration in the rod's axes: -w² l along x, -alpha l along z.
  const Vec3 a_c(-omega * omega * kHalf, 0.0, -alpha * kHalf);
  const Vec3 force = kMass * (a_c - gravityInRod(q));
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(w(3 + k), force(k), 1e-9) << k;
    EXPECT_NEAR(w(k), 0.0, 1e-9) << k;  // a free pivot carries no moment
  }
}

TEST(ForceTorque, AStepsContactsLoadTheLinksTheyTouchAtTheirPoints) {
  core::SceneRobot robot{"arm", rod(), 2, {1}};  // its rod is body 2 of the world
  const core::ArticulationState s = at(robot.model, 0.5, 0.0);
  const core::ArticulationKinematics kin = core::kinematics(robot.model, s);
  std::vector<core::BodyState> bodies(3);
  const core::Placement& X = kin.X_WL[1];
  bodies[2].p_WB = X.p_PC + X.R_PC * Vec3(kHalf, 0.0, 0.0);
  // One push on the rod from the ground (1e-2 N·s up, 1e-3 along x, in a
  // 1 ms step), and one from body 0 sitting on it (the rod is its `other`).
  const Vec3 p1 = X.p_PC + X.R_PC * Vec3(0.3, 0.0, 0.02), p2 = X.p_PC + X.R_PC * Vec3(0.1, 0.0, 0.02);
  core::Contact ground;
  ground.body = 2;
  ground.normal_W = Vec3::UnitZ();
  ground.normal_impulse = 1e-2;
  ground.tangent_impulse_W = Vec3(1e-3, 0.0, 0.0);
  ground.r_W = p1 - bodies[2].p_WB;
  core::Contact box;
  box.body = 0;
  box.other = 2;
  box.normal_W = Vec3::UnitZ();  // toward body 0: up, so down on the rod
  box.normal_impulse = 5e-3;
  box.r_other_W = p2 - bodies[2].p_WB;
  const std::vector<Vec6> w = core::contactWrenches_L(robot, kin, bodies, {ground, box}, 1e-3);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_TRUE(w[0].isZero());
  const Vec3 f1 = X.R_PC.transpose() * Vec3(1.0, 0.0, 10.0), f2 = X.R_PC.transpose() * Vec3(0.0, 0.0, -5.0);
  const Vec3 moment = Vec3(0.3, 0.0, 0.02).cross(f1) + Vec3(0.1, 0.0, 0.02).cross(f2);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(w[1](3 + k), (f1 + f2)(k), 1e-12) << k;
    EXPECT_NEAR(w[1](k), moment(k), 1e-12) << k;
  }
}

TEST(ForceTorque, ItsNoiseIsSeededAndOfItsSigmaOnEachNumber) {
  const ArticulationModel model = rod();
  const core::ArticulationState s = at(model, 0.0, 0.0);
  const core::ArticulationKinematics kin = core::kinematics(model, s);
  const Eigen::VectorXd u = core::generalizedVelocity(model, s);
  core::ForceTorqueSensor a(1, {0.5, 3}), b(1, {0.5, 3}), exact(1, {});
  const Vec6 truth = exact.reading(model, kin, u, u, 1e-3, Vec3(0.0, 0.0, -kG), {});
  Vec6 sum = Vec6::Zero(), squares = Vec6::Zero();
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const Vec6 x = a.reading(model, kin, u, u, 1e-3, Vec3(0.0, 0.0, -kG), {});
    EXPECT_EQ(x, b.reading(model, kin, u, u, 1e-3, Vec3(0.0, 0.0, -kG), {}));
    sum += x - truth;
    squares += (x - truth).cwiseAbs2();
  }
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(sum(k) / n, 0.0, 0.02) << k;
    EXPECT_NEAR(std::sqrt(squares(k) / n), 0.5, 0.01) << k;
  }
  // A reading due but not taken (nobody listened) leaves the next one as it would have been.
  core::ForceTorqueSensor every(1, {0.5, 8}), late(1, {0.5, 8});
  const Vec6 first = every.reading(model, kin, u, u, 1e-3, Vec3(0.0, 0.0, -kG), {});
  const Vec6 second = every.reading(model, kin, u, u, 1e-3, Vec3(0.0, 0.0, -kG), {});
  late.pass();
  EXPECT_EQ(late.reading(model, kin, u, u, 1e-3, Vec3(0.0, 0.0, -kG), {}), second);
  EXPECT_NE(first, second);
  every.restart();
  EXPECT_EQ(every.reading(model, kin, u, u, 1e-3, Vec3(0.0, 0.0, -kG), {}), first);
  EXPECT_THROW(core::ForceTorqueSensor(1, {-1.0, 0}), std::invalid_argument);
  EXPECT_THROW(core::ForceTorqueSensor(0, {}), std::invalid_argument);
}

}  // namespace
}  // namespace rigid_body_sim::test
