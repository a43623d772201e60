// Many bodies: body-body contact against closed forms (momentum, restitution,
// Newton's cradle, a box sliding on a box), a stack standing still, sleep, a room full of boxes and
// determinism: the whole step (step.cpp) with several bodies.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../../test_util.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/step/diagnostics.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

core::BodySpec named(core::BodySpec b, const std::string& name) {
  b.name = name;
  return b;
}

core::ModelSpec world(std::vector<core::BodySpec> bodies, const Vec3& gravity, double restitution,
                      std::vector<core::Sdf> scene = {}) {
  core::ModelSpec s;
  s.bodies = std::move(bodies);
  s.gravity_W = gravity;
  s.scene = std::move(scene);
  s.contact.restitution = restitution;
  s.contact.friction = 0.5;
  return s;
}

core::BodyState at(const core::Model& model, int i, const Vec3& p, const Vec3& v = Vec3::Zero(),
                   const Quat& q = Quat::Identity()) {
  core::LinkState link;
  link.p_WL = p;
  link.v_WL = v;
  link.q_WL = q;
  return core::bodyStateFromLink(model.body(i), link);
}

Vec3 momentum(const core::Model& model, const core::State& s) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < model.bodyCount(); ++i) p += model.body(i).mass * s.bodies[i].v_WB;
  return p;
}

// Along x, along y and slanted: the broad phase sweeps along x in strips
// along y, and a pair must be found whichever way the bodies meet.
TEST(TwoSpheres, HeadOnConservesMomentumWithRestitution) {
  const double e = 0.8;
  const core::Model model(world({named(ballBody(0.1, 1.0), "a"), named(ballBody(0.1, 2.0), "b")}, Vec3::Zero(), e));
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, -0.9, 0.3).normalized()}) {
    core::State s;
    s.bodies = {at(model, 0, -0.5 * d, 2.0 * d), at(model, 1, 0.5 * d, -1.0 * d)};
    const Vec3 p0 = momentum(model, s);
    const double closing = 3.0;
    core::Workspace ws;
    double deepest = 0.0;
    for (int n = 0; n < 1000; ++n) {
      core::step(model, s, {}, &ws);
      deepest = std::max(deepest, ws.deepest_penetration);
    }
    EXPECT_LT(deepest, 1e-3) << d.transpose();  // met in time, not found once overlapping
    EXPECT_LT((momentum(model, s) - p0).norm(), 1e-12) << d.transpose();
    const double separating = (s.bodies[1].v_WB - s.bodies[0].v_WB).dot(d);
    EXPECT_NEAR(separating, e * closing, 0.01 * e * closing) << d.transpose();
    EXPECT_GT((s.bodies[1].p_WB - s.bodies[0].p_WB).dot(d), 0.2);  // apart again, not through each other
    for (const core::BodyState& b : s.bodies) {
      EXPECT_LT((b.v_WB - b.v_WB.dot(d) * d).norm(), 1e-12) << d.transpose();  // stays on the line
    }
  }
}

TEST(NewtonsCradle, ARowOfTouchingBallsPassesTheImpulseAlong) {
  const int n = 5;
  std::vector<core::BodySpec> balls;
  for (int i = 0; i <= n; ++i) balls.push_back(named(ballBody(0.1), "ball" + std::to_string(i)));
  const core::Model model(world(balls, Vec3::Zero(), 1.0));
  core::State s;
  s.bodies.push_back(at(model, 0, Vec3(-0.6, 0, 0), Vec3(1, 0, 0)));                         // the striker
  for (int i = 1; i <= n; ++i) s.bodies.push_back(at(model, i, Vec3(0.2 * (i - 1), 0, 0)));  // touching
  const double e0 = core::totalEnergy(model, s);
  for (int k = 0; k < 1000; ++k) core::step(model, s);
  EXPECT_NEAR(s.bodies[n].v_WB.x(), 1.0, 0.02);  // the last ball leaves with the striker's speed
  for (int i = 0; i < n; ++i) EXPECT_NEAR(s.bodies[i].v_WB.x(), 0.0, 0.02) << "ball " << i;
  EXPECT_NEAR(momentum(model, s).x(), 1.0, 1e-12);
  EXPECT_NEAR(core::totalEnergy(model, s), e0, 0.02 * e0);
}

