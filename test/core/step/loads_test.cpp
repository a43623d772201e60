// Impulses and wrenches at a point, against hand computation.
#include "rigid_body_sim/core/step/loads.h"

#include <gtest/gtest.h>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

/// World-frame inertia I_W = R_WL I_L R_WLᵀ of a body posed at q_WL.
Mat3 worldInertia(const core::BodyModel& b, const Quat& q_WL) {
  const Mat3 R = q_WL.toRotationMatrix();
  return R * b.I_C_L * R.transpose();
}

/// A body whose inertia is not diagonal in its link frame, so the principal
/// frame differs from the link frame: the conversions are exercised.
core::BodySpec skewedBody() {
  core::BodySpec b;
  b.name = "skewed";
  b.mass = 2.5;
  b.I_C_L << 0.30, 0.02, -0.01,  //
      0.02, 0.20, 0.015,         //
      -0.01, 0.015, 0.25;
  b.p_LC = Vec3(0.1, -0.05, 0.2);
  return b;
}

const Quat kTilted = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));

core::State posed(const core::Model& model, const Vec3& w_W = Vec3::Zero()) {
  core::LinkState link;
  link.q_WL = kTilted;
  link.w_W = w_W;
  return stateOf(model, link);
}

TEST(Impulse, AtTheCentreOfMassOnlyTranslates) {
  const core::Model model(spec(skewedBody(), 1e-3, Vec3::Zero()));
  core::State s = posed(model);
  core::applyImpulse(model.body(0), s.bodies[0], {Vec3(1.0, -2.0, 0.5), Vec3::Zero(), Vec3::Zero()});
  EXPECT_LT((s.bodies[0].v_WB - Vec3(1.0, -2.0, 0.5) / 2.5).norm(), 1e-15);
  EXPECT_LT(s.bodies[0].w_B.norm(), 1e-15);
}

TEST(Impulse, AtAWorldPointTurnsTheBody) {
  const core::Model model(spec(skewedBody(), 1e-3, Vec3::Zero()));
  core::State s = posed(model, Vec3(0.1, 0.2, -0.3));
  const core::BodyState before = s.bodies[0];
  const Vec3 J(0.3, 1.0, -0.4), r(0.2, -0.1, 0.05), H(0.0, 0.01, 0.02);
  core::applyImpulse(model.body(0), s.bodies[0], {J, H, r, core::Frame::kWorld});
  // Δv = J/M, Δω = I_W⁻¹ (r × J + H)
  const Vec3 dw = worldInertia(model.body(0), kTilted).inverse() * (r.cross(J) + H);
  EXPECT_LT((s.bodies[0].v_WB - before.v_WB - J / 2.5).norm(), 1e-14);
  EXPECT_LT((core::angularVelocityWorld(s.bodies[0]) - core::angularVelocityWorld(before) - dw).norm(), 1e-12);
}

TEST(Impulse, InTheBodyFrameTurnsWithTheBody) {
  const core::Model model(spec(skewedBody(), 1e-3, Vec3::Zero()));
  core::State s = posed(model);
  const Vec3 J_L(0.0, 0.0, 1.0), r_L(0.3, 0.0, 0.0);
  core::applyImpulse(model.body(0), s.bodies[0], {J_L, Vec3::Zero(), r_L, core::Frame::kBody});
  const Mat3 R = kTilted.toRotationMatrix();
  const Vec3 dw = worldInertia(model.body(0), kTilted).inverse() * (R * r_L).cross(R * J_L);
  EXPECT_LT((s.bodies[0].v_WB - R * J_L / 2.5).norm(), 1e-14);
  EXPECT_LT((core::angularVelocityWorld(s.bodies[0]) - dw).norm(), 1e-12);
}

