// Bodies added and removed between steps (issue 14's spawn and delete, in
// the core): Model::withBody and withoutBody with removeBody on the state.
// A spawned body collides from the next step; a deleted one takes its
// contacts with it, wakes what rested on it, and changes no bit of bodies
// that never touched it; the same edits at the same steps give the same bits.
#include <gtest/gtest.h>

#include <optional>
#include <thread>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

const Vec3 kHalf(0.2, 0.1, 0.05);

core::BodySpec named(core::BodySpec b, const std::string& name) {
  b.name = name;
  return b;
}

core::BodyState at(const core::Model& model, int i, const Vec3& p, const Vec3& v = Vec3::Zero()) {
  core::LinkState link;
  link.p_WL = p;
  link.v_WL = v;
  return core::bodyStateFromLink(model.body(i), link);
}

core::ModelSpec ground(std::vector<core::BodySpec> bodies) {
  core::ModelSpec s = onGround(bodies.front(), impulse(0.0, 0.5));
  s.bodies = std::move(bodies);
  return s;
}

void run(const core::Model& model, core::State& s, core::Workspace& ws, int steps) {
  for (int n = 0; n < steps; ++n) core::step(model, s, {}, &ws);
}

TEST(WorldEdit, AFarBodysDeletionChangesNoBitOfTheOthers) {
  // a slides on the ground, b falls far away, c rests: deleting b at step 500
  // leaves a and c exactly where a world without b ever puts them.
  const std::vector<core::BodySpec> three = {named(boxBody(kHalf), "a"), named(boxBody(kHalf), "b"),
                                             named(boxBody(kHalf), "c")};
  const core::Model with_b(ground(three));
  core::State s;
  s.bodies = {at(with_b, 0, Vec3(0, 0, kHalf.z()), Vec3(1, 0, 0)), at(with_b, 1, Vec3(20, 20, 5)),
              at(with_b, 2, Vec3(0, 5, kHalf.z()))};
  const core::Model without_b(ground({three[0], three[2]}));
  core::State t;
  t.bodies = {s.bodies[0], s.bodies[2]};
  core::Workspace ws, wt;
  ws.threads = wt.threads = 1;
  run(with_b, s, ws, 500);
  const core::Model edited = with_b.withoutBody(1);
  core::removeBody(with_b, s, 1);
  core::Workspace fresh;
  fresh.threads = 1;
  run(edited, s, fresh, 500);
  run(without_b, t, wt, 1000);
  ASSERT_EQ(edited.bodyCount(), 2u);
  EXPECT_EQ(edited.body(1).name, "c");
  EXPECT_TRUE(bitIdentical(s, t));
}

TEST(WorldEdit, ABodyRestingOnADeletedOneWakesAndFalls) {
  const core::Model model(ground({named(boxBody(Vec3(0.5, 0.5, 0.1), 10.0), "base"), named(boxBody(kHalf), "top")}));
  core::State s;
  s.bodies = {at(model, 0, Vec3(0, 0, 0.1)), at(model, 1, Vec3(0, 0, 0.2 + kHalf.z()))};
  core::Workspace ws;
  run(model, s, ws, 2000);
  ASSERT_TRUE(s.bodies[1].asleep);  // resting on the base
  const core::Model edited = model.withoutBody(0);
  core::removeBody(model, s, 0);
  EXPECT_FALSE(s.bodies[0].asleep);
  for (const core::ContactImpulse& c : s.contact_impulses) EXPECT_EQ(c.other, -1);  // none with the base
  core::Workspace fresh;
  run(edited, s, fresh, 1000);
  EXPECT_NEAR(s.bodies[0].p_WB.z(), kHalf.z(), 1e-3);  // fell onto the ground
}

TEST(WorldEdit, ASpawnedBodyCollidesFromTheNextStep) {
  // A one-body world (no solids yet) gains a ball above its box: the box
  // gets its solid, and the ball comes to rest on it.
  const core::Model one(ground({named(boxBody(kHalf), "box")}));
  core::State s;
  s.bodies = {at(one, 0, Vec3(0, 0, kHalf.z()))};
  core::Workspace ws;
  run(one, s, ws, 10);
  const double radius = 0.05;
  const core::Model two = one.withBody(named(ballBody(radius), "ball"));
  ASSERT_EQ(two.bodyCount(), 2u);
  EXPECT_FALSE(two.body(0).solid_B.empty());
  s.bodies.push_back(at(two, 1, Vec3(0, 0, 0.5)));
  core::Workspace fresh;
  run(two, s, fresh, 2000);
  EXPECT_NEAR(s.bodies[1].p_WB.z(), 2 * kHalf.z() + radius, 2e-3);  // on the box, not through it
  EXPECT_NEAR(s.bodies[0].p_WB.z(), kHalf.z(), 1e-3);
}