core::ModelSpec stack(bool sleep) {
  std::vector<core::BodySpec> boxes;
  for (int i = 0; i < 5; ++i) boxes.push_back(named(boxBody(Vec3(0.1, 0.1, 0.1)), "box" + std::to_string(i)));
  core::ModelSpec spec = world(boxes, Vec3(0, 0, -9.81), 0.0, {core::Sdf::plane(Vec3::UnitZ())});
  spec.sleep.enabled = sleep;
  return spec;
}

TEST(Friction, ABoxSlidesOnABoxTheClosedFormDistance) {
  // A box sliding on a heavy box that rests on the ground stops after
  // v₀²/(2 μ g), placed so that the lower box's face samples lie exactly on
  // the upper one's edges. Before, near those edges the upper box's solid
  // gave the lower box's face points sideways normals: the box was launched
  // (v_z 0.28 m/s in the first step) and then stopped at the next sample,
  // 0.05 m instead of 0.17 m at μ = 0.3.
  const Vec3 top(0.2, 0.1, 0.05);
  for (const double mu : {0.3, 0.6, 1.0}) {
    core::ModelSpec ms = world({named(boxBody(Vec3(2.0, 1.0, 0.1), 1000.0), "base"), named(boxBody(top), "top")},
                               Vec3(0, 0, -9.81), 0.0, {core::Sdf::plane(Vec3::UnitZ())});
    ms.contact.friction = mu;
    ms.sleep.enabled = false;
    const core::Model model(ms);
    const double v0 = 1.0;
    core::State s;
    s.bodies = {at(model, 0, Vec3(0, 0, 0.1)), at(model, 1, Vec3(-1.0, 0, 0.2 + top.z()), Vec3(v0, 0, 0))};
    double highest = 0.0;
    for (int n = 0; n < 5000 && s.bodies[1].v_WB.x() > 1e-9; ++n) {
      core::step(model, s);
      highest = std::max(highest, s.bodies[1].p_WB.z());
    }
    const double expected = v0 * v0 / (2 * mu * 9.81);
    EXPECT_NEAR(s.bodies[1].p_WB.x() + 1.0, expected, 0.01 * expected) << "mu " << mu;
    EXPECT_LT(highest, 0.2 + top.z() + 1e-4) << "mu " << mu;  // slid flat, never lifted
  }
}

TEST(Stack, FiveBoxesStandStillForTenSeconds) {
  for (bool sleep : {false, true}) {
    const core::Model model(stack(sleep));
    core::State s;
    for (int i = 0; i < 5; ++i) s.bodies.push_back(at(model, i, Vec3(0, 0, 0.1 + 0.2 * i)));
    const core::State start = s;
    core::Workspace ws;
    double deepest = 0.0, drift = 0.0;
    for (int k = 0; k < 10000; ++k) {
      core::step(model, s, {}, &ws);
      deepest = std::max(deepest, ws.deepest_penetration);
      for (int i = 0; i < 5; ++i) drift = std::max(drift, (s.bodies[i].p_WB - start.bodies[i].p_WB).norm());
    }
    EXPECT_LT(drift, 1e-3) << "sleep " << sleep;
    EXPECT_LT(deepest, 1e-3) << "sleep " << sleep;
    if (sleep) {
      for (int i = 0; i < 5; ++i) EXPECT_TRUE(s.bodies[i].asleep) << "box " << i;
    }
  }
}

// Sleep goes by islands: a box resting on the ground under a box still
// sliding to a stop must not fall asleep before the top one (it would be
// jolted awake again). Both are still (for the sleep time, or held exactly
// still) only once the top one has stopped; they fall asleep in the same
// step and stay so.
TEST(Sleep, TouchingBodiesFallAsleepTogetherAndStayAsleep) {
  const core::Model model(stack(true));
  core::State s;
  s.bodies = {at(model, 0, Vec3(0, 0, 0.1)), at(model, 1, Vec3(0, 0, 0.3), Vec3(0.3, 0, 0))};
  for (int i = 2; i < 5; ++i) s.bodies.push_back(at(model, i, Vec3(2.0 * i, 0, 0.1)));  // elsewhere, on the ground
  core::Workspace ws;
  int asleep_at[2] = {-1, -1};
  for (int k = 0; k < 3000; ++k) {
    core::step(model, s, {}, &ws);
    for (int i = 0; i < 2; ++i) {
      if (asleep_at[i] < 0 && s.bodies[i].asleep) asleep_at[i] = k;
      if (asleep_at[i] >= 0) {
        ASSERT_TRUE(s.bodies[i].asleep) << "box " << i << " woke at step " << k;
      }
    }
  }
  ASSERT_GE(asleep_at[1], 0);
  EXPECT_EQ(asleep_at[0], asleep_at[1]);
  // The top box slides for v/(μ g) = 0.06 s and settles.
  EXPECT_GE(asleep_at[1] * model.dt(), 0.06);
  EXPECT_LT(asleep_at[1] * model.dt(), 1.0);
  EXPECT_GT(s.bodies[1].p_WB.x(), 0.0);  // it slid, on top of the other
  EXPECT_NEAR(s.bodies[1].p_WB.z(), 0.3, 1e-3);
}

