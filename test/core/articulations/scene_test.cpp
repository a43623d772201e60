// Robots and free bodies in one scene (docs/physics.md §11.9): a pusher on
// a prismatic joint shoves a box across the floor, a lift raises a box, a
// floating robot and a box collide in zero gravity; each against its closed
// form or conservation law, in one solve.
#include "rigid_body_sim/core/articulations/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "../../test_util.h"
#include "articulation_models.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kG = 9.81;
constexpr double kH = 1e-3;

using test::boxMass;
using test::boxShape;

/// A world-fixed robot: one box link of `size` and `mass` on a prismatic
/// joint along `axis`, its origin at `origin` when q = 0.
ArticulationModel slider(const Vec3& axis, const Vec3& origin, const Vec3& size, double mass) {
  ArticulationModel model = test::oneJoint(JointType::Prismatic, "slider", "slide", origin, axis);
  ArticulatedLink& link = model.links[1];
  link.limits.effort = 1000.0;
  link.mass = boxMass(mass, size);
  link.collision = {boxShape(size)};
  checkArticulation(model);
  return model;
}

ModelSpec settings(const std::vector<BodySpec>& bodies, double friction, bool ground) {
  ModelSpec spec;
  spec.dt = kH;
  spec.bodies = bodies;
  if (ground) spec.scene = {Sdf::plane(Vec3::UnitZ())};
  spec.contact.friction = friction;
  return spec;
}

struct SceneRun {
  Scene scene;
  SceneState state;
  SceneLoads loads;
  SceneWorkspace ws;

  SceneRun(const ModelSpec& spec, std::vector<Scene::RobotSpec> robots, const std::vector<LinkState>& bodies,
           const std::vector<ArticulationState>& starts)
      : scene(spec, std::move(robots)) {
    State free = restState(Model(spec));
    for (std::size_t i = 0; i < bodies.size(); ++i)
      free.bodies[i] = bodyStateFromLink(scene.model().body(i), bodies[i]);
    state = sceneState(scene, free, starts);
  }
  void steps(int n) {
    for (int i = 0; i < n; ++i) stepScene(scene, state, loads, ws);
  }
  const BodyState& body(int i) const { return state.bodies.bodies[i]; }
};

/// Bit for bit the same pose and velocity.
bool sameBits(const BodyState& a, const BodyState& b) {
  return a.p_WB == b.p_WB && a.v_WB == b.v_WB && a.q_WB.coeffs() == b.q_WB.coeffs() && a.w_B == b.w_B;
}

LinkState at(const Vec3& p) {
  LinkState X;
  X.p_WL = p;
  return X;
}

Pose placed(const Vec3& p) {
  Pose X;
  X.translation = p;
  return X;
}

// A 2 kg pusher on a horizontal prismatic joint, its face against a 1 kg
// box on a frictionless floor, pushed with 20 N: pusher and box move as
// one, a = F / (M + m), the contact carrying m a. (With friction on the
// floor and on the face, how the box's weight splits between the floor and
// the face's friction is not determined by rigid contacts, so neither is
// the floor's friction: the platform below has friction's closed form.)
TEST(Scene, PusherShovesABox) {
  const double M = 2.0, m = 1.0, F = 20.0;
  const ArticulationModel pusher = slider(Vec3::UnitX(), Vec3(0.0, 0.0, 0.1), Vec3(0.1, 0.3, 0.1), M);
  const BodySpec box = test::boxBody(Vec3(0.1, 0.1, 0.1), m);
  SceneRun run(settings({box}, 0.0, true), {{"pusher", pusher}}, {at(Vec3(0.15, 0.0, 0.1))}, {restState(pusher)});
  run.loads.robots.resize(1);
  run.loads.robots[0].effort = Eigen::VectorXd::Constant(1, F);
  const int n = 500;
  run.steps(n);
  const double a = F / (M + m);
  // Verlet (§11.5): the step's velocity is the one at its middle, and the
  // pusher is exactly at a t² / 2; the box stays face to face.
  EXPECT_NEAR(run.body(0).v_WB.x(), a * (n - 0.5) * kH, 1e-9);
  EXPECT_NEAR(run.state.robots[0].v(0), run.body(0).v_WB.x(), 1e-9);
  EXPECT_NEAR(run.state.robots[0].q(0), a * kH * kH * n * n / 2.0, 1e-9);
  EXPECT_NEAR(run.body(0).p_WB.x() - 0.15, run.state.robots[0].q(0), 1e-9);
  EXPECT_NEAR(run.body(0).p_WB.z(), 0.1, 1e-6);
  EXPECT_LT(run.body(0).w_B.norm(), 1e-9);
  double push = 0.0;  // N·s, between pusher and box this step (found both ways: each's points in the other)
  for (const Contact& c : run.ws.bodies.contacts) {
    if (c.other >= 0) push += c.normal_impulse;
  }
  EXPECT_NEAR(push / kH, m * a, 1e-6);
}