TEST(WorldEdit, TheSameEditsAtTheSameStepsGiveTheSameBits) {
  const auto once = [] {
    core::Model model(ground({named(boxBody(kHalf), "a"), named(boxBody(kHalf), "b")}));
    core::State s;
    s.bodies = {at(model, 0, Vec3(0, 0, 0.5)), at(model, 1, Vec3(0.1, 0, 1.0))};
    core::Workspace ws;
    run(model, s, ws, 100);
    model = model.withBody(named(ballBody(0.1), "c"));
    s.bodies.push_back(at(model, 2, Vec3(0, 0.05, 2.0), Vec3(0.5, 0, 0)));
    run(model, s, ws, 200);
    core::removeBody(model, s, 0);
    model = model.withoutBody(0);
    run(model, s, ws, 300);
    return s;
  };
  EXPECT_TRUE(bitIdentical(once(), once()));
}

// The node edits its model in place between steps (an edited copy of a
// world of 1,000 bodies cost the loop milliseconds and the heap its
// copies) and keeps its worker threads: the bits are those of the copies.
TEST(WorldEdit, EditsInPlaceGiveTheBitsOfEditedCopies) {
  const core::ModelSpec spec = ground({named(boxBody(kHalf), "a"), named(boxBody(kHalf), "b")});
  const auto start = [](const core::Model& model) {
    core::State s;
    s.bodies = {at(model, 0, Vec3(0, 0, 0.5)), at(model, 1, Vec3(0.1, 0, 1.0))};
    return s;
  };
  const auto two_threads = [] {
    core::Workspace ws;
    ws.threads = 2;
    ws.min_parallel_work = 1;
    return ws;
  };
  const core::Model first(spec);
  core::State copied = start(first);
  {
    core::Model model = first;
    core::Workspace ws = two_threads();
    run(model, copied, ws, 100);
    model = model.withBody(named(ballBody(0.1), "c"));
    ws = two_threads();
    copied.bodies.push_back(at(model, 2, Vec3(0, 0.05, 2.0), Vec3(0.5, 0, 0)));
    run(model, copied, ws, 200);
    core::removeBody(model, copied, 0);
    model = model.withoutBody(0);
    ws = two_threads();
    run(model, copied, ws, 300);
  }
  core::State in_place = start(first);
  core::Model model = first;
  core::Workspace ws = two_threads();
  run(model, in_place, ws, 100);
  model.addBody(model.bodyBuilder().build(named(ballBody(0.1), "c")));
  ws = ws.forEditedModel();
  EXPECT_EQ(ws.threads, 2);
  in_place.bodies.push_back(at(model, 2, Vec3(0, 0.05, 2.0), Vec3(0.5, 0, 0)));
  run(model, in_place, ws, 200);
  core::removeBody(model, in_place, 0);
  model.removeBody(0);
  ws = ws.forEditedModel();
  run(model, in_place, ws, 300);
  EXPECT_TRUE(bitIdentical(copied, in_place));
  EXPECT_EQ(model.bodyCount(), 2u);
  EXPECT_EQ(model.body(1).name, "c");
}