// A body its contacts hold exactly still (pushed, v = ω = 0 to the last bit)
// is in equilibrium and sleeps without waiting for the sleep time. Bodies
// that only touch, at rest in zero gravity, are not held: they wait.
TEST(Sleep, ABodyHeldExactlyStillSleepsAtOnceOneMerelyTouchingWaits) {
  const core::Model held(stack(true));
  core::State s;
  s.bodies = {at(held, 0, Vec3(0, 0, 0.11))};  // dropped 1 cm
  for (int i = 1; i < 5; ++i) s.bodies.push_back(at(held, i, Vec3(2.0 * i, 0, 0.1 + 0.05 * i)));
  core::Workspace ws;
  int asleep_at = -1, exact_awake = 0;
  for (int k = 0; k < 1000 && asleep_at < 0; ++k) {
    core::step(held, s, {}, &ws);
    const core::BodyState& b = s.bodies[0];
    if (b.asleep) asleep_at = k;
    exact_awake += !b.asleep && b.v_WB.isZero(0.0) && b.w_B.isZero(0.0);
  }
  ASSERT_GE(asleep_at, 0);
  EXPECT_EQ(exact_awake, 0);                             // asleep in the first step it was exactly still
  EXPECT_LT(s.bodies[0].still_time, held.sleep().time);  // without waiting for the sleep time

  core::ModelSpec floating = stack(true);
  floating.gravity_W = Vec3::Zero();
  const core::Model touching(floating);
  core::State t;
  for (int i = 0; i < 5; ++i) t.bodies.push_back(at(touching, i, Vec3(0, 0, 0.1 + 0.2 * i)));  // faces touching
  for (int k = 0; k < 400; ++k) core::step(touching, t);
  for (const core::BodyState& b : t.bodies) EXPECT_FALSE(b.asleep);
  for (int k = 0; k < 200; ++k) core::step(touching, t);
  for (const core::BodyState& b : t.bodies) EXPECT_TRUE(b.asleep);  // after the sleep time
}

// The broad phase sweeps a sleeper only against the awake boxes after it in
// x, and an awake box against all after it: a box dropped onto a sleeper
// must find it whichever of the two comes first in x.
TEST(Sleep, ABoxDroppedOnASleeperLandsOnItFromEitherSide) {
  const core::Model model(stack(true));
  core::State s;
  for (int i = 0; i < 3; ++i) {  // three 0.2 m cubes asleep on the ground
    s.bodies.push_back(at(model, i, Vec3(2.0 * i, 0, 0.1)));
    s.bodies.back().asleep = true;
  }
  s.bodies.push_back(at(model, 3, Vec3(0.05, 0, 0.5)));        // after sleeper 0 in x
  s.bodies.push_back(at(model, 4, Vec3(2.0 - 0.05, 0, 0.5)));  // before sleeper 1 in x
  core::Workspace ws;
  for (int k = 0; k < 1500; ++k) core::step(model, s, {}, &ws);
  EXPECT_NEAR(s.bodies[3].p_WB.z(), 0.3, 1e-3);  // on top of its sleeper, not through it
  EXPECT_NEAR(s.bodies[4].p_WB.z(), 0.3, 1e-3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(s.bodies[i].p_WB.z(), 0.1, 1e-3) << "box " << i;
  EXPECT_TRUE(s.bodies[2].asleep);  // nothing came near it
}

// A sleeper is ground to the solve on either side of a contact. Its own
// points against an awake body's solid make contacts whose `body` is the
// sleeper; those once gave the sleeper mass terms (with an inverse inertia
// never computed for it) and the position stage moved it. In the pile of
// 10,000 boxes with restitution 0.5 (bench/pile.sh) such a contact's
// impulse grew by half each step until two boxes left at 200 m/s.
TEST(Sleep, ASleeperUnderABoxResistsAsGroundAndDoesNotMove) {
  const core::Model model(stack(true));
  core::State s;
  s.bodies.push_back(at(model, 0, Vec3(0, 0, 0.1)));
  s.bodies.back().asleep = true;
  // Resting on it, a little turned and off centre, so each box's corners meet the other's faces.
  s.bodies.push_back(at(model, 1, Vec3(0.05, 0.03, 0.3), Vec3::Zero(), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()))));
  for (int i = 2; i < 5; ++i) s.bodies.push_back(at(model, i, Vec3(3.0 * i, 0, 0.1)));  // far away, resting
  const core::BodyState sleeper = s.bodies[0];
  core::Workspace ws;
  for (int k = 0; k < 2000; ++k) {
    core::step(model, s, {}, &ws);
    if (s.bodies[0].asleep) {
      EXPECT_TRUE(s.bodies[0] == sleeper) << "step " << k;
    }
    ASSERT_LT(s.bodies[1].v_WB.norm(), 0.1) << "step " << k;
  }
  EXPECT_NEAR(s.bodies[1].p_WB.z(), 0.3, 1e-4);
}

