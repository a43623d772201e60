// A world as it runs with robots in it (core::Simulation over a Scene): it
// steps as the scene does, its edits move the links' indices with the free
// bodies', reset puts the robots back, and what it refuses changes nothing.
#include "rigid_body_sim/core/step/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "../../test_util.h"
#include "../articulations/articulation_models.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kH = 1e-3;

/// A 1 kg, 0.4 m bar hanging from a hinge about y at (0, 0, `hinge_z`),
/// released from horizontal: from 1.5 m it swings clear of the floor.
ArticulationModel pendulum(double hinge_z) {
  ArticulationModel model = test::oneJoint(JointType::Revolute, "bar", "hinge", Vec3(0.0, 0.0, hinge_z), Vec3::UnitY());
  ArticulatedLink& bar = model.links[1];
  bar.limits.lower = -4.0;
  bar.limits.upper = 4.0;
  bar.limits.effort = 10.0;
  const Vec3 size(0.4, 0.05, 0.05), centre(0.2, 0.0, 0.0);
  bar.mass = test::boxMass(1.0, size, centre);
  bar.collision = {test::boxShape(size, centre)};
  checkArticulation(model);
  return model;
}

BodySpec box(const std::string& name) {
  BodySpec b = test::boxBody(Vec3(0.1, 0.1, 0.1));
  b.name = name;
  return b;
}

/// Boxes "a", "b", ... dropped on a floor at x = 3, 6, ... (far from the
/// pendulum and from each other) and the pendulum released from horizontal.
struct World {
  Scene scene;
  SceneState start;

  explicit World(const std::vector<std::string>& boxes, double hinge_z = 1.5)
      : scene(spec(boxes), {{"arm", pendulum(hinge_z)}}) {
    State free;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      LinkState X;
      X.p_WL = Vec3(3.0 * (boxes[i][0] - 'a' + 1), 0.0, 0.5);
      free.bodies.push_back(bodyStateFromLink(scene.model().body(i), X));
    }
    start = sceneState(scene, free, {restState(scene.robots()[0].model, Pose())});
  }

  static ModelSpec spec(const std::vector<std::string>& boxes) {
    ModelSpec s;
    s.dt = kH;
    s.scene = {Sdf::plane(Vec3::UnitZ())};
    for (const std::string& name : boxes) s.bodies.push_back(box(name));
    return s;
  }
};

void expectSameBody(const BodyState& a, const BodyState& b) {
  EXPECT_EQ(a.p_WB, b.p_WB);
  EXPECT_EQ(a.q_WB.coeffs(), b.q_WB.coeffs());
  EXPECT_EQ(a.v_WB, b.v_WB);
  EXPECT_EQ(a.w_B, b.w_B);
}

TEST(Simulation, StepsAsTheSceneDoes) {
  World w({"a", "b"});
  Simulation sim(w.scene, w.start);
  SceneState direct = w.start;
  SceneWorkspace ws;
  for (int n = 0; n < 600; ++n) {
    sim.step({});
    stepScene(w.scene, direct, {}, ws);
  }
  ASSERT_EQ(sim.state.bodies.size(), 3u);  // two boxes, the bar
  for (std::size_t i = 0; i < 3; ++i) expectSameBody(sim.state.bodies[i], direct.bodies.bodies[i]);
  EXPECT_EQ(sim.robots[0].q, direct.robots[0].q);
  EXPECT_EQ(sim.robots[0].v, direct.robots[0].v);
  EXPECT_GT(std::abs(sim.robots[0].q[0]), 0.5);  // it swung
  EXPECT_EQ(sim.workspace.bodies.contacts.size(), ws.bodies.contacts.size());
}

