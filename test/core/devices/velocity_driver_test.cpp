// The velocity driver (docs/physics.md §10.4) on a box sliding on ground
// with friction: 0.5 m/s is reached no sooner than the force limit allows
// and within its time plus the controller's settling, then held within 1%;
// after the timeout it no longer drives; a command beyond the limits is
// clipped, not refused.
#include "rigid_body_sim/core/devices/velocity_driver.h"

#include <gtest/gtest.h>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

const Vec3 kHalf(0.2, 0.1, 0.05);
constexpr double kG = 9.81, kMu = 0.5;

struct Rig {
  core::Model model;
  core::State state;
  core::VelocityDriver driver;
  core::Workspace ws;

  explicit Rig(const core::DriverSettings& settings)
      : model(onGround(boxBody(kHalf), impulse(0.0, kMu))), driver(settings) {
    core::LinkState link;
    link.p_WL = Vec3(0, 0, kHalf.z());
    state = stateOf(model, link);
  }
  /// One step, driven; returns the force the driver applied.
  Vec3 step() {
    core::Loads loads{driver.load(model.body(0), state.bodies[0], state.time, model.dt())};
    core::step(model, state, loads, &ws);
    return loads[0].force_W;
  }
  core::LinkState link() const { return core::linkState(model.body(0), state.bodies[0]); }
};

core::DriverSettings planar() {
  core::DriverSettings s;
  s.planar = true;
  return s;
}

TEST(VelocityDriver, ReachesTheCommandAsTheForceLimitAllowsAndHoldsItWithinOnePercent) {
  Rig rig(planar());
  const double v = 0.5, m = 1.0, f_max = rig.driver.settings().max_force;
  const double accel = (f_max - kMu * m * kG) / m;  // the most the limit allows against friction
  const double t_force = v / accel;                 // 0.098 s
  // Then the critically damped PI settles: from leaving the limit (an error of
  // f_max / (m k_p) = 0.2 m/s) to 1 % takes about 10 / k_p = 0.2 s.
  const double settle = 10.0 / rig.driver.settings().linear_gain;
  double reached = -1.0;
  for (int n = 0; n < 2500; ++n) {
    if (n % 100 == 0) rig.driver.command(Vec3(v, 0, 0), Vec3::Zero(), rig.state.time);  // 10 Hz, as a planner sends
    const Vec3 f = rig.step();
    EXPECT_LE(f.norm(), f_max * (1 + 1e-12));
    const double vx = rig.link().v_WL.x();
    EXPECT_LE(vx, accel * rig.state.time + 1e-9) << "faster than the force limit allows at t = " << rig.state.time;
    if (reached < 0.0 && std::abs(vx - v) <= 0.01 * v) reached = rig.state.time;
    if (reached > 0.0) {
      ASSERT_NEAR(vx, v, 0.01 * v) << "t = " << rig.state.time;
    }
  }
  ASSERT_GT(reached, 0.0);
  EXPECT_GE(reached, t_force);
  EXPECT_LE(reached, t_force + settle);
  EXPECT_NEAR(rig.link().v_WL.y(), 0.0, 1e-6);
}

TEST(VelocityDriver, TurnsAtTheCommandedYawRate) {
  Rig rig(planar());
  for (int n = 0; n < 2000; ++n) {
    if (n % 100 == 0) rig.driver.command(Vec3(0.3, 0, 0), Vec3(0, 0, 1.0), rig.state.time);
    rig.step();
  }
  EXPECT_NEAR(rig.link().w_W.z(), 1.0, 0.01);
  // Forward along its own heading as it turns.
  const Vec3 forward = rig.link().q_WL * Vec3::UnitX();
  EXPECT_NEAR(rig.link().v_WL.dot(forward), 0.3, 0.003);
}

TEST(VelocityDriver, AfterTheTimeoutItNoLongerDrives) {
  Rig rig(planar());
  rig.driver.command(Vec3(0.5, 0, 0), Vec3::Zero(), 0.0);
  for (int n = 0; n < 500; ++n) rig.step();  // t = 0.5 s: still driven
  EXPECT_NEAR(rig.link().v_WL.x(), 0.5, 0.005);
  rig.step();
  EXPECT_EQ(rig.step(), Vec3::Zero());       // past the 0.5 s timeout
  for (int n = 0; n < 200; ++n) rig.step();  // friction stops it within v / (mu g) = 0.1 s
  EXPECT_LT(rig.link().v_WL.norm(), 1e-3);
  EXPECT_FALSE(rig.driver.active(rig.state.time));
}

TEST(VelocityDriver, ACommandBeyondTheLimitsIsClippedNotRefused) {
  core::DriverSettings s = planar();
  s.max_linear_speed = 1.0;
  s.max_force = 20.0;
  Rig rig(s);
  for (int n = 0; n < 2000; ++n) {
    if (n % 100 == 0) {
      EXPECT_TRUE(rig.driver.command(Vec3(5.0, 0, 0), Vec3(0, 0, 50.0), rig.state.time));
    }
    rig.step();
  }
  EXPECT_NEAR(rig.link().v_WL.norm(), 1.0, 0.01);
  EXPECT_NEAR(rig.link().w_W.z(), 2.0, 0.02);  // max_angular_speed
  EXPECT_FALSE(rig.driver.command(Vec3(0.5, 0, 0), Vec3::Zero(), rig.state.time));
}

TEST(VelocityDriver, BadSettingsAreRefusedNamingTheKey) {
  core::DriverSettings s;
  s.max_force = 0.0;
  expectThrowsWith<std::invalid_argument>([&] { core::validateDriver(s, "cmd_vel"); }, {"cmd_vel.max_force = 0"});
  s = {};
  s.timeout = -1.0;
  expectThrowsWith<std::invalid_argument>([&] { core::validateDriver(s, "bodies[0].cmd_vel"); },
                                          {"bodies[0].cmd_vel.timeout = -1"});
}

}  // namespace
}  // namespace rigid_body_sim::test