/// 100 boxes (10 cm cubes) over a 2 × 2 m room, turned every way, dropped.
struct Room {
  core::Model model;
  core::State start;
};

Room roomOfBoxes() {
  const core::Sdf room =
      core::Sdf::subtract({core::Sdf::box(Vec3(2.2, 2.2, 1.2)).transformed({Quat::Identity(), Vec3(0, 0, 0.5)}),
                           core::Sdf::box(Vec3(2.0, 2.0, 1.5)).transformed({Quat::Identity(), Vec3(0, 0, 0.75)})});
  std::vector<core::BodySpec> boxes;
  for (int i = 0; i < 100; ++i) boxes.push_back(named(boxBody(Vec3(0.05, 0.05, 0.05), 0.5), "box" + std::to_string(i)));
  core::ModelSpec spec = world(boxes, Vec3(0, 0, -9.81), 0.2, {room});
  Room r{core::Model(spec), {}};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int i = 0; i < 100; ++i) {
    const Vec3 p(-0.8 + 0.4 * (i % 5), -0.8 + 0.4 * ((i / 5) % 5), 0.3 + 0.25 * (i / 25));
    const Quat q(Eigen::AngleAxisd(angle(rng), Vec3(angle(rng), angle(rng), angle(rng)).normalized()));
    r.start.bodies.push_back(at(r.model, i, p, Vec3::Zero(), q));
  }
  return r;
}

// A box lying 1 mm above the ground, still, is struck on one end by a
// tilted box falling at 4 m/s: the blow drives that end down in the step.
// The struck box's own motion gave its ground contacts no margin, so the
// corners 1 mm up were not in the step's set and went through (the pile of
// 10,000 boxes: 2.4 mm). A body's margin against the scene grows by the
// margin of the bodies that may strike it (physics §5.1); over ten phases
// of the blow against the step grid, nothing goes below the position slop.
TEST(Tunneling, ABoxStruckOnTheGroundIsNotDrivenThroughIt) {
  const Vec3 half(0.2, 0.1, 0.05);
  core::ModelSpec ms = world({named(boxBody(half), "struck"), named(boxBody(half), "striker")}, Vec3(0, 0, -9.81), 0.5,
                             {core::Sdf::plane(Vec3::UnitZ())});
  ms.sleep.enabled = false;
  const core::Model model(ms);
  const Quat tilt(Eigen::AngleAxisd(-0.5, Vec3::UnitY()));
  const Vec3 lowest = tilt * Vec3(-half.x(), 0.0, -half.z());  // the striker's lowest edge, from its centre
  double deepest = 0.0;
  for (int phase = 0; phase < 10; ++phase) {
    core::State s;
    const double top = 2 * half.z() + 1e-3, gap = 1e-3 + 4e-4 * phase;
    s.bodies = {at(model, 0, Vec3(0, 0, half.z() + 1e-3)),
                at(model, 1, Vec3(0.17, 0, top + gap) - lowest, Vec3(0, 0, -4), tilt)};
    core::Workspace ws;
    for (int n = 0; n < 50; ++n) {
      core::step(model, s, {}, &ws);
      deepest = std::max(deepest, ws.deepest_penetration);
    }
    EXPECT_LT(s.bodies[0].w_B.norm() + s.bodies[1].v_WB.norm(), 50.0);  // struck, not thrown off
  }
  EXPECT_LT(deepest, model.contact().position_slop);
}