// Two lanes of one scene: a 2 kg pusher on a prismatic joint (a robot) and
// a 2 kg free body, each frictionless and pushed with 20 N, shove a 1 kg
// box along a floor with μ = 0.5. Each box gains a h a step,
// a = (F − μ m g) / (M + m), whichever pushed it: a box behaves alike
// touched by a robot or by a body, to the free solve's velocity tolerance
// (1e-7 m/s). Only their starts differ: the robot's first step is half a
// step's (§11.5), the bodies' a whole one, so the robot's lane is behind
// by at most h F / (2 (M + m)) (its start knows the push, not the floor's
// friction). Then each
// pusher, at 1 m/s, strikes a box at rest in zero gravity, restitution 0.5:
// each box leaves at (1 + e) M / (M + m) times the speed.
TEST(Scene, ABoxPushedByARobotMovesAsOnePushedByABody) {
  const double M = 2.0, m = 1.0, F = 20.0, mu = 0.5;
  const ArticulationModel pusher = slider(Vec3::UnitX(), Vec3(0.0, 0.0, 0.1), Vec3(0.1, 0.3, 0.1), M);
  BodySpec body_pusher = test::boxBody(Vec3(0.05, 0.15, 0.1), M);
  body_pusher.name = "body_pusher";
  body_pusher.friction = 0.0;
  const BodySpec box = test::boxBody(Vec3(0.1, 0.1, 0.1), m);
  BodySpec other_box = box;
  other_box.name = "other_box";
  Scene::RobotSpec robot{"pusher", pusher};
  robot.friction = 0.0;
  const auto lanes = [&](const ModelSpec& spec, const Vec3& v_pusher) {
    ArticulationState start = restState(pusher);
    start.v(0) = v_pusher.x();
    LinkState body_start = at(Vec3(0.0, 2.0, 0.1));
    body_start.v_WL = v_pusher;
    return SceneRun(spec, {robot}, {at(Vec3(0.15, 0.0, 0.1)), body_start, at(Vec3(0.15, 2.0, 0.1))}, {start});
  };
  {
    SceneRun run = lanes(settings({box, body_pusher, other_box}, mu, true), Vec3::Zero());
    run.loads.robots.resize(1);
    run.loads.robots[0].effort = Eigen::VectorXd::Constant(1, F);
    run.loads.bodies.resize(3);
    run.loads.bodies[1].force_W = Vec3(F, 0.0, 0.0);
    const int n = 500;
    run.steps(n - 1);
    const double robot_lane = run.body(0).v_WB.x(), body_lane = run.body(2).v_WB.x();
    run.steps(1);
    const double a = (F - mu * m * kG) / (M + m), v = a * n * kH;
    const double tolerance = run.scene.model().solver().velocity_tolerance;  // m/s
    EXPECT_NEAR(run.body(0).v_WB.x() - robot_lane, a * kH, tolerance) << "the box the robot pushed";
    EXPECT_NEAR(run.body(2).v_WB.x() - body_lane, a * kH, tolerance) << "the box the body pushed";
    EXPECT_NEAR(run.body(2).v_WB.x(), v, tolerance);
    EXPECT_LE(run.body(0).v_WB.x(), v + tolerance);
    EXPECT_GE(run.body(0).v_WB.x(), v - 0.5 * kH * F / (M + m) - tolerance);
  }
  {
    ModelSpec spec = settings({box, body_pusher, other_box}, mu, false);
    spec.gravity_W = Vec3::Zero();
    spec.contact.restitution = 0.5;
    SceneRun run = lanes(spec, Vec3(1.0, 0.0, 0.0));
    run.state.bodies.bodies[0].p_WB.x() = 0.2;  // 5 cm ahead: the pushers arrive at 1 m/s
    run.state.bodies.bodies[2].p_WB.x() = 0.2;
    run.steps(200);
    const double v_box = (1.0 + 0.5) * M / (M + m);
    EXPECT_NEAR(run.body(0).v_WB.x(), v_box, 1e-6) << "the box the robot struck";
    EXPECT_NEAR(run.body(2).v_WB.x(), v_box, 1e-6) << "the box the body struck";
  }
}