// Deleting a free body moves the links down one index everywhere, and the
// robot and the other body step on bit for bit as in a world that never had it.
TEST(Simulation, RemovingABodyMovesTheLinksDown) {
  World three({"a", "b"}), two({"b"});
  Simulation sim(three.scene, three.start);
  Simulation without(two.scene, two.start);
  for (int n = 0; n < 300; ++n) {
    sim.step({});
    without.step({});
  }
  sim.removeBody(0);
  EXPECT_EQ(sim.scene.robots()[0].first_body, 1);
  EXPECT_EQ(sim.scene.robotOf(1), 0);
  EXPECT_EQ(sim.model().body(1).name, "arm/bar");
  for (int n = 0; n < 300; ++n) {
    sim.step({});
    without.step({});
  }
  for (std::size_t i = 0; i < 2; ++i) expectSameBody(sim.state.bodies[i], without.state.bodies[i]);
  EXPECT_EQ(sim.robots[0].q, without.robots[0].q);
}

// A free body spawned beside a robot goes before its links, which move up
// one index everywhere (the contact impulses' warm starts renamed with
// them): from then on the world steps bit for bit as one that had the body
// from the start. The bar, hinged low, is on the floor by then (not yet
// asleep), so its link has warm starts to keep; the new box is high up,
// still falling.
TEST(Simulation, ABodySpawnedBesideARobotGoesBeforeItsLinks) {
  World one({"a"}, 0.3), two({"a", "b"}, 0.3);
  LinkState high;
  high.p_WL = Vec3(6.0, 0.0, 100.0);
  two.start.bodies.bodies[1] = bodyStateFromLink(two.scene.model().body(1), high);
  Simulation sim(one.scene, one.start);
  Simulation with(two.scene, two.start);
  for (int n = 0; n < 500; ++n) {
    sim.step({});
    with.step({});
  }
  const auto onLink = [](const State& s, int link) {
    return std::count_if(s.contact_impulses.begin(), s.contact_impulses.end(),
                         [&](const ContactImpulse& c) { return c.body == link || c.other == link; });
  };
  ASSERT_GT(onLink(sim.state, 1), 0) << "the bar is not on the floor";
  const BodyState spawned = with.state.bodies[1];
  sim.addBody(sim.model().bodyBuilder().build(box("b")), spawned);
  EXPECT_EQ(sim.model().body(1).name, "b");
  EXPECT_EQ(sim.model().body(2).name, "arm/bar");
  EXPECT_EQ(sim.scene.robots()[0].first_body, 2);
  EXPECT_EQ(sim.scene.robotOf(2), 0);
  EXPECT_EQ(sim.scene.robotOf(1), -1);
  EXPECT_EQ(onLink(sim.state, 2), onLink(with.state, 2));  // the bar's warm starts, renamed
  for (int n = 0; n < 300; ++n) {
    sim.step({});
    with.step({});
  }
  for (std::size_t i = 0; i < 3; ++i) expectSameBody(sim.state.bodies[i], with.state.bodies[i]);
  EXPECT_EQ(sim.robots[0].q, with.robots[0].q);
  EXPECT_EQ(sim.robots[0].v, with.robots[0].v);
  sim.reset(0.0);  // a reset puts the spawned body where it was spawned
  expectSameBody(sim.state.bodies[1], spawned);
}