TEST(Room, HundredBoxesStayInsideDoNotSinkAndRest) {
  const Room room = roomOfBoxes();
  core::State s = room.start;
  core::Workspace ws;
  double deepest = 0.0, gained = 0.0;
  const auto energy = [&](int i) {
    const core::BodyModel& b = room.model.body(i);
    return core::kineticEnergy(b, s.bodies[i]) + core::potentialEnergy(b, s.bodies[i], room.model.gravity());
  };
  std::vector<double> before(100);
  std::vector<char> touches_body(100);
  for (int k = 0; k < 10000; ++k) {  // the last few settle on each other after 7 s
    for (int i = 0; i < 100; ++i) before[i] = energy(i);
    core::step(room.model, s, {}, &ws);
    deepest = std::max(deepest, ws.deepest_penetration);
    // A box touching only the room can only lose energy, to the solver's
    // tolerance (1e-7 m/s: about 1e-9 J a step for these 0.5 kg boxes).
    std::fill(touches_body.begin(), touches_body.end(), 0);
    for (const core::Contact& c : ws.contacts) {
      if (c.other >= 0) touches_body[c.body] = touches_body[c.other] = 1;
    }
    for (int i = 0; i < 100; ++i) {
      if (!touches_body[i]) gained = std::max(gained, energy(i) - before[i]);
    }
  }
  EXPECT_LT(deepest, 2e-3);
  EXPECT_LT(gained, 1e-9);
  int resting = 0;
  for (const core::BodyState& b : s.bodies) {
    EXPECT_LT(b.p_WB.head<2>().cwiseAbs().maxCoeff(), 1.0);  // inside the walls
    EXPECT_GT(b.p_WB.z(), 0.0);                              // above the floor
    resting += core::atRest(room.model, b);
  }
  EXPECT_EQ(resting, 100);
}

TEST(Determinism, ARoomOfBoxesIsBitIdenticalRunToRun) {
  const Room room = roomOfBoxes();
  auto run = [&] {
    core::State s = room.start;
    for (int k = 0; k < 1500; ++k) core::step(room.model, s);
    return s;
  };
  EXPECT_TRUE(bitIdentical(run(), run()));
}

// A world is a fixed point of the step only when every body in it is: here a
// two-box stack, which falls asleep, and three boxes dropped tumbling on
// the ground, one of them pushed later. The skipped steps must give the
// bits of the computed ones, and there must be skipped steps.
TEST(Determinism, SkippingAFixedPointGivesTheStepsComputedInFull) {
  const core::Model model(stack(true));
  core::State a;
  for (int i = 0; i < 5; ++i) {
    const Quat q(Eigen::AngleAxisd(0.4 * i, Vec3(1, 2, 0.3 * i).normalized()));
    a.bodies.push_back(i < 2 ? at(model, i, Vec3(0, 0, 0.1 + 0.2 * i))
                             : at(model, i, Vec3(i, 0, 0.3), Vec3::Zero(), q));
  }
  core::State b = a;
  core::Workspace skipping, computing;
  computing.skip_fixed_points = false;
  core::Loads push(5);
  core::addWrench(model.body(4), push[4], {Vec3(20, 0, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld});
  std::size_t skipped_before_push = 0;
  for (int k = 0; k < 5000; ++k) {
    if (k == 3000) skipped_before_push = skipping.skipped_steps;
    const core::Loads& loads = k >= 3000 && k < 3010 ? push : core::Loads{};
    core::step(model, a, loads, &skipping);
    core::step(model, b, loads, &computing);
    ASSERT_TRUE(bitIdentical(a, b)) << "step " << k;
  }
  EXPECT_GT(skipped_before_push, 500u);
  EXPECT_GT(skipping.skipped_steps, skipped_before_push + 500u);
  EXPECT_TRUE(a.bodies[0].asleep && a.bodies[1].asleep);
}

TEST(Determinism, OneThreadOrTwoGiveTheSameBits) {
  const Room room = roomOfBoxes();
  auto run = [&](int threads) {
    core::State s = room.start;
    core::Workspace ws;
    ws.threads = threads;
    ws.min_parallel_work = 1;  // split even this small world
    for (int k = 0; k < 1500; ++k) core::step(room.model, s, {}, &ws);
    return s;
  };
  EXPECT_TRUE(bitIdentical(run(1), run(2)));
}

}  // namespace
}  // namespace rigid_body_sim::test
