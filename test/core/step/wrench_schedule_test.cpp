// Timed wrenches deliver exactly force × duration; a held wrench (the
// node's ~wrench topic) acts in whole steps until replaced, cleared or timed out.
#include "rigid_body_sim/core/step/wrench_schedule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

/// Three shipped boxes, a, b and c, in no gravity.
core::Model threeBoxes() {
  core::BodySpec a = shippedBox(), b = shippedBox(), c = shippedBox();
  a.name = "a";
  b.name = "b";
  c.name = "c";
  core::ModelSpec three = spec(a, 1e-3, Vec3::Zero());
  three.bodies = {a, b, c};
  return core::Model(three);
}

/// x N along the world's x axis.
core::Wrench push(double x) { return core::Wrench{Vec3(x, 0, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld}; }

TEST(WrenchSchedule, DeliversForceTimesDurationOffTheStepGrid) {
  // 2 N for 0.0123 s from t = 0.0047: windows that cut steps in the middle.
  const double dt = 1e-3;
  const core::Model model(spec(shippedBox(), dt, Vec3::Zero()));
  core::WrenchSchedule schedule;
  schedule.add(0, {Vec3(2, 0, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld}, 0.0047, 0.0047 + 0.0123);
  core::State s = stateOf(model, core::LinkState{});
  core::Loads loads;
  for (int n = 0; n < 40; ++n) {
    schedule.loadsFor(model, s, s.time, dt, loads);
    core::step(model, s, loads);
    schedule.dropFinished(s.time);
  }
  EXPECT_NEAR(s.bodies[0].v_WB.x(), 2.0 * 0.0123 / 1.0, 1e-14);  // Δv = F T / M
  EXPECT_EQ(schedule.size(), 0u);
}

TEST(WrenchSchedule, AWindowOnAStepBoundaryActsOnWholeStepsWhateverTheRounding) {
  // The node gives a start of n·dt (a stamp on the step grid) and steps from
  // t = k·dt; (n − 1)·dt + dt is not always n·dt in floating point. The step
  // before the window gets nothing, the steps inside it the whole force.
  const double dt = 1e-3;
  const core::Model model(spec(shippedBox(), dt, Vec3::Zero()));
  const core::State rest = stateOf(model, core::LinkState{});
  core::Loads loads;
  int off_grid = 0;
  for (long long n = 1; n < 200000; n += 7) {
    const double start = static_cast<double>(n) * dt, end = static_cast<double>(n + 50) * dt;
    const double before = static_cast<double>(n - 1) * dt, last = static_cast<double>(n + 49) * dt;
    if (before + dt != start || last + dt != end) ++off_grid;
    core::WrenchSchedule schedule;
    schedule.add(0, push(2.0), start, end);
    schedule.loadsFor(model, rest, before, dt, loads);
    ASSERT_TRUE(loads.empty() || loads[0].force_W.isZero()) << "n = " << n << ": " << loads[0].force_W.x();
    for (const double t : {start, last}) {
      schedule.loadsFor(model, rest, t, dt, loads);
      ASSERT_FALSE(loads.empty()) << "n = " << n;
      ASSERT_EQ(loads[0].force_W.x(), 2.0) << "n = " << n << ", t = " << t;
    }
    schedule.loadsFor(model, rest, end, dt, loads);
    ASSERT_TRUE(loads.empty() || loads[0].force_W.isZero()) << "n = " << n << ": " << loads[0].force_W.x();
  }
  EXPECT_GT(off_grid, 0) << "no case of the rounding this test is about";
}

TEST(WrenchSchedule, WrenchesAddAndClearPerBody) {
  const core::Model model(spec(shippedBox(), 1e-3, Vec3::Zero()));
  const core::State rest = stateOf(model, core::LinkState{});
  core::WrenchSchedule schedule;
  const double forever = core::WrenchSchedule::kForever;
  schedule.add(0, {Vec3(1, 0, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld}, 0.0, forever);
  schedule.add(0, {Vec3(0, 3, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld}, 0.0, forever);
  core::Loads loads;
  schedule.loadsFor(model, rest, 5.0, 1e-3, loads);
  ASSERT_EQ(loads.size(), 1u);
  EXPECT_EQ(loads[0].force_W, Vec3(1, 3, 0));
  schedule.add(0, {Vec3(0, 0, 7), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld}, 9.0, forever);  // later
  schedule.loadsFor(model, rest, 5.0, 1e-3, loads);
  EXPECT_EQ(loads[0].force_W, Vec3(1, 3, 0));
  schedule.clear(0);
  schedule.loadsFor(model, rest, 10.0, 1e-3, loads);
  EXPECT_TRUE(loads.empty());
}

TEST(WrenchSchedule, ADeletedBodyTakesItsWrenchesAndThoseInItsAxes) {
  // Three boxes; wrenches on each, one on c given in b's axes. Deleting b
  // drops b's and the one in b's axes; c's other wrench now acts on index 1.
  const core::Model model = threeBoxes();
  const double forever = core::WrenchSchedule::kForever;
  core::WrenchSchedule schedule;
  schedule.add(0, push(1), 0.0, forever);
  schedule.add(1, push(2), 0.0, forever);
  schedule.add(2, push(3), 0.0, forever);
  schedule.add(2, push(4), 0.0, forever, 1);  // in b's axes
  schedule.add(2, push(5), 7.0, forever);     // yet to start
  schedule.dropFinished(1.0);
  EXPECT_EQ(schedule.removeBody(1), 2u);
  const core::Model two = model.withoutBody(1);
  core::State s = core::restState(model);
  core::removeBody(model, s, 1);
  core::Loads loads;
  schedule.loadsFor(two, s, 8.0, 0.5, loads);  // a step of 0.5 s: whole fractions
  ASSERT_EQ(loads.size(), 2u);
  EXPECT_EQ(loads[0].force_W, Vec3(1, 0, 0));
  EXPECT_EQ(loads[1].force_W, Vec3(8, 0, 0));  // c's own two
  EXPECT_EQ(schedule.count(0), 1u);
  EXPECT_EQ(schedule.count(1), 2u);
  EXPECT_EQ(schedule.count(2), 0u);
}

TEST(WrenchSchedule, AWrenchInAnotherBodysAxesTurnsWithThatBody) {
  // 2 N on body 0 (1 kg) along body 1's x axis, while body 1 spins about its
  // z axis (a principal axis: ω stays constant). Each step holds the force
  // where body 1 points at the step's start, and the step turns body 1 by
  // θ = 2 atan(h ω / 2) (the quaternion update), so after n steps
  // v = (h F / M) Σₖ (cos kθ, sin kθ) = (h F / M) (1 − e^{inθ}) / (1 − e^{iθ}).
  const double dt = 1e-3, w = 3.0, F = 2.0;
  core::ModelSpec two = spec(shippedBox(), dt, Vec3::Zero());
  two.bodies.push_back(shippedBox());
  two.bodies[1].name = "spinner";
  const core::Model model(two);
  core::State s;
  core::LinkState spinning;
  spinning.p_WL = Vec3(5, 0, 0);
  spinning.w_W = Vec3(0, 0, w);
  s.bodies = {core::bodyStateFromLink(model.body(0), core::LinkState{}),
              core::bodyStateFromLink(model.body(1), spinning)};
  core::WrenchSchedule schedule;
  schedule.add(0, {Vec3(F, 0, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld}, 0.0, core::WrenchSchedule::kForever,
               1);
  core::Loads loads;
  const int n = 700;  // about a third of a turn
  for (int k = 0; k < n; ++k) {
    schedule.loadsFor(model, s, s.time, dt, loads);
    core::step(model, s, loads);
  }
  const double theta = 2.0 * std::atan(0.5 * dt * w);
  const std::complex<double> sum = (1.0 - std::polar(1.0, n * theta)) / (1.0 - std::polar(1.0, theta));
  EXPECT_NEAR(s.bodies[0].v_WB.x(), dt * F * sum.real(), 1e-12);
  EXPECT_NEAR(s.bodies[0].v_WB.y(), dt * F * sum.imag(), 1e-12);
  EXPECT_GT(s.bodies[0].v_WB.y(), 0.1);       // it turned: a fixed world force would give none along y
  EXPECT_EQ(s.bodies[0].w_B, Vec3::Zero());   // the force acts at the centre of mass
  EXPECT_EQ(s.bodies[1].v_WB, Vec3::Zero());  // and on body 0 only
}

TEST(WrenchSchedule, AHeldWrenchActsInWholeStepsUntilItsTimeout) {
  // 3 N held from t = 0.010 s with a timeout of 0.25 s: 250 whole steps of
  // 1 ms, Δv = F T / M = 0.75 m/s; then it is gone. A second one replaces
  // the first, it does not add to it.
  const double dt = 1e-3;
  const core::Model model(spec(shippedBox(), dt, Vec3::Zero()));
  core::WrenchSchedule schedule;
  core::State s = stateOf(model, core::LinkState{});
  core::Loads loads;
  const auto run = [&](int steps) {
    for (int n = 0; n < steps; ++n) {
      schedule.loadsFor(model, s, s.time, dt, loads);
      core::step(model, s, loads);
      schedule.dropFinished(s.time);
    }
  };
  run(10);
  schedule.hold(0, {Vec3(1, 0, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld}, s.time, 0.25);
  schedule.hold(0, {Vec3(3, 0, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld}, s.time, 0.25);
  EXPECT_TRUE(schedule.holds(0));
  EXPECT_EQ(schedule.size(), 0u);  // not a timed wrench
  run(400);
  EXPECT_NEAR(s.bodies[0].v_WB.x(), 3.0 * 0.25, 1e-12);
  EXPECT_FALSE(schedule.holds(0));
  // Until cleared, with no timeout; in the body's own axes, turning with it.
  schedule.hold(0, {Vec3(0, 2, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kBody}, s.time,
                core::WrenchSchedule::kForever);
  run(100);
  EXPECT_NEAR(s.bodies[0].v_WB.y(), 2.0 * 0.1, 1e-12);
  schedule.clear(0);
  EXPECT_FALSE(schedule.holds(0));
  run(10);
  EXPECT_NEAR(s.bodies[0].v_WB.y(), 2.0 * 0.1, 1e-12);
}

TEST(WrenchSchedule, ADeletedBodyTakesTheWrenchesHeldInItsAxes) {
  // a holds one in b's axes, c one in its own: deleting b drops a's, and
  // c's acts on index 1.
  const core::Model model = threeBoxes();
  core::WrenchSchedule schedule;
  schedule.hold(0, push(1), 0.0, core::WrenchSchedule::kForever, 1);
  schedule.hold(2, push(3), 0.0, core::WrenchSchedule::kForever);
  EXPECT_EQ(schedule.removeBody(1), 0u);  // no timed wrench went
  EXPECT_FALSE(schedule.holds(0));
  EXPECT_TRUE(schedule.holds(1));
  const core::Model two = model.withoutBody(1);
  core::State s = core::restState(model);
  core::removeBody(model, s, 1);
  core::Loads loads;
  schedule.loadsFor(two, s, 1.0, 1e-3, loads);
  ASSERT_EQ(loads.size(), 2u);
  EXPECT_EQ(loads[0].force_W, Vec3::Zero());
  EXPECT_EQ(loads[1].force_W, Vec3(3, 0, 0));
}

TEST(WrenchSchedule, EachBodyHoldsABoundedNumberAndStepsCostOnlyWhatActs) {
  const core::Model model(spec(shippedBox(), 1e-3, Vec3::Zero()));
  const core::State rest = stateOf(model, core::LinkState{});
  core::WrenchSchedule schedule;
  const core::Wrench one{Vec3(1, 0, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld};
  // Future wrenches, latest first: the schedule keeps them in order of start.
  const std::size_t cap = core::WrenchSchedule::kMaxPerBody;
  for (std::size_t k = cap; k > 0; --k) ASSERT_TRUE(schedule.add(0, one, 10.0 + k, 10.0 + k + 0.5));
  EXPECT_FALSE(schedule.add(0, one, 1.0, 2.0));  // refused: full
  EXPECT_EQ(schedule.count(0), cap);
  core::Loads loads;
  schedule.loadsFor(model, rest, 0.0, 1e-3, loads);
  EXPECT_TRUE(loads.empty());
  // At t = 11.2 only the first acts; at 12.2 the first has ended and the second acts.
  schedule.dropFinished(11.2);
  schedule.loadsFor(model, rest, 11.2, 1e-3, loads);
  ASSERT_EQ(loads.size(), 1u);
  EXPECT_NEAR((loads[0].force_W - Vec3(1, 0, 0)).norm(), 0.0,
              1e-9);  // the step's fraction of the window is 1 − rounding
  schedule.dropFinished(12.2);
  EXPECT_EQ(schedule.count(0), cap - 1);
  EXPECT_TRUE(schedule.add(0, one, 1.0, 2.0));  // room again (a start in the past acts at once)
  schedule.loadsFor(model, rest, 12.2, 1e-3, loads);
  EXPECT_NEAR((loads[0].force_W - Vec3(1, 0, 0)).norm(), 0.0, 1e-9);  // the second only: [1, 2) is over
  schedule.clear(0);
  EXPECT_EQ(schedule.count(0), 0u);
  EXPECT_EQ(schedule.size(), 0u);
}

}  // namespace
}  // namespace rigid_body_sim::test