// A robot added to a running world goes last, its links after every body:
// from then on the world steps bit for bit as one made with it. A second
// robot of the same name is refused and changes nothing.
TEST(Simulation, ARobotAddedGoesLastAndStepsAsOneMadeWithIt) {
  World one({"a"});
  const Pose there{Quat::Identity(), Vec3(-3.0, 0.0, 0.0)};
  Scene made(World::spec({"a"}), {{"arm", pendulum(1.5)}, {"low", pendulum(0.3)}});
  std::vector<ArticulationState> robots{one.start.robots[0], restState(made.robots()[1].model, there)};
  Simulation with(made, sceneState(made, one.start.bodies, robots));
  Simulation sim(one.scene, one.start);
  sim.addRobot({"low", pendulum(0.3)}, robots[1]);
  ASSERT_EQ(sim.model().bodyCount(), 3u);
  EXPECT_EQ(sim.model().body(2).name, "low/bar");
  EXPECT_EQ(sim.scene.robots()[1].first_body, 2);
  EXPECT_EQ(sim.scene.robotOf(2), 1);
  EXPECT_NE(sim.model().body(2).collision_group, sim.model().body(1).collision_group);
  expectSameBody(sim.state.bodies[2], with.state.bodies[2]);  // its link placed where it starts
  for (int n = 0; n < 600; ++n) {
    sim.step({});
    with.step({});
  }
  for (std::size_t i = 0; i < 3; ++i) expectSameBody(sim.state.bodies[i], with.state.bodies[i]);
  for (std::size_t r = 0; r < 2; ++r) {
    EXPECT_EQ(sim.robots[r].q, with.robots[r].q);
    EXPECT_EQ(sim.robots[r].v, with.robots[r].v);
  }
  const State before = sim.state;
  EXPECT_THROW(sim.addRobot({"low", pendulum(1.0)}, robots[1]), std::invalid_argument);
  ASSERT_EQ(sim.model().bodyCount(), 3u);
  ASSERT_EQ(sim.robots.size(), 2u);
  for (std::size_t i = 0; i < 3; ++i) expectSameBody(sim.state.bodies[i], before.bodies[i]);
  sim.reset(0.0);  // a reset puts the added robot back where it was added
  EXPECT_EQ(sim.robots[1].q, robots[1].q);
}

// A robot deleted goes from every table at once: its links, its state and
// start, its timed joint efforts; the later robot's links and efforts move
// down with it. From then on the world steps bit for bit as one made without
// it (the robot's timed effort still on the robot it was given to), a reset
// puts the robot left where it started, and no robot r refuses, changing nothing.
TEST(Simulation, ARobotRemovedLeavesTheWorldAsOneMadeWithoutIt) {
  const Pose there{Quat::Identity(), Vec3(-3.0, 0.0, 0.0)};
  Scene both(World::spec({"a"}), {{"arm", pendulum(1.5)}, {"low", pendulum(0.3)}});
  Scene alone(World::spec({"a"}), {{"low", pendulum(0.3)}});
  const World one({"a"});
  const ArticulationState low = restState(alone.robots()[0].model, there);
  Simulation sim(both, sceneState(both, one.start.bodies, {one.start.robots[0], low}));
  Simulation without(alone, sceneState(alone, one.start.bodies, {low}));
  sim.joint_efforts.add(1, 1, 2.0, 0.0, 0.2);  // on "low"'s hinge, for 0.2 s
  without.joint_efforts.add(0, 1, 2.0, 0.0, 0.2);

  EXPECT_THROW(sim.removeRobot(2), std::invalid_argument);
  ASSERT_EQ(sim.robots.size(), 2u);
  ASSERT_EQ(sim.model().bodyCount(), 3u);
  sim.removeRobot(0);
  ASSERT_EQ(sim.scene.robots().size(), 1u);
  ASSERT_EQ(sim.model().bodyCount(), 2u);
  EXPECT_EQ(sim.model().body(1).name, "low/bar");
  EXPECT_EQ(sim.scene.robots()[0].first_body, 1);
  EXPECT_EQ(sim.scene.robotOf(1), 0);
  const auto loads = [](const Simulation& s) {
    std::vector<ArticulationLoads> l(1);
    l[0].effort = Eigen::VectorXd::Zero(1);
    s.joint_efforts.addEfforts(0, s.state.time, kH, l[0].effort);
    return l;
  };
  for (int n = 0; n < 600; ++n) {
    sim.step({}, loads(sim));
    without.step({}, loads(without));
  }
  EXPECT_GT(std::abs(sim.robots[0].q[0] - low.q[0]), 0.1);  // it moved
  for (std::size_t i = 0; i < 2; ++i) expectSameBody(sim.state.bodies[i], without.state.bodies[i]);
  EXPECT_EQ(sim.robots[0].q, without.robots[0].q);
  EXPECT_EQ(sim.robots[0].v, without.robots[0].v);
  sim.reset(1.0);
  EXPECT_EQ(sim.robots[0].q, low.q);
  expectSameBody(sim.state.bodies[1], without.initial.bodies[1]);
}