TEST(Wrench, AtAPointOverOneStep) {
  // Notes mode (no gyroscopic term): exactly Δv = Δt F/M, Δω = Δt I_W⁻¹ (r × F + τ).
  const double dt = 1e-3;
  const core::Model model(spec(skewedBody(), dt, Vec3::Zero(), /*gyroscopic=*/false));
  core::State s = posed(model);
  const Vec3 F(2.0, 0.0, -1.0), tau(0.0, 0.1, 0.0), r(0.0, 0.2, 0.1);
  core::Loads loads(1);
  core::addWrench(model.body(0), loads[0], {F, tau, r, core::Frame::kWorld});
  core::step(model, s, loads);
  const Vec3 dw = dt * worldInertia(model.body(0), kTilted).inverse() * (r.cross(F) + tau);
  EXPECT_LT((s.bodies[0].v_WB - dt * F / 2.5).norm(), 1e-15);
  EXPECT_LT((core::angularVelocityWorld(s.bodies[0]) - dw).norm() / dw.norm(), 1e-12);
}

TEST(Wrench, GyroscopicStepAgreesToSecondOrder) {
  // From rest the gyroscopic term is O(Δt²): the first step matches the hand value closely.
  const double dt = 1e-3;
  const core::Model model(spec(skewedBody(), dt, Vec3::Zero()));
  core::State s = posed(model);
  const Vec3 F(0.0, 1.0, 0.0), r(0.3, 0.0, 0.0);
  core::Loads loads(1);
  core::addWrench(model.body(0), loads[0], {F, Vec3::Zero(), r, core::Frame::kWorld});
  core::step(model, s, loads);
  const Vec3 dw = dt * worldInertia(model.body(0), kTilted).inverse() * r.cross(F);
  EXPECT_LT((core::angularVelocityWorld(s.bodies[0]) - dw).norm() / dw.norm(), 1e-5);
}

TEST(Wrench, BodyFrameForceFollowsTheRotatedAxis) {
  // gazebo_ros_pkgs #310: a body-frame force on a body turned 90° about z
  // must push along world +y, not world +x.
  const double dt = 1e-3;
  const core::Model model(spec(shippedBox(), dt, Vec3::Zero()));
  core::LinkState link;
  link.q_WL = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
  core::State s = stateOf(model, link);
  core::Loads loads(1);
  core::addWrench(model.body(0), loads[0], {Vec3(1.0, 0.0, 0.0), Vec3::Zero(), Vec3::Zero(), core::Frame::kBody});
  for (int n = 0; n < 1000; ++n) core::step(model, s, loads);
  EXPECT_NEAR(s.bodies[0].v_WB.y(), 1.0, 1e-12);  // F t / M
  EXPECT_NEAR(s.bodies[0].v_WB.x(), 0.0, 1e-12);
}

TEST(Wrench, TwoWrenchesAdd) {
  const core::Model model(spec(skewedBody(), 1e-3, Vec3::Zero()));
  core::BodyLoad both, first, second;
  const core::Wrench a{Vec3(1, 0, 0), Vec3(0, 0, 0.1), Vec3(0, 0.1, 0), core::Frame::kWorld};
  const core::Wrench b{Vec3(0, 2, 0), Vec3::Zero(), Vec3(0.2, 0, 0), core::Frame::kBody};
  core::addWrench(model.body(0), both, a);
  core::addWrench(model.body(0), both, b);
  core::addWrench(model.body(0), first, a);
  core::addWrench(model.body(0), second, b);
  EXPECT_EQ(both.force_W, first.force_W + second.force_W);
  EXPECT_EQ(both.torque_W, first.torque_W + second.torque_W);
  EXPECT_EQ(both.force_B, first.force_B + second.force_B);
  EXPECT_EQ(both.torque_B, first.torque_B + second.torque_B);
  // Torque about the centre of mass: τ + r × F.
  EXPECT_LT((first.torque_W - Vec3(0, 0, 0.1) - Vec3(0, 0.1, 0).cross(Vec3(1, 0, 0))).norm(), 1e-15);
}

}  // namespace
}  // namespace rigid_body_sim::test