// A 1 kg box on a 2 kg platform that slides along x (μ = 0.5 between them),
// driven by an effort: below μ g (M + m) the box rides along, a = F/(M + m);
// above, it slips, its acceleration μ g, the platform's (F − μ m g)/M.
TEST(Scene, PlatformCarriesOrLosesABox) {
  const double M = 2.0, m = 1.0, mu = 0.5;
  const ArticulationModel platform = slider(Vec3::UnitX(), Vec3(0.0, 0.0, 0.5), Vec3(1.0, 0.4, 0.1), M);
  const BodySpec box = test::boxBody(Vec3(0.1, 0.1, 0.1), m);
  for (const double F : {10.0, 30.0}) {
    SceneRun run(settings({box}, mu, false), {{"platform", platform}}, {at(Vec3(0.0, 0.0, 0.65))},
                 {restState(platform)});
    run.loads.robots.resize(1);
    run.loads.robots[0].effort = Eigen::VectorXd::Constant(1, F);
    const int n = 300;
    run.steps(n - 1);
    const double box_before = run.body(0).v_WB.x(), platform_before = run.state.robots[0].v(0);
    run.steps(1);
    const double t = n * kH;
    const bool slips = F > mu * kG * (M + m);
    const double a_box = slips ? mu * kG : F / (M + m);
    const double a_platform = slips ? (F - mu * m * kG) / M : a_box;
    EXPECT_NEAR(run.body(0).v_WB.x() - box_before, a_box * kH, 1e-9) << F;
    EXPECT_NEAR(run.state.robots[0].v(0) - platform_before, a_platform * kH, 1e-9) << F;
    // The platform's first step is half a step's, its friction unknown to that start (§11.5).
    EXPECT_NEAR(run.state.robots[0].v(0), a_platform * t, 0.5 * kH * F / M) << F;
    EXPECT_NEAR(run.body(0).v_WB.z(), 0.0, 1e-9) << F;
    EXPECT_NEAR(run.body(0).p_WB.z(), 0.65, 1e-6) << F;
  }
}

