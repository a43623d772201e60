// The speed limits and the finite-state guard (src/core/guard.cpp,
// docs/physics.md §5.9): loads and contacts never push a body past the
// limits, and a body whose state stops being finite goes back to its last
// finite pose, at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/loads.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

core::ModelSpec freeSpace() { return spec(boxBody(Vec3(0.2, 0.1, 0.05)), 1e-3, Vec3::Zero()); }

TEST(SpeedLimits, ALoadBeyondThemEndsAtTheLimitInItsDirection) {
  core::ModelSpec ms = freeSpace();
  ms.limits.max_linear_speed = 50.0;
  ms.limits.max_angular_speed = 20.0;
  const core::Model model(ms);
  core::State s = core::restState(model);
  core::Loads loads(1);
  loads[0].force_W = Vec3(3e6, 4e6, 0.0);  // 5e3 m/s in one step, unlimited
  loads[0].torque_W = Vec3(0.0, 0.0, 1e6);
  core::Workspace ws;
  core::step(model, s, loads, &ws);
  EXPECT_NEAR(s.bodies[0].v_WB.norm(), 50.0, 1e-12);
  EXPECT_NEAR(s.bodies[0].v_WB.x() / s.bodies[0].v_WB.y(), 0.75, 1e-12);
  EXPECT_NEAR(s.bodies[0].w_B.norm(), 20.0, 1e-12);
  EXPECT_EQ(ws.speed_limited, std::vector<int>{0});
  // Below the limits nothing is scaled or reported.
  loads[0] = core::BodyLoad();
  core::step(model, s, loads, &ws);
  EXPECT_TRUE(ws.speed_limited.empty());
}

TEST(SpeedLimits, GravityAloneStopsAtTheLinearLimit) {
  core::ModelSpec ms = spec(shippedBox(), 1e-3, Vec3(0.0, 0.0, -9.81));
  ms.limits.max_linear_speed = 10.0;
  const core::Model model(ms);
  core::State s = core::restState(model);
  core::Workspace ws;
  for (int n = 0; n < 2000; ++n) core::step(model, s, {}, &ws);  // 19.6 m/s unlimited
  EXPECT_NEAR(s.bodies[0].v_WB.z(), -10.0, 1e-12);
  EXPECT_EQ(ws.speed_limited, std::vector<int>{0});
}

TEST(SpeedLimits, AnAcceptedTorqueThroughALeverStaysFinite) {
  // The node accepts a force of 999,999 N at a point 999,999 m away: 1e12 N·m
  // on a 1 kg box, NaN within 20 steps before the limits.
  const core::Model model(spec(shippedBox(), 1e-3, Vec3(0.0, 0.0, -9.81)));
  core::State s = core::restState(model);
  core::Loads loads(1);
  core::addWrench(model.body(0), loads[0],
                  core::Wrench{Vec3(0.0, 999999.0, 0.0), Vec3::Zero(), Vec3(999999.0, 0.0, 0.0), core::Frame::kWorld});
  core::Workspace ws;
  for (int n = 0; n < 1000; ++n) {
    core::step(model, s, loads, &ws);
    ASSERT_TRUE(ws.diverged.empty()) << n;
  }
  const core::BodyState& b = s.bodies[0];
  EXPECT_TRUE(b.p_WB.allFinite() && b.v_WB.allFinite() && b.q_WB.coeffs().allFinite() && b.w_B.allFinite());
  EXPECT_LE(b.v_WB.norm(), model.limits().max_linear_speed * (1 + 1e-12));
  EXPECT_LE(b.w_B.norm(), model.limits().max_angular_speed * (1 + 1e-12));
  EXPECT_NEAR(b.q_WB.norm(), 1.0, 1e-12);
}