// An entity's id names it through every other edit, and once it is
// removed its id is refused, even after a new entity is added in its place.
TEST(Simulation, IdsNameTheirEntityUntilItGoes) {
  World w({"a", "b", "c"});
  Simulation sim(w.scene, w.start);
  const EntityId a = sim.bodyId(0), b = sim.bodyId(1), c = sim.bodyId(2), arm = sim.robotId(0);
  EXPECT_NE(a, b);
  EXPECT_EQ(sim.bodyIndex(c), 2);
  EXPECT_EQ(sim.bodyIndex(EntityId{}), std::nullopt);  // a default id names nothing
  sim.removeBody(1);
  EXPECT_EQ(sim.bodyIndex(a), 0);
  EXPECT_EQ(sim.bodyIndex(b), std::nullopt);
  EXPECT_EQ(sim.bodyIndex(c), 1);
  EXPECT_EQ(sim.model().body(*sim.bodyIndex(c)).name, "c");
  const EntityId d = sim.addBody(sim.model().bodyBuilder().build(box("d")), BodyState{});
  EXPECT_NE(d, b);  // b's slot again, a newer generation
  EXPECT_EQ(d.slot, b.slot);
  EXPECT_EQ(sim.bodyIndex(b), std::nullopt);
  EXPECT_EQ(sim.bodyIndex(d), 2);
  EXPECT_EQ(sim.model().body(2).name, "d");
  const EntityId low = sim.addRobot({"low", pendulum(0.3)}, restState(pendulum(0.3), Pose()));
  sim.removeRobot(0);
  EXPECT_EQ(sim.robotIndex(arm), std::nullopt);
  EXPECT_EQ(sim.robotIndex(low), 0u);
  EXPECT_EQ(sim.scene.robots()[0].name, "low");
  EXPECT_THROW(sim.bodyId(3), std::out_of_range);  // a link, not a free body
  EXPECT_THROW(sim.robotId(1), std::out_of_range);
}

TEST(Simulation, ResetPutsTheRobotsBack) {
  World w({"a"});
  Simulation sim(w.scene, w.start);
  for (int n = 0; n < 400; ++n) sim.step({});
  ASSERT_NE(sim.robots[0].q, w.start.robots[0].q);
  sim.reset(7.0);
  EXPECT_EQ(sim.robots[0].q, w.start.robots[0].q);
  EXPECT_EQ(sim.robots[0].v, w.start.robots[0].v);
  expectSameBody(sim.state.bodies[1], w.start.bodies.bodies[1]);  // the bar's link, where it started
  EXPECT_EQ(sim.state.time, 7.0);
}

TEST(Simulation, RefusedEditsAndLoadsChangeNothing) {
  World w({"a"});
  Simulation sim(w.scene, w.start);
  for (int n = 0; n < 100; ++n) sim.step({});
  const State before = sim.state;
  const std::vector<ArticulationState> robots_before = sim.robots;
  EXPECT_THROW(sim.removeBody(1), std::invalid_argument);          // the bar: a link, not a free body
  PreparedBody taken = sim.model().bodyBuilder().build(box("a"));  // a's name is taken
  EXPECT_THROW(sim.addBody(taken, BodyState{}), std::invalid_argument);
  Loads on_link(2);
  on_link[1].force_W = Vec3(1.0, 0.0, 0.0);  // the bar's: a robot's loads are its own
  EXPECT_THROW(sim.step(on_link), std::invalid_argument);
  ASSERT_EQ(sim.state.bodies.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) expectSameBody(sim.state.bodies[i], before.bodies[i]);
  EXPECT_EQ(sim.state.time, before.time);
  EXPECT_EQ(sim.robots[0].q, robots_before[0].q);
  sim.step(Loads(2));  // per body, the link's zero: taken
  EXPECT_GT(sim.state.time, before.time);
}

}  // namespace
}  // namespace rigid_body_sim::core
