// The fixed-point cache (src/core/fixed_point.cpp): a step that returned its
// input unchanged is not computed again for the same input, and anything
// that differs (a load, the state, the cache dropped) computes it again.
#include "step/fixed_point.h"

#include <gtest/gtest.h>

#include "../../test_util.h"

namespace rigid_body_sim::test {
namespace {

int g_advances = 0;  // how often the stand-in advance() ran

/// A step that changes nothing (a body resting exactly).
bool unchanged(const core::Model&, core::State&, const core::Loads&, double, core::Workspace&) {
  ++g_advances;
  return false;
}

/// A step that moves the body.
bool moving(const core::Model&, core::State& s, const core::Loads&, double h, core::Workspace&) {
  ++g_advances;
  s.bodies[0].p_WB.x() += h;
  return false;
}

struct FixedPointTest : ::testing::Test {
  core::Model model{spec(shippedBox(), 1e-3, Vec3::Zero())};
  core::State state = core::restState(model);
  core::Workspace ws;
  void SetUp() override {
    g_advances = 0;
    state.bodies[0].still_time = 0.1;  // below the sleep speeds: worth caching
  }
  void repeat(const core::Loads& loads = {}, bool (*advance)(const core::Model&, core::State&, const core::Loads&,
                                                             double, core::Workspace&) = unchanged) {
    // As step() does: repeated, or computed and recorded.
    if (core::repeatFixedPoint(model, state, loads, 1e-3, ws)) return;
    core::recordFixedPoint(model, state, loads, advance(model, state, loads, 1e-3, ws), ws);
  }
};

TEST_F(FixedPointTest, ARepeatedInputIsNotComputedAgainButItsStillTimeCounts) {
  repeat();
  EXPECT_EQ(g_advances, 1);
  repeat();
  repeat();
  EXPECT_EQ(g_advances, 1);
  EXPECT_EQ(ws.skipped_steps, 2u);
  EXPECT_DOUBLE_EQ(state.bodies[0].still_time, 0.1 + 2e-3);  // as the computed step would count it
}

TEST_F(FixedPointTest, ADifferentLoadOrStateOrADroppedCacheComputesTheStep) {
  repeat();
  core::Loads loads(1);
  loads[0].force_W = Vec3(0, 0, 1e-9);
  repeat(loads);  // another load
  EXPECT_EQ(g_advances, 2);
  state.bodies[0].p_WB.y() += 1e-12;  // another state (set_state)
  repeat(loads);
  EXPECT_EQ(g_advances, 3);
  core::forgetFixedPoint(ws);
  repeat(loads);
  EXPECT_EQ(g_advances, 4);
  repeat(loads);  // cached again
  EXPECT_EQ(g_advances, 4);
}

TEST_F(FixedPointTest, AStepThatMovesIsAlwaysComputed) {
  for (int k = 0; k < 3; ++k) repeat({}, moving);
  EXPECT_EQ(g_advances, 3);
  EXPECT_EQ(ws.skipped_steps, 0u);
}

TEST_F(FixedPointTest, AMovingBodyIsNotCachedAndSwitchingTheCacheOffComputesEveryStep) {
  state.bodies[0].still_time = 0.0;  // faster than the sleep speeds: the input is not kept
  repeat();
  repeat();
  EXPECT_EQ(g_advances, 2);
  state.bodies[0].still_time = 0.1;
  ws.skip_fixed_points = false;
  for (int k = 0; k < 3; ++k) repeat();
  EXPECT_EQ(g_advances, 5);
}

}  // namespace
}  // namespace rigid_body_sim::test
