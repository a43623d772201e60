// Translational motion and the step's bookkeeping, against closed forms.
#include "rigid_body_sim/core/step/step.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/diagnostics.h"

namespace rigid_body_sim::test {
namespace {

const Vec3 kGravity(0.0, 0.0, -9.81);

TEST(FreeFall, FollowsTheEulerCromerRecurrence) {
  const double dt = 1e-3;
  const core::Model model(spec(shippedBox(), dt, kGravity));
  core::LinkState start;
  start.p_WL = Vec3(0.5, -1.0, 10.0);
  start.v_WL = Vec3(1.0, 2.0, 3.0);
  core::State s = stateOf(model, start);
  for (int n = 1; n <= 2000; ++n) {
    core::step(model, s);
    // v_n = v₀ + n Δt g;  x_n = x₀ + n Δt v₀ + Δt² g n(n+1)/2 (x uses v_{n+1}).
    const Vec3 v = start.v_WL + n * dt * kGravity;
    const Vec3 x = start.p_WL + n * dt * start.v_WL + dt * dt * kGravity * (n * (n + 1) / 2.0);
    ASSERT_LT((s.bodies[0].v_WB - v).norm(), 1e-12) << "step " << n;
    ASSERT_LT((s.bodies[0].p_WB - x).norm(), 1e-12) << "step " << n;
  }
  EXPECT_NEAR(s.time, 2.0, 1e-12);  // time accumulates Δt: rounding only
}

TEST(FreeFall, MatchesTheClosedFormWithinTheFirstOrderTerm) {
  for (double dt : {1e-3, 1e-2}) {
    const core::Model model(spec(shippedBox(), dt, kGravity));
    core::LinkState start;
    start.p_WL = Vec3(0, 0, 100);
    core::State s = stateOf(model, start);
    const int steps = static_cast<int>(std::lround(3.0 / dt));
    for (int n = 0; n < steps; ++n) core::step(model, s);
    const double t = s.time;
    const double exact = 100.0 - 0.5 * 9.81 * t * t;
    // Euler-Cromer falls ahead of the closed form by exactly ½ g Δt t.
    EXPECT_NEAR(s.bodies[0].p_WB.z() - exact, -0.5 * 9.81 * dt * t, 1e-9) << "dt " << dt;
    EXPECT_NEAR(s.bodies[0].v_WB.z(), -9.81 * t, 1e-10);
  }
}

TEST(Projectile, ReachesTheApexOfTheClosedForm) {
  const double dt = 1e-3;
  const Vec3 v0(3.0, 0.0, 5.0);
  const core::Model model(spec(shippedBox(), dt, kGravity));
  core::LinkState start;
  start.v_WL = v0;
  core::State s = stateOf(model, start);
  double apex = 0.0, t_apex = 0.0, x_apex = 0.0;
  while (s.bodies[0].v_WB.z() > -v0.z()) {
    core::step(model, s);
    if (s.bodies[0].p_WB.z() > apex) {
      apex = s.bodies[0].p_WB.z();
      t_apex = s.time;
      x_apex = s.bodies[0].p_WB.x();
    }
  }
  const double g = 9.81;
  // h = v_z²/(2g) at t = v_z/g; the discrete apex lies within v_z Δt below.
  EXPECT_LT(apex, v0.z() * v0.z() / (2 * g));
  EXPECT_NEAR(apex, v0.z() * v0.z() / (2 * g), v0.z() * dt);
  EXPECT_NEAR(t_apex, v0.z() / g, dt);
  EXPECT_NEAR(x_apex, v0.x() * t_apex, 1e-12);
}

TEST(Damping, DecayRateIsIndependentOfTheTimeStep) {
  core::BodySpec body = shippedBox();
  for (double dt : {1e-3, 1e-2, 0.1}) {
    core::ModelSpec ms = spec(body, dt, Vec3::Zero(), /*gyroscopic=*/false);
    ms.damping.linear = 0.7;
    ms.damping.angular = 1.3;
    const core::Model model(ms);
    core::LinkState start;
    start.v_WL = Vec3(2.0, 0.0, 0.0);
    start.w_W = Vec3(0.0, 0.0, 4.0);
    core::State s = stateOf(model, start);
    const int steps = static_cast<int>(std::lround(1.0 / dt));
    for (int n = 0; n < steps; ++n) core::step(model, s);
    EXPECT_NEAR(s.bodies[0].v_WB.x(), 2.0 * std::exp(-0.7), 1e-12) << "dt " << dt;
    EXPECT_NEAR(s.bodies[0].w_B.z(), 4.0 * std::exp(-1.3), 1e-12) << "dt " << dt;
  }
}

TEST(Damping, DragForceFollowsTheNotesRecurrence) {
  const double dt = 1e-2, sigma = 0.5, mass = 2.0;
  core::BodySpec body = shippedBox();
  body.mass = mass;
  core::ModelSpec ms = spec(body, dt, Vec3::Zero());
  ms.damping.linear_drag = sigma;
  const core::Model model(ms);
  core::LinkState start;
  start.v_WL = Vec3(0.0, 3.0, 0.0);
  core::State s = stateOf(model, start);
  for (int n = 1; n <= 100; ++n) {
    core::step(model, s);
    // v_{n+1} = v_n + Δt (−σ v_n)/M = (1 − σΔt/M)ⁿ v₀
    EXPECT_NEAR(s.bodies[0].v_WB.y(), 3.0 * std::pow(1.0 - sigma * dt / mass, n), 1e-12);
  }
}

TEST(Quaternion, StaysUnitWhileTumbling) {
  core::BodySpec body = shippedBox();
  body.I_C_L(0, 1) = body.I_C_L(1, 0) = 0.001;  // off the principal axes as well
  const core::Model model(spec(body, 1e-2, kGravity));
  core::LinkState start;
  start.w_W = Vec3(7.0, -3.0, 11.0);
  core::State s = stateOf(model, start);
  for (int n = 0; n < 10000; ++n) {
    core::step(model, s);
    ASSERT_NEAR(s.bodies[0].q_WB.norm(), 1.0, 1e-15) << "step " << n;
  }
}

TEST(Determinism, TwoRunsAreBitIdentical) {
  core::BodySpec body = shippedBox();
  body.I_C_L(0, 2) = body.I_C_L(2, 0) = 0.0007;
  core::ModelSpec ms = spec(body, 1e-3, kGravity);
  ms.damping.angular = 0.01;
  const core::Model model(ms);
  core::LinkState start;
  start.w_W = Vec3(0.3, 4.0, -0.2);
  start.v_WL = Vec3(1.0, 0.0, 2.0);
  core::Loads loads(1);
  core::addWrench(model.body(0), loads[0], {Vec3(0.1, 0, 0), Vec3(0, 0, 0.01), Vec3(0.1, 0, 0), core::Frame::kBody});
  auto run = [&] {
    core::State s = stateOf(model, start);
    for (int n = 0; n < 20000; ++n) core::step(model, s, loads);
    return s;
  };
  const core::State a = run();
  const core::State b = run();
  EXPECT_TRUE(bitIdentical(a, b));
}

TEST(Step, LargeSpinStaysFiniteAndConserving) {
  // Δt |ω| = 10 rad per step: the midpoint iteration cannot contract in one
  // step, so the step sub-divides; the state stays finite and the invariants hold.
  const core::Model model(spec(shippedBox(), 1e-2, Vec3::Zero()));
  core::LinkState start;
  start.w_W = Vec3(30.0, 1000.0, -20.0);
  core::State s = stateOf(model, start);
  const double e0 = core::totalEnergy(model, s);
  const Vec3 l0 = core::angularMomentumWorld(model.body(0), s.bodies[0]);
  for (int n = 0; n < 100; ++n) core::step(model, s);
  ASSERT_TRUE(s.bodies[0].w_B.allFinite());
  EXPECT_NEAR(core::totalEnergy(model, s) / e0, 1.0, 1e-9);
  EXPECT_LT((core::angularMomentumWorld(model.body(0), s.bodies[0]) - l0).norm() / l0.norm(), 1e-9);
}

}  // namespace
}  // namespace rigid_body_sim::test
