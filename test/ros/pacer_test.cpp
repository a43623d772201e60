// The loop's pacing (no master): at any real-time factor sim time follows
// the wall clock to the nearest step from where it was rebased, a late loop
// catches up in slices with its callbacks between, a loop that
// falls behind is capped and told so, and the timing report reads the
// recorded periods and edits.
#include "rigid_body_sim/ros/pacer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

namespace rigid_body_sim::node {
namespace {

using Clock = Pacer::Clock;
using std::chrono::microseconds;
using std::chrono::milliseconds;

TEST(Pacer, SimTimeFollowsTheWallClockTimesTheRealTimeFactor) {
  Pacer p;
  const Clock::time_point t0 = Clock::now();
  const double dt = 1e-3;
  p.rebase(t0, 2.0);  // sim time 2 s at t0: 2000 steps taken
  long long steps = 2000;
  EXPECT_EQ(p.stepsDue(t0, steps, dt, 1.0), 0);
  // 10 ms of wall time: 10 steps at 1x, and then none are due.
  steps += p.stepsDue(t0 + milliseconds(10), steps, dt, 1.0);
  EXPECT_EQ(steps, 2010);
  EXPECT_EQ(p.stepsDue(t0 + milliseconds(10), steps, dt, 1.0), 0);
  // To the nearest step: 10.4 ms due no more, 10.6 ms one more.
  EXPECT_EQ(p.stepsDue(t0 + microseconds(10400), steps, dt, 1.0), 0);
  EXPECT_EQ(p.stepsDue(t0 + microseconds(10600), steps, dt, 1.0), 1);
  EXPECT_FALSE(p.more());
  // At 4x, 10 ms of wall time since t0 are 40 steps of sim time since 2 s,
  // taken in slices of 10 ms of sim time with the callbacks between.
  steps = 2000;
  for (const int slice : {10, 10, 10, 10}) {
    EXPECT_EQ(p.stepsDue(t0 + milliseconds(10), steps, dt, 4.0), slice);
    steps += slice;
    EXPECT_EQ(p.more(), steps < 2040) << steps;
  }
  EXPECT_EQ(p.stepsDue(t0 + milliseconds(10), steps, dt, 4.0), 0);
  // At 0.1x, 10 ms are one step.
  EXPECT_EQ(p.stepsDue(t0 + milliseconds(10), 2000, dt, 0.1), 1);
  EXPECT_FALSE(p.behind());
  // A slice is 10 ms of sim time whatever the step: 2 steps of 5 ms, or one
  // step when a step is longer than that.
  EXPECT_EQ(p.stepsDue(t0 + milliseconds(100), 400, 5e-3, 1.0), 2);
  EXPECT_TRUE(p.more());
  EXPECT_EQ(p.stepsDue(t0 + milliseconds(500), 80, 0.025, 1.0), 1);
}

TEST(Pacer, ALoopThatStalledCatchesUpInSlicesAndServesItsCallbacksBetween) {
  // 0.3 s late (a stall on a busy machine): the 300 steps due come 10 at a
  // time, so a command that arrives meanwhile waits 10 ms of sim time, not 0.3 s.
  Pacer p;
  const Clock::time_point t0 = Clock::now();
  p.rebase(t0, 0.0);
  long long steps = 0;
  int slices = 0;
  do {
    steps += p.stepsDue(t0 + milliseconds(300), steps, 1e-3, 1.0);
    ++slices;
  } while (p.more());
  EXPECT_EQ(steps, 300);
  EXPECT_EQ(slices, 30);
  EXPECT_FALSE(p.behind());
}

TEST(Pacer, ALoopThatFallsBehindIsCappedAndTold) {
  Pacer p;
  const Clock::time_point t0 = Clock::now();
  p.rebase(t0, 0.0);
  EXPECT_EQ(p.stepsDue(t0 + std::chrono::seconds(5), 0, 1e-3, 1.0), 10);
  EXPECT_TRUE(p.behind());
  EXPECT_FALSE(p.more());  // rebased, not caught up
  // Rebased where it is, it paces from there.
  p.rebase(t0 + std::chrono::seconds(5), 1.0);
  EXPECT_EQ(p.stepsDue(t0 + std::chrono::seconds(5) + milliseconds(3), 1000, 1e-3, 1.0), 3);
  EXPECT_FALSE(p.behind());
}

TEST(Pacer, ARebaseInTheFutureWaitsForTheWallClock) {
  // The clock ahead of the wall (steps taken while paused): nothing is due
  // until the wall clock reaches the reference.
  Pacer p;
  const Clock::time_point t0 = Clock::now();
  p.rebase(t0 + milliseconds(50), 1.0);
  EXPECT_EQ(p.stepsDue(t0 + milliseconds(20), 1000, 1e-3, 1.0), 0);
  EXPECT_EQ(p.stepsDue(t0 + milliseconds(52), 1000, 1e-3, 1.0), 2);
}

TEST(Pacer, TheReportReadsThePeriodsAndTheEdits) {
  Pacer p;
  EXPECT_TRUE(p.report(1e-3, 0.0).empty());
  const Clock::time_point t0 = Clock::now();
  // 1001 ticks: 1000 periods, 999 of 1 ms and one of 3 ms.
  for (int k = 0; k <= 1000; ++k) p.recordTick(t0 + microseconds(1000 * k + (k == 1000 ? 2000 : 0)));
  p.recordSpawn(0.002);
  p.recordSpawn(0.001);
  p.recordDelete(0.004);
  const std::vector<std::string> lines = p.report(1e-3, 0.1);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "1000 ticks, |period - 0.001 s| p50 0.0 us, p99 0.0 us, max 2000.0 us; sim time 0.100 s");
  EXPECT_EQ(lines[1], "2 spawns on the loop, p50 2.000 ms, p90 2.000 ms, max 2.000 ms");
  EXPECT_EQ(lines[2], "1 deletes on the loop, p50 4.000 ms, p90 4.000 ms, max 4.000 ms");
}

}  // namespace
}  // namespace rigid_body_sim::node