// A 2 kg platform on a vertical prismatic joint lifts a 1 kg box resting
// on it with 40 N: a = F / (M + m) − g, the box never leaving it.
TEST(Scene, LiftRaisesABox) {
  const double M = 2.0, m = 1.0, F = 40.0;
  const ArticulationModel lift = slider(Vec3::UnitZ(), Vec3(0.0, 0.0, 0.5), Vec3(0.4, 0.4, 0.1), M);
  const BodySpec box = test::boxBody(Vec3(0.1, 0.1, 0.1), m);
  SceneRun run(settings({box}, 0.5, false), {{"lift", lift}}, {at(Vec3(0.0, 0.0, 0.65))}, {restState(lift)});
  run.loads.robots.resize(1);
  run.loads.robots[0].effort = Eigen::VectorXd::Constant(1, F);
  const int n = 500;
  run.steps(n - 1);
  const double before = run.state.robots[0].v(0);
  run.steps(1);
  const double a = F / (M + m) - kG;
  EXPECT_NEAR(run.state.robots[0].v(0) - before, a * kH, 1e-9);
  // Its first step is half a step's; the box's weight, unknown to that start, takes some of it.
  EXPECT_NEAR(run.state.robots[0].v(0), a * n * kH, 0.5 * kH * (F / M - kG));
  EXPECT_NEAR(run.body(0).v_WB.z(), run.state.robots[0].v(0), 1e-9);
  EXPECT_NEAR(run.body(0).p_WB.z() - 0.65, run.state.robots[0].q(0), 1e-6);
  EXPECT_LT(run.body(0).v_WB.head<2>().norm(), 1e-12);
}

/// A floating two-link robot: two bars joined by a hinge about z.
ArticulationModel floatingArm() { return test::twoBars(); }

/// [angular about W's origin; linear] of the robot and the free bodies:
/// the robot's as its step carries it (its velocities give it from where
/// they act, the step's start: §11.5).
Vec6 totalMomentum(const SceneRun& run) {
  const SceneRobot& robot = run.scene.robots()[0];
  const ArticulationState& a = run.state.robots[0];
  Vec6 H = a.carried.valid ? a.carried.H_W : momentum_W(robot.model, kinematics(robot.model, a));
  for (std::size_t i = 0; i < run.scene.freeBodyCount(); ++i) {
    const BodyModel& b = run.scene.model().body(i);
    const BodyState& s = run.body(static_cast<int>(i));
    const Vec3 p = b.mass * s.v_WB;
    const Mat3 R = s.q_WB.toRotationMatrix();
    const Vec3 w_W = R * s.w_B;
    const Vec3 L = R * b.inv_inertia_B.cwiseInverse().asDiagonal() * R.transpose() * w_W;
    H.head<3>() += L + s.p_WB.cross(p);
    H.tail<3>() += p;
  }
  return H;
}

// In zero gravity the robot, bent and spinning its elbow, flies into a box
// at rest off its axis: the contact's impulse acts on both in one solve, so
// the total linear and angular momentum stay what they were.
TEST(Scene, CollisionKeepsTheMomentum) {
  const ArticulationModel arm = floatingArm();
  ModelSpec spec = settings({test::boxBody(Vec3(0.1, 0.1, 0.1), 1.5)}, 0.5, false);
  spec.gravity_W = Vec3::Zero();
  ArticulationState start = restState(arm, placed(Vec3(-0.6, 0.05, 0.0)));
  start.q(0) = 0.3;
  start.v(0) = 2.0;
  start.V_B.tail<3>() = Vec3(1.0, 0.0, 0.0);
  SceneRun run(spec, {{"arm", arm}}, {at(Vec3(0.25, 0.0, 0.02))}, {start});
  const Vec6 before = totalMomentum(run);
  bool touched = false;
  for (int i = 0; i < 1500; ++i) {
    run.steps(1);
    touched = touched || !run.ws.bodies.contacts.empty();
  }
  ASSERT_TRUE(touched);
  EXPECT_GT(run.body(0).v_WB.x(), 0.1);  // the box was struck
  const Vec6 after = totalMomentum(run);
  EXPECT_LT((after - before).norm(), 1e-9) << (after - before).transpose();
}

