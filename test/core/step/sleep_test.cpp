// Still time and sleep (src/core/sleep.cpp, docs/physics.md §6): when a body
// counts as still, when an island falls asleep, and what wakes a sleeper.
#include "step/sleep.h"

#include <gtest/gtest.h>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/step.h"
#include "step/scratch.h"

namespace rigid_body_sim::test {
namespace {

core::Model twoBoxes() {
  core::ModelSpec ms = spec(shippedBox(), 1e-3, Vec3(0, 0, -9.81));
  ms.bodies = {boxBody(Vec3(0.1, 0.1, 0.1)), boxBody(Vec3(0.1, 0.1, 0.1))};
  ms.bodies[1].name = "other";
  ms.sleep.time = 0.5;
  return core::Model(ms);
}

core::Contact between(int body, int other, double separation = 0.0) {
  core::Contact c;
  c.body = body;
  c.other = other;
  c.separation = separation;
  return c;
}

TEST(Sleep, ABodyFallsAsleepOnAStepThatOnlyHoldsItUp) {
  // A 1 kg ball dropped from 0.5 m stops dead on landing (no bounce), and
  // fell asleep on that step: the contacts it kept, which the node reports
  // for a sleeper, carried the impact (13.1 N) instead of m g. The step it
  // falls asleep on now holds it up and nothing more: impulse = m g h.
  const core::Model model(onGround(ballBody(0.1), core::ContactSettings{}));
  core::State state;
  core::LinkState start;
  start.p_WL.z() = 0.6;
  state.bodies = {core::bodyStateFromLink(model.body(0), start)};
  core::Workspace ws;
  int k = 0;
  for (; k < 5000 && !state.bodies[0].asleep; ++k) core::step(model, state, {}, &ws);
  ASSERT_TRUE(state.bodies[0].asleep) << "after " << k << " steps";
  double normal = 0.0;
  for (const core::Contact& c : ws.contacts) normal += c.normal_impulse;
  EXPECT_NEAR(normal / model.dt(), 9.81, 1e-9) << "asleep after " << k << " steps";
}

TEST(Sleep, StillTimeCountsBelowBothSleepSpeedsAndRestartsAboveEither) {
  const core::Model model = twoBoxes();  // 0.01 m/s and 0.05 rad/s
  core::BodyState s;
  s.v_WB = Vec3(0.009, 0, 0);
  core::updateStillTime(model, 1e-3, s);
  core::updateStillTime(model, 1e-3, s);
  EXPECT_EQ(s.still_time, 2e-3);
  s.w_B = Vec3(0, 0.06, 0);
  core::updateStillTime(model, 1e-3, s);
  EXPECT_EQ(s.still_time, 0.0);
}

TEST(Sleep, ABodyIsReadyOnlyWhenTouchingAfterTheSleepTime) {
  const core::Model model = twoBoxes();
  core::BodyState s;
  s.still_time = 0.5;
  EXPECT_TRUE(core::readyToSleep(model, true, s));
  EXPECT_FALSE(core::readyToSleep(model, false, s));  // in flight: never
  s.still_time = 0.499;
  EXPECT_FALSE(core::readyToSleep(model, true, s));
}

/// Two boxes touching each other, both still for `still0` and `still1` s.
void sleepPair(const core::Model& model, double still0, double still1, core::State& s) {
  s = core::restState(model);
  s.bodies[0].still_time = still0;
  s.bodies[1].still_time = still1;
  s.bodies[0].v_WB = Vec3(0.001, 0, 0);
  core::Workspace ws;
  ws.contacts = {between(0, 1)};
  ws.scratch->in_contact = {1, 1};
  core::sleepIslands(model, s, ws, /*islands_known=*/false);
}

TEST(Sleep, AnIslandFallsAsleepAsAWholeOrNotAtAll) {
  const core::Model model = twoBoxes();
  core::State s;
  sleepPair(model, 0.6, 0.1, s);  // one is not ready: neither sleeps
  EXPECT_FALSE(s.bodies[0].asleep);
  EXPECT_FALSE(s.bodies[1].asleep);
  sleepPair(model, 0.6, 0.5, s);
  EXPECT_TRUE(s.bodies[0].asleep);
  EXPECT_TRUE(s.bodies[1].asleep);
  EXPECT_EQ(s.bodies[0].v_WB, Vec3::Zero());  // put to rest exactly
}

TEST(Sleep, ALoadWakesASleeperAndNoLoadLeavesIt) {
  const core::Model model = twoBoxes();
  core::State s = core::restState(model);
  s.bodies[0].asleep = s.bodies[1].asleep = true;
  s.bodies[0].still_time = s.bodies[1].still_time = 1.0;
  core::Loads loads(2);
  loads[1].force_W = Vec3(0, 0, 1);
  core::wakeLoadedBodies(s, loads);
  EXPECT_TRUE(s.bodies[0].asleep);
  EXPECT_FALSE(s.bodies[1].asleep);
  EXPECT_EQ(s.bodies[1].still_time, 0.0);
}

TEST(Sleep, ABodyComingAtASleeperWakesItOneRestingOnItDoesNot) {
  const core::Model model = twoBoxes();
  const double h = 1e-3;  // a resting contact approaches at most sleep speed + |g| h = 0.01981 m/s
  for (const double approach : {0.015, 0.5}) {
    core::State s = core::restState(model);
    s.bodies[1].asleep = true;
    s.bodies[0].v_WB = Vec3(0, 0, -approach);
    core::Workspace ws;
    ws.contacts = {between(0, 1)};
    ws.contacts[0].normal_W = Vec3::UnitZ();  // body 0 lies on body 1
    const bool woke = core::wakeTouchedSleepers(model, s, ws, h);
    EXPECT_EQ(woke, approach > 0.1) << approach;
    EXPECT_EQ(s.bodies[1].asleep, approach < 0.1) << approach;
  }
}

TEST(Sleep, ABodyPressedDeeperThanTheSlopWakesItsSleeper) {
  const core::Model model = twoBoxes();
  core::State s = core::restState(model);
  s.bodies[1].asleep = true;
  core::Workspace ws;
  ws.contacts = {between(0, 1, -2.0 * model.contact().position_slop)};
  EXPECT_TRUE(core::wakeTouchedSleepers(model, s, ws, 1e-3));
  EXPECT_FALSE(s.bodies[1].asleep);
}

}  // namespace
}  // namespace rigid_body_sim::test
