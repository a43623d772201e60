// The integration stages (src/core/integration.cpp) one function at a time,
// against closed forms (docs/physics.md §5.2–5.4, §5.6–5.7).
#include "step/integration.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../../test_util.h"

namespace rigid_body_sim::test {
namespace {

/// The shipped box in free space (no scene), gravity g.
core::Model freeBox(const Vec3& g, double linear_drag = 0.0, double angular_drag = 0.0) {
  core::ModelSpec ms = spec(shippedBox(), 1e-3, g);
  ms.damping.linear_drag = linear_drag;
  ms.damping.angular_drag = angular_drag;
  return core::Model(ms);
}

double energy(const core::BodyModel& b, const Vec3& w_B) { return 0.5 * w_B.dot(b.inertia_B.cwiseProduct(w_B)); }

TEST(Integration, ForcesAreDragPlusTheLoadsInTheirFrames) {
  const core::Model model = freeBox(Vec3::Zero(), 0.3, 0.02);
  core::State s = core::restState(model);
  core::BodyState& b = s.bodies[0];
  b.q_WB = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));  // body x along world y
  b.v_WB = Vec3(1, 2, 3);
  b.w_B = Vec3(0.5, 0, 0);
  core::BodyLoad load;
  load.force_W = Vec3(0, 0, 4);
  load.force_B = Vec3(1, 0, 0);   // world (0, 1, 0)
  load.torque_W = Vec3(0, 0, 2);  // body z is world z
  load.torque_B = Vec3(0, 1, 0);
  const core::Workspace ws;
  const core::NetLoad net = core::accumulateForces(model, s, &load, ws, 0);
  // F = −σ v + F_W + R F_B;  τ_B = −σ_ω ω + τ_B + Rᵀ τ_W.
  EXPECT_LT((net.force_W - (-0.3 * Vec3(1, 2, 3) + Vec3(0, 0, 4) + Vec3(0, 1, 0))).norm(), 1e-15);
  EXPECT_LT((net.torque_B - (-0.02 * Vec3(0.5, 0, 0) + Vec3(0, 1, 0) + Vec3(0, 0, 2))).norm(), 1e-15);
}

TEST(Integration, VelocitiesTakeGravityAsAnAccelerationAndTorqueInTheBodyFrame) {
  const Vec3 g(0, 0, -9.81);
  const core::Model model = freeBox(g);
  const core::BodyModel& b = model.body(0);
  core::BodyState s;
  s.v_WB = Vec3(1, 0, 0);
  core::NetLoad net;
  net.force_W = Vec3(2, 0, 0);
  net.torque_B = Vec3(0.1, 0.2, 0.3);
  const double h = 1e-3;
  core::integrateVelocity(model, b, net, h, s);
  EXPECT_EQ(s.v_WB, Vec3(1, 0, 0) + h * (g + b.inv_mass * Vec3(2, 0, 0)));
  EXPECT_EQ(s.w_B, h * b.inv_inertia_B.cwiseProduct(Vec3(0.1, 0.2, 0.3)));
}

TEST(Integration, DampingIsADecayRateWhateverTheStep) {
  core::ModelSpec ms = spec(shippedBox(), 1e-3, Vec3::Zero());
  ms.damping.linear = 2.0;
  ms.damping.angular = 0.5;
  const core::Model model(ms);
  for (const double h : {1e-3, 0.25e-3}) {  // the model's step, and a half of a half (log-barrier sub-steps)
    core::BodyState s;
    s.v_WB = Vec3(1, 0, 0);
    s.w_B = Vec3(0, 0, 4);
    const int n = static_cast<int>(std::lround(0.5 / h));
    for (int k = 0; k < n; ++k) core::applyDamping(model, h, s);
    EXPECT_NEAR(s.v_WB.x(), std::exp(-2.0 * 0.5), 1e-12);  // v(t) = v₀ e^(−k t)
    EXPECT_NEAR(s.w_B.z(), 4.0 * std::exp(-0.5 * 0.5), 1e-12);
  }
}