// Two floating robots fly into each other in zero gravity: a contact
// between two robots' links is one row with a side for each, so the total
// momentum stays what it was.
TEST(Scene, TwoRobotsCollideKeepingTheMomentum) {
  const ArticulationModel arm = floatingArm();
  ModelSpec spec = settings({}, 0.5, false);
  spec.gravity_W = Vec3::Zero();
  ArticulationState a = restState(arm, placed(Vec3(-0.6, 0.05, 0.0)));
  a.q(0) = 0.3;
  a.v(0) = 2.0;
  a.V_B.tail<3>() = Vec3(1.0, 0.0, 0.0);
  ArticulationState b = restState(arm, placed(Vec3(0.3, -0.05, 0.03)));
  b.q(0) = -0.5;
  b.V_B.head<3>() = Vec3(0.0, 0.0, 1.0);
  SceneRun run(spec, {{"a", arm}, {"b", arm}}, {}, {a, b});
  const auto total = [&run] {
    Vec6 H = Vec6::Zero();
    for (std::size_t r = 0; r < 2; ++r) {
      const ArticulationState& s = run.state.robots[r];
      H += s.carried.valid ? s.carried.H_W
                           : momentum_W(run.scene.robots()[r].model, kinematics(run.scene.robots()[r].model, s));
    }
    return H;
  };
  const Vec6 before = total();
  bool touched = false;
  for (int i = 0; i < 1500; ++i) {
    run.steps(1);
    for (const Contact& c : run.ws.bodies.contacts) touched = touched || (c.other >= 0 && c.normal_impulse > 0.0);
  }
  ASSERT_TRUE(touched);
  EXPECT_GT(run.state.robots[1].V_B.norm(), 0.1);  // b was struck
  EXPECT_LT((total() - before).norm(), 1e-9) << (total() - before).transpose();
}

// A pusher resting against a box on the floor: the island, robot and box,
// falls asleep after the sleep time and then stays exactly put; an effort
// wakes the robot, which wakes the box as it comes at it and shoves it.
TEST(Scene, AnIslandWithARobotSleepsAndWakes) {
  const ArticulationModel pusher = slider(Vec3::UnitX(), Vec3(0.0, 0.0, 0.1), Vec3(0.1, 0.3, 0.1), 2.0);
  const BodySpec box = test::boxBody(Vec3(0.1, 0.1, 0.1), 1.0);
  SceneRun run(settings({box}, 0.5, true), {{"pusher", pusher}}, {at(Vec3(0.15, 0.0, 0.1))}, {restState(pusher)});
  int asleep_at = -1;
  for (int i = 0; i < 1000 && asleep_at < 0; ++i) {
    run.steps(1);
    if (run.state.robots[0].asleep) asleep_at = i;
  }
  ASSERT_GE(asleep_at, 0);
  EXPECT_NEAR(asleep_at * kH, 0.5, 0.01);  // sleep.time
  EXPECT_TRUE(run.body(0).asleep);         // with its island
  const SceneState held = run.state;
  run.steps(200);
  EXPECT_EQ(run.state.robots[0].q, held.robots[0].q);
  EXPECT_TRUE(run.body(0).p_WB == held.bodies.bodies[0].p_WB &&
              run.body(0).q_WB.coeffs() == held.bodies.bodies[0].q_WB.coeffs());
  EXPECT_TRUE(run.state.robots[0].asleep && run.body(0).asleep);
  run.loads.robots.resize(1);
  run.loads.robots[0].effort = Eigen::VectorXd::Constant(1, 20.0);
  run.steps(1);
  EXPECT_FALSE(run.state.robots[0].asleep);
  run.steps(300);
  EXPECT_FALSE(run.body(0).asleep);
  EXPECT_GT(run.body(0).p_WB.x(), 0.2);  // shoved
}