// The node deletes through core::Simulation: one call takes the body out of
// the model, the state, the initial state, the schedule and the contact
// ledger, and every later index moves down in all of them alike.
TEST(WorldEdit, ASimulationTakesABodyOutOfEveryTableAtOnce) {
  // a slides far off; b is a heavy base with c asleep on it; d rests alone.
  core::Model model(ground({named(boxBody(kHalf), "a"), named(boxBody(Vec3(0.5, 0.5, 0.1), 10.0), "b"),
                            named(boxBody(kHalf), "c"), named(boxBody(kHalf), "d")}));
  core::State start;
  start.bodies = {at(model, 0, Vec3(-5, 0, kHalf.z())), at(model, 1, Vec3(0, 0, 0.1)),
                  at(model, 2, Vec3(0, 0, 0.2 + kHalf.z())), at(model, 3, Vec3(5, 0, kHalf.z()))};
  core::Simulation sim(model, start);
  const double forever = core::WrenchSchedule::kForever;
  const core::Wrench push{Vec3(0.5, 0, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld};
  sim.schedule.add(0, push, 100.0, forever, 1);  // on a, in b's axes: goes with b
  sim.schedule.add(3, push, 100.0, forever);     // on d: stays, as body 2
  for (int n = 0; n < 2000; ++n) {
    core::step(sim.model(), sim.state, {}, &sim.workspace.bodies);
    sim.contacts.update(sim.state, sim.workspace.bodies.contacts);
  }
  ASSERT_TRUE(sim.state.bodies[2].asleep);  // c on b
  ASSERT_FALSE(sim.contacts.kept().empty());
  const core::State before = sim.state;

  EXPECT_EQ(sim.removeBody(1), 1u);  // a's wrench in b's axes

  ASSERT_EQ(sim.model().bodyCount(), 3u);
  EXPECT_EQ(sim.model().body(1).name, "c");
  EXPECT_EQ(sim.model().body(2).name, "d");
  ASSERT_EQ(sim.state.bodies.size(), 3u);
  ASSERT_EQ(sim.initial.bodies.size(), 3u);
  EXPECT_EQ(sim.initial.bodies[1].p_WB, start.bodies[2].p_WB);  // c's start, now body 1
  EXPECT_EQ(sim.initial.bodies[2].p_WB, start.bodies[3].p_WB);
  EXPECT_EQ(sim.state.bodies[2].p_WB, before.bodies[3].p_WB);
  EXPECT_FALSE(sim.state.bodies[1].asleep);  // c lost its base
  for (const core::Contact& c : sim.contacts.kept()) {
    EXPECT_NE(c.body, 1);  // none of c's kept contacts with the deleted base
    EXPECT_LT(c.other, 3);
  }
  EXPECT_EQ(sim.schedule.count(0), 0u);
  EXPECT_EQ(sim.schedule.count(2), 1u);  // d's, moved down with d
  // c falls onto the ground, and reset puts every body where it started.
  for (int n = 0; n < 1000; ++n) core::step(sim.model(), sim.state, {}, &sim.workspace.bodies);
  EXPECT_NEAR(sim.state.bodies[1].p_WB.z(), kHalf.z(), 1e-3);
  sim.reset(7.0);
  EXPECT_EQ(sim.state.time, 7.0);
  EXPECT_EQ(sim.state.bodies[1].p_WB, start.bodies[2].p_WB);
  EXPECT_EQ(sim.schedule.size(), 0u);
}

// set_state in the node: a body put somewhere keeps no warm start (its
// impulses belonged to contacts at the old pose) and is awake to move on.
TEST(WorldEdit, ABodyPlacedElsewhereKeepsNoWarmStart) {
  const core::Model model(ground({named(boxBody(kHalf), "a")}));
  core::State s;
  s.bodies = {at(model, 0, Vec3(0, 0, kHalf.z()))};
  core::Simulation sim(model, s);
  for (int n = 0; n < 20; ++n) core::step(sim.model(), sim.state, {}, &sim.workspace.bodies);
  ASSERT_FALSE(sim.state.contact_impulses.empty());  // resting on the ground, not yet asleep
  ASSERT_GT(sim.state.bodies[0].still_time, 0.0);
  core::BodyState there = at(model, 0, Vec3(3, 0, 1));
  there.still_time = 0.5;  // whatever the caller's copy says: it is to move
  sim.place(0, there);
  EXPECT_TRUE(sim.state.contact_impulses.empty());
  EXPECT_FALSE(sim.state.bodies[0].asleep);
  EXPECT_EQ(sim.state.bodies[0].still_time, 0.0);
  EXPECT_EQ(sim.state.bodies[0].p_WB, Vec3(3, 0, 1));
  for (int n = 0; n < 1000; ++n) core::step(sim.model(), sim.state, {}, &sim.workspace.bodies);
  EXPECT_NEAR(sim.state.bodies[0].p_WB.z(), kHalf.z(), 1e-3);  // fell from there
  EXPECT_THROW(sim.place(1, s.bodies[0]), std::out_of_range);
}

// A body the model refuses only beside the others (here the penalty
// spring, which no builder checks: it needs the step) leaves the model as
// it was, in place too.
TEST(WorldEdit, AnAddBodyTheModelRefusesLeavesItAsItWas) {
  core::ModelSpec spec = ground({named(boxBody(kHalf), "box")});
  spec.contact.method = core::ContactMethod::kPenaltyQuadratic;
  spec.contact.penalty_stiffness = 1e5;  // k dt^2 / m = 0.1 for the 1 kg box at dt = 1 ms
  core::Model model(spec);
  core::BodySpec light = named(ballBody(0.01), "light");
  light.mass = 1e-3;  // k dt^2 / m = 100: unstable
  const core::PreparedBody prepared = model.bodyBuilder().build(light);
  expectThrowsWith<std::invalid_argument>([&] { model.addBody(prepared); },
                                          {"contact.penalty_stiffness", "body 'light'"});
  EXPECT_EQ(model.bodyCount(), 1u);
  EXPECT_EQ(model.body(0).name, "box");
  model.addBody(model.bodyBuilder().build(named(boxBody(kHalf), "second")));
  EXPECT_EQ(model.bodyCount(), 2u);
}

TEST(WorldEdit, ABodyBuiltOnAnotherThreadIsTheBodyWithBodyBuilds) {
  // The node builds a spawned body off its loop (a mesh's grid takes
  // seconds) from a builder taken at start, while the model is retuned:
  // inserted later, it gives the bits of a body built at once. A retuned
  // scene surface reaches the prepared body too.
  const core::Model model(ground({named(boxBody(kHalf), "box")}));
  const core::BodyBuilder builder = model.bodyBuilder();
  std::optional<core::PreparedBody> prepared;
  std::thread([&] { prepared = builder.build(named(ballBody(0.1), "ball")); }).join();
  core::Tuning t = model.tuning();
  t.friction = 0.9;
  const core::Model retuned = model.retuned(t);
  const core::Model direct = retuned.withBody(named(ballBody(0.1), "ball"));
  const core::Model later = retuned.withBody(*prepared);
  EXPECT_EQ(later.body(1).friction, 0.9);
  const auto run_from = [&](const core::Model& m) {
    core::State s;
    s.bodies = {at(m, 0, Vec3(0, 0, kHalf.z())), at(m, 1, Vec3(0.05, 0, 0.4), Vec3(0.3, 0, 0))};
    core::Workspace ws;
    run(m, s, ws, 800);
    return s;
  };
  const core::State a = run_from(direct), b = run_from(later);
  EXPECT_TRUE(bitIdentical(a, b));
  EXPECT_GT(a.contact_impulses.size(), 0u);  // the ball ends on the box: both solids took part
}

TEST(WorldEdit, DeletingTheLastBodyLeavesAWorldThatSteps) {
  const core::Model one(ground({named(boxBody(kHalf), "box")}));
  core::State s;
  s.bodies = {at(one, 0, Vec3(0, 0, 1))};
  const core::Model none = one.withoutBody(0);
  core::removeBody(one, s, 0);
  EXPECT_EQ(none.bodyCount(), 0u);
  for (int n = 0; n < 10; ++n) core::step(none, s);
  EXPECT_NEAR(s.time, 0.01, 1e-15);
  // And gains one again.
  const core::Model again = none.withBody(named(boxBody(kHalf), "box"));
  s.bodies.push_back(at(again, 0, Vec3(0, 0, kHalf.z())));
  core::step(again, s);
  EXPECT_EQ(again.bodyCount(), 1u);
}

TEST(WorldEdit, BadEditsAreRefusedAndChangeNothing) {
  const core::Model model(ground({named(boxBody(kHalf), "box")}));
  expectThrowsWith<std::invalid_argument>([&] { (void)model.withBody(named(boxBody(kHalf), "box")); },
                                          {"name = 'box'", "another body has this name"});
  core::BodySpec heavy = named(boxBody(kHalf), "heavy");
  heavy.mass = -1.0;
  expectThrowsWith<std::invalid_argument>([&] { (void)model.withBody(heavy); }, {"body 'heavy': mass"});
  expectThrowsWith<std::invalid_argument>([&] { (void)model.withoutBody(3); }, {"no such body"});
  EXPECT_EQ(model.bodyCount(), 1u);
}

}  // namespace
}  // namespace rigid_body_sim::test