TEST(SpeedLimits, AContactPushBeyondThemIsLimited) {
  // A 1000 kg box at 400 m/s hits a 1 kg box at rest, elastically: the light
  // one leaves at about 800 m/s unlimited. The impulse solve is limited
  // before positions move, so the step ends at the limit.
  core::ModelSpec ms = spec(boxBody(Vec3(0.1, 0.1, 0.1), 1000.0), 1e-4, Vec3::Zero());
  core::BodySpec light = boxBody(Vec3(0.1, 0.1, 0.1), 1.0);
  light.name = "light";
  ms.bodies.push_back(light);
  ms.scene = {core::Sdf::plane(Vec3::UnitZ()).transformed({Quat::Identity(), Vec3(0.0, 0.0, -100.0)})};
  ms.contact = impulse(1.0, 0.0);
  const core::Model model(ms);
  core::State s = core::restState(model);
  s.bodies[0].v_WB = Vec3(400.0, 0.0, 0.0);
  s.bodies[1].p_WB = Vec3(0.205, 0.0, 0.0);
  core::Workspace ws;
  bool limited = false;
  for (int n = 0; n < 5 && !limited; ++n) {
    core::step(model, s, {}, &ws);
    limited = !ws.speed_limited.empty();
    EXPECT_LE(s.bodies[1].v_WB.norm(), 500.0 * (1 + 1e-12)) << n;
  }
  ASSERT_TRUE(limited);
  EXPECT_EQ(ws.speed_limited, std::vector<int>{1});
  EXPECT_NEAR(s.bodies[1].v_WB.x(), 500.0, 1e-9);
}

TEST(Guard, ANonFiniteBodyGoesBackToItsLastPoseAtRest) {
  for (const core::ContactMethod method : {core::ContactMethod::kImpulse, core::ContactMethod::kShapeMatching}) {
    core::ModelSpec ms = onGround(boxBody(Vec3(0.2, 0.1, 0.05)), impulse(0.0, 0.5));
    ms.contact.method = method;
    const core::Model model(ms);
    core::LinkState start;
    start.p_WL = Vec3(1.0, 2.0, 0.5);
    start.v_WL = Vec3(0.3, 0.0, 0.0);
    core::State s = stateOf(model, start);
    core::Workspace ws;
    core::step(model, s, {}, &ws);
    const core::BodyState before = s.bodies[0];
    core::Loads loads(1);
    loads[0].force_W = Vec3(kInf, 0.0, 0.0);  // no caller should, but the state must survive it
    core::step(model, s, loads, &ws);
    const core::BodyState& b = s.bodies[0];
    ASSERT_EQ(ws.diverged.size(), 1u);
    EXPECT_EQ(ws.diverged[0].body, 0);
    EXPECT_NE(ws.diverged[0].what.find("velocity"), std::string::npos) << ws.diverged[0].what;
    EXPECT_EQ(b.p_WB, before.p_WB);
    EXPECT_EQ(b.q_WB.coeffs(), before.q_WB.coeffs());
    EXPECT_TRUE(b.v_WB.isZero(0.0) && b.w_B.isZero(0.0));
    EXPECT_FALSE(b.asleep);
    // It goes on from there, finite.
    core::step(model, s, {}, &ws);
    EXPECT_TRUE(ws.diverged.empty());
    EXPECT_TRUE(s.bodies[0].p_WB.allFinite());
    for (const core::ContactImpulse& c : s.contact_impulses) EXPECT_TRUE(std::isfinite(c.normal));
  }
}

TEST(Guard, ABodyThatCameInNonFiniteGoesToTheOrigin) {
  const core::Model model(freeSpace());
  core::State s = core::restState(model);
  s.bodies[0].p_WB.x() = std::numeric_limits<double>::quiet_NaN();
  core::Workspace ws;
  core::step(model, s, {}, &ws);
  ASSERT_EQ(ws.diverged.size(), 1u);
  EXPECT_NE(ws.diverged[0].what.find("position"), std::string::npos);
  EXPECT_NE(ws.diverged[0].what.find("origin"), std::string::npos);
  EXPECT_TRUE(s.bodies[0].p_WB.isZero(0.0));
}

}  // namespace
}  // namespace rigid_body_sim::test