// A NaN effort on one robot: the guard puts that robot back where its step
// began, at rest, and says so; the box beside it steps on.
TEST(Scene, TheGuardPutsBackARobotAlone) {
  const ArticulationModel pusher = slider(Vec3::UnitX(), Vec3(0.0, 0.0, 0.1), Vec3(0.1, 0.3, 0.1), 2.0);
  const BodySpec box = test::boxBody(Vec3(0.1, 0.1, 0.1), 1.0);
  ArticulationState start = restState(pusher);
  start.q(0) = 0.01;
  SceneRun run(settings({box}, 0.5, true), {{"pusher", pusher}}, {at(Vec3(1.0, 0.0, 0.5))}, {start});
  run.loads.robots.resize(1);
  run.loads.robots[0].effort = Eigen::VectorXd::Constant(1, std::numeric_limits<double>::quiet_NaN());
  run.steps(1);
  EXPECT_EQ(run.ws.robot_diverged, (std::vector<char>{1}));
  EXPECT_EQ(run.state.robots[0].q(0), 0.01);
  EXPECT_EQ(run.state.robots[0].v(0), 0.0);
  EXPECT_NEAR(run.body(0).v_WB.z(), -9.81e-3, 1e-15);  // the box fell for one step
  run.loads.robots[0].effort(0) = 1.0;
  run.steps(1);
  EXPECT_EQ(run.ws.robot_diverged, (std::vector<char>{0}));
  EXPECT_GT(run.state.robots[0].v(0), 0.0);
}

// A free box falling onto the floor far from a robot steps exactly as it
// does in a world of its own: islands without a robot are the free bodies'.
TEST(Scene, FreeIslandsStepAsOnTheirOwn) {
  const ArticulationModel pusher = slider(Vec3::UnitX(), Vec3(5.0, 0.0, 0.1), Vec3(0.1, 0.3, 0.1), 2.0);
  const BodySpec box = test::boxBody(Vec3(0.1, 0.1, 0.1), 1.0);
  const ModelSpec spec = settings({box}, 0.5, true);
  LinkState X = at(Vec3(0.0, 0.0, 0.3));
  X.q_WL = Quat(Eigen::AngleAxisd(0.3, Vec3(1.0, 1.0, 0.0).normalized()));
  SceneRun run(spec, {{"pusher", pusher}}, {X}, {restState(pusher)});
  const Model alone(spec);
  State state = restState(alone);
  state.bodies[0] = bodyStateFromLink(alone.body(0), X);
  Workspace ws;
  ws.skip_fixed_points = false;
  for (int i = 0; i < 800; ++i) {
    run.steps(1);
    step(alone, state, {}, &ws);
    const BodyState& a = run.body(0);
    const BodyState& b = state.bodies[0];
    ASSERT_TRUE(sameBits(a, b)) << "step " << i;
  }
  EXPECT_TRUE(state.bodies[0].asleep);  // it came to rest and slept, in both
  EXPECT_TRUE(run.body(0).asleep);
}

// Eight rod pendulums hung 1 cm apart, each swung out to its own angle, so
// that their rods overlap where they cannot part (issue 44: ten such
// reached 1e4 rad/s, and a box at rest 5 m away was thrown 1e6 m, pulled
// into their island by their runaway speed and lifted by their split
// impulse). Their trouble stays within the speed limits, and the box steps
// exactly as in a world of its own.
TEST(Scene, OverlappingRobotsStayBoundedAndMoveNothingTheyDoNotTouch) {
  std::vector<Scene::RobotSpec> robots;
  std::vector<ArticulationState> starts;
  for (int i = 0; i < 8; ++i) {
    ArticulationModel rod =
        test::oneJoint(JointType::Continuous, "rod", "pivot", Vec3(0.01 * (i % 4), 0.01 * (i / 4), 1.0), Vec3::UnitY());
    // urdf/pendulum.urdf's rod: a 0.5 m, 1 kg cylinder of radius 0.02 m.
    rod.links[1].mass = {1.0, Vec3(0.0, 0.0, -0.25), Vec3(1.0 / 48.0, 1.0 / 48.0, 1e-5).asDiagonal()};
    CollisionShape cylinder;
    cylinder.kind = CollisionShape::Kind::kCylinder;
    cylinder.radius = 0.02;
    cylinder.length = 0.5;
    cylinder.X_LS.translation = Vec3(0.0, 0.0, -0.25);
    rod.links[1].collision = {cylinder};
    checkArticulation(rod);
    ArticulationState start = restState(rod);
    start.q(0) = 0.1 * i;
    starts.push_back(start);
    robots.push_back({"rod" + std::to_string(i), std::move(rod)});
  }
  const BodySpec box = test::boxBody(Vec3(0.1, 0.1, 0.05), 1.0);
  const ModelSpec spec = settings({box}, 0.5, true);
  const LinkState X = at(Vec3(5.0, 0.0, 0.05));
  SceneRun run(spec, std::move(robots), {X}, starts);
  const Model alone(spec);
  State state = restState(alone);
  state.bodies[0] = bodyStateFromLink(alone.body(0), X);
  Workspace ws;
  const SpeedLimits& limits = spec.limits;
  for (int i = 0; i < 500; ++i) {
    run.steps(1);
    step(alone, state, {}, &ws);
    const BodyState& a = run.body(0);
    const BodyState& b = state.bodies[0];
    ASSERT_TRUE(sameBits(a, b)) << "step " << i << ": the box at " << a.p_WB.transpose() << ", alone at "
                                << b.p_WB.transpose();
    for (const ArticulationState& r : run.state.robots) {
      ASSERT_TRUE(r.q.allFinite()) << "step " << i;
      ASSERT_LE(r.v.cwiseAbs().maxCoeff(), limits.max_angular_speed) << "step " << i;
    }
  }
}

