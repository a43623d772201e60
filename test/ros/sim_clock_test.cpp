// The node's clock without a master: readings per step, anchoring, and the
// way back from a reading to sim time.
#include "rigid_body_sim/ros/sim_clock.h"

#include <gtest/gtest.h>

namespace {

using rigid_body_sim::node::formatStamp;
using rigid_body_sim::node::SimClock;

constexpr int64_t kWall = 1795360000123456789;  // a wall-clock reading, ns

TEST(SimClock, SimTimeIsStepsTimesDtAndIgnoresAnchors) {
  SimClock clock(0.001, /*wall_anchored=*/false);
  EXPECT_EQ(clock.stampAt(0), 0);
  EXPECT_EQ(clock.stampAt(1234), 1234000000);
  clock.anchor(1234, kWall);
  EXPECT_EQ(clock.stampAt(1234), 1234000000);
}

TEST(SimClock, WallAnchoredAdvancesByDtPerStepAndStandsStillBetween) {
  SimClock clock(0.001, true);
  clock.anchor(0, kWall);
  EXPECT_EQ(clock.stampAt(0), kWall);
  EXPECT_EQ(clock.stampAt(3) - clock.stampAt(2), 1000000);  // however long the wall clock took
  EXPECT_EQ(clock.stampAt(5000), kWall + 5000000000);
}

TEST(SimClock, ReanchoringJumpsToTheWallClockButNeverBack) {
  SimClock clock(0.001, true);
  clock.anchor(0, kWall);
  EXPECT_EQ(clock.anchor(100, kWall + 3000000000), 0);  // unpaused after 3 s of wall time
  EXPECT_EQ(clock.stampAt(100), kWall + 3000000000);
  EXPECT_EQ(clock.stampAt(101), kWall + 3001000000);
  // Ahead of the wall clock (stepped while paused): it does not go back, and
  // says by how much it is ahead.
  EXPECT_EQ(clock.anchor(5000, kWall + 3100000000), 4800000000);
  EXPECT_EQ(clock.stampAt(5000), kWall + 3000000000 + 4900000000);
}

TEST(SimClock, AReadingGivesBackItsStepsSimTimeExactly) {
  for (const bool wall : {false, true}) {
    SimClock clock(0.001, wall);
    clock.anchor(7, kWall);
    for (const long long steps : {7LL, 8LL, 1007LL, 123456789LL}) {
      EXPECT_EQ(clock.simTimeAt(clock.stampAt(steps)), static_cast<double>(steps) * 0.001) << steps;
      EXPECT_EQ(clock.simTimeAt(clock.stampAt(steps) + 1), static_cast<double>(steps) * 0.001) << steps;
    }
    // Between steps: the reading's own time.
    EXPECT_NEAR(clock.simTimeAt(clock.stampAt(1007) + 400000), 1.0074, 1e-12);
  }
  // A Δt that is no whole number of ns: readings round, and still map back.
  SimClock odd(1.0 / 3000.0, true);
  odd.anchor(0, kWall);
  for (long long steps = 0; steps < 3000; ++steps) {
    ASSERT_EQ(odd.simTimeAt(odd.stampAt(steps)), static_cast<double>(steps) * (1.0 / 3000.0)) << steps;
  }
}

TEST(SimClock, FormatsStampsExactly) {
  EXPECT_EQ(formatStamp(kWall), "1795360000.123456789");
  EXPECT_EQ(formatStamp(1000000), "0.001000000");
  EXPECT_EQ(formatStamp(-1500000000), "-1.500000000");
}

}  // namespace