TEST(Integration, TheGyroscopicStepConservesEnergyAndMomentumEvenWhenItSubsteps) {
  const core::Model model = freeBox(Vec3::Zero());
  const core::BodyModel& b = model.body(0);
  // 3 rad/s contracts in a few passes; 3000 rad/s at 1 ms cannot, and sub-steps.
  for (const double speed : {3.0, 3000.0}) {
    core::BodyState s;
    s.w_B = speed * Vec3(0.3, 1.0, 0.2).normalized();
    const double e0 = energy(b, s.w_B);
    const double L0 = b.inertia_B.cwiseProduct(s.w_B).norm();
    const Quat increment = core::gyroscopicRotation(model, b, 1e-3, s);
    EXPECT_NEAR(energy(b, s.w_B) / e0, 1.0, 1e-12) << speed;
    EXPECT_NEAR(b.inertia_B.cwiseProduct(s.w_B).norm() / L0, 1.0, 1e-12) << speed;
    if (speed < 10.0) {  // one contracting pass: it turns by about |ω| h
      EXPECT_NEAR(2.0 * std::atan(increment.vec().norm() / increment.w()), speed * 1e-3, 1e-3 * speed * 1e-3);
    }
  }
}

TEST(Integration, WithoutTheGyroscopicTermTheRotationIsTheAngularVelocity) {
  core::ModelSpec ms = spec(shippedBox(), 1e-3, Vec3::Zero(), /*gyroscopic=*/false);
  const core::Model model(ms);
  core::BodyState s;
  s.w_B = Vec3(1, 2, 3);
  const Quat increment = core::gyroscopicRotation(model, model.body(0), 1e-3, s);
  EXPECT_EQ(increment.coeffs(), Quat(1.0, 0.5e-3, 1e-3, 1.5e-3).coeffs());  // [1, h/2 ω]
  EXPECT_EQ(s.w_B, Vec3(1, 2, 3));
}

TEST(Integration, PositionsMoveByTheNewVelocityAndOrientationsStayUnit) {
  const core::Model model = freeBox(Vec3::Zero());
  core::BodyState s;
  s.v_WB = Vec3(1, -2, 0.5);
  s.w_B = Vec3(0, 0, 2 * M_PI);  // one turn a second about z
  for (int k = 0; k < 250; ++k) core::integrateBody(model, model.body(0), 1e-3, s);
  EXPECT_LT((s.p_WB - 0.25 * Vec3(1, -2, 0.5)).norm(), 1e-12);
  EXPECT_NEAR(s.q_WB.norm(), 1.0, 1e-15);
  // About a principal axis each step turns by the Cayley map's 2 atan(h ω / 2) (§5.7), a quarter turn to O(h²).
  const double turned = 250 * 2.0 * std::atan(0.5e-3 * 2 * M_PI);
  EXPECT_LT(s.q_WB.angularDistance(Quat(Eigen::AngleAxisd(turned, Vec3::UnitZ()))), 1e-12);
  EXPECT_NEAR(turned, M_PI / 2, 1e-5);
}

TEST(Integration, TheStagesSkipSleepersAndCountStillTime) {
  core::ModelSpec ms = spec(shippedBox(), 1e-3, Vec3(0, 0, -9.81));
  core::BodySpec second = shippedBox();
  second.name = "other";
  ms.bodies.push_back(second);
  const core::Model model(ms);
  core::State s = core::restState(model);
  s.bodies[1].asleep = true;
  core::Workspace ws;
  core::integrateVelocities(model, s, {}, 1e-3, ws);
  core::integratePositions(model, s, 1e-3, ws);
  EXPECT_EQ(s.bodies[0].v_WB, 1e-3 * Vec3(0, 0, -9.81));
  EXPECT_EQ(s.bodies[0].still_time, 1e-3);  // slower than the sleep speed after one step
  EXPECT_EQ(s.bodies[1].v_WB, Vec3::Zero());
  EXPECT_EQ(s.bodies[1].p_WB, core::restState(model).bodies[1].p_WB);
}

}  // namespace
}  // namespace rigid_body_sim::test