/// The pusher shoving a row of three boxes, and 40 boxes falling elsewhere.
SceneRun crowd(int threads) {
  const ArticulationModel pusher = slider(Vec3::UnitX(), Vec3(0.0, 0.0, 0.1), Vec3(0.1, 0.3, 0.1), 2.0);
  std::vector<BodySpec> boxes;
  std::vector<LinkState> poses;
  for (int i = 0; i < 3; ++i) {
    boxes.push_back(test::boxBody(Vec3(0.1, 0.1, 0.1), 1.0));
    boxes.back().name = "row" + std::to_string(i);
    poses.push_back(at(Vec3(0.16 + 0.21 * i, 0.01 * i, 0.1)));
  }
  for (int i = 0; i < 40; ++i) {
    boxes.push_back(test::boxBody(Vec3(0.05, 0.05, 0.05), 0.5));
    boxes.back().name = "falling" + std::to_string(i);
    LinkState X = at(Vec3(3.0 + 0.3 * (i % 8), 0.3 * (i / 8), 0.2 + 0.01 * i));
    X.q_WL = Quat(Eigen::AngleAxisd(0.1 * i, Vec3(1.0, 0.5, 0.2).normalized()));
    poses.push_back(X);
  }
  SceneRun run(settings(boxes, 0.5, true), {{"pusher", pusher}}, poses, {restState(pusher)});
  run.ws.bodies.threads = threads;
  run.ws.bodies.min_parallel_work = 1;
  run.loads.robots.resize(1);
  run.loads.robots[0].effort = Eigen::VectorXd::Constant(1, 30.0);
  return run;
}

TEST(Scene, SameAtOneThreadAndTwo) {
  SceneRun one = crowd(1), two = crowd(2);
  for (int i = 0; i < 600; ++i) {
    one.steps(1);
    two.steps(1);
    ASSERT_TRUE(one.state.robots[0].q == two.state.robots[0].q && one.state.robots[0].v == two.state.robots[0].v)
        << "step " << i;
    for (std::size_t b = 0; b < one.scene.freeBodyCount(); ++b) {
      const BodyState& x = one.body(static_cast<int>(b));
      const BodyState& y = two.body(static_cast<int>(b));
      ASSERT_TRUE(x.p_WB == y.p_WB && x.v_WB == y.v_WB && x.q_WB.coeffs() == y.q_WB.coeffs() && x.w_B == y.w_B)
          << "step " << i << " body " << b;
    }
  }
  EXPECT_GT(one.body(2).v_WB.x(), 0.5);  // the row is moving
}

}  // namespace
}  // namespace rigid_body_sim::core
