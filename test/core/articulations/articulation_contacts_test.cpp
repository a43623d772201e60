// An articulation's links against the scene (docs/physics.md §11.8): a
// pendulum comes to rest on the floor, a two-link arm lying on it does not
// creep, a four-wheeled base rolls at the speed ω r its wheels set.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "articulation_models.h"
#include "lone_robot.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/articulations/articulation_step.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/core/contacts/contact.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kG = 9.81;
constexpr double kH = 1e-3;

ModelSpec groundSettings(double friction) {
  ModelSpec spec;
  spec.dt = kH;
  spec.scene = {Sdf::plane(Vec3::UnitZ())};
  spec.contact.friction = friction;
  return spec;
}

using test::boxMass;
using test::boxShape;

/// A robot alone on the settings' scene, under gravity.
struct Robot {
  const ArticulationModel& model;
  test::LoneRobot alone;
  ArticulationState state;
  ArticulationLoads loads;

  Robot(const ArticulationModel& m, const ModelSpec& settings, const ArticulationState& start)
      : model(m), alone(m, Vec3(0, 0, -kG), kH, settings.limits, settings), state(start) {}
  void steps(int n) {
    for (int i = 0; i < n; ++i) ASSERT_TRUE(alone.step(state, loads));
  }
  /// The last step's contacts, with their impulses.
  const std::vector<Contact>& contacts() const { return alone.workspace().bodies.contacts; }
  /// The deepest any link's contact is into the floor (m, ≥ 0).
  double deepest() const {
    double d = 0.0;
    for (const Contact& c : contacts()) d = std::max(d, -c.separation);
    return d;
  }
};

// A rod on a fixed pivot 0.5 m up, a ball of radius 0.05 at its tip 0.6 m
// out, released horizontal: it swings down and stops with the ball on the
// floor, sin θ = (0.5 − 0.05)/0.6. One joint: each contact's K has rank 1.
TEST(ArticulationContacts, PendulumComesToRestOnTheFloor) {
  ArticulationModel model = test::oneJoint(JointType::Continuous, "rod", "pivot", Vec3(0.0, 0.0, 0.5), Vec3::UnitY());
  ArticulatedLink& rod = model.links[1];
  rod.damping = 0.05;
  rod.mass = boxMass(1.0, Vec3(0.6, 0.02, 0.02), Vec3(0.3, 0.0, 0.0));
  CollisionShape ball;
  ball.kind = CollisionShape::Kind::kSphere;
  ball.radius = 0.05;
  ball.X_LS.translation = Vec3(0.6, 0.0, 0.0);
  rod.collision = {ball};
  checkArticulation(model);
  Robot run(model, groundSettings(0.5), restState(model));
  double deepest = 0.0;
  for (int i = 0; i < 4000; ++i) {
    run.steps(1);
    deepest = std::max(deepest, run.deepest());
  }
  // About +y, a positive angle turns x toward −z: the tip goes down.
  const double rest = std::asin(0.45 / 0.6);
  EXPECT_NEAR(run.state.q(0), rest, 2e-4);  // within the slop's share of the angle (1e-4 / 0.6 cos θ)
  EXPECT_NEAR(run.state.v(0), 0.0, 1e-9);
  EXPECT_LT(deepest, 0.05);  // the first touch, at 2.9 m/s, is caught speculatively
  EXPECT_LT(run.deepest(), 1e-4 + 1e-9);
}

/// Two bars joined end to end by a hinge about z, lying flat on the floor,
/// the base floating.
ArticulationModel lyingArm() { return test::twoBars(); }

TEST(ArticulationContacts, ArmLyingOnTheFloorRestsWithoutCreep) {
  const ArticulationModel model = lyingArm();
  ArticulationState start = restState(model);
  start.X_WB.translation = Vec3(0.0, 0.0, 0.05);
  start.q(0) = 0.7;  // bent at the elbow
  ModelSpec settings = groundSettings(0.5);
  settings.sleep.enabled = false;  // the solve alone holds it
  Robot run(model, settings, start);
  run.steps(500);
  const Vec3 settled = run.state.X_WB.translation;
  const double elbow = run.state.q(0);
  run.steps(4500);
  EXPECT_LT((run.state.X_WB.translation - settled).norm(), 1e-9);
  EXPECT_NEAR(run.state.q(0), elbow, 1e-9);
  EXPECT_NEAR(run.state.X_WB.translation.z(), 0.05, 1e-4);  // on the floor, within the slop
  EXPECT_LT(run.state.V_B.norm(), 1e-9);
  // The floor carries the arm's weight: Σ λ_N = m g h.
  double lifted = 0.0;
  for (const Contact& c : run.contacts()) lifted += c.normal_impulse;
  EXPECT_NEAR(lifted, 2.0 * kG * kH, 1e-9);
}

// At rest on the floor for sleep.time it sleeps, exactly where it is; an
// effort wakes it.
TEST(ArticulationContacts, ArmAtRestSleepsAndAnEffortWakesIt) {
  const ArticulationModel model = lyingArm();
  ArticulationState start = restState(model);
  start.X_WB.translation = Vec3(0.0, 0.0, 0.05);
  start.q(0) = 0.7;
  Robot run(model, groundSettings(0.5), start);
  run.steps(400);
  EXPECT_FALSE(run.state.asleep);
  run.steps(1000);  // still since the first steps, for more than sleep.time = 0.5 s
  ASSERT_TRUE(run.state.asleep);
  const ArticulationState slept = run.state;
  run.steps(1000);
  EXPECT_EQ(run.state.X_WB.translation, slept.X_WB.translation);
  EXPECT_EQ(run.state.q, slept.q);
  run.loads.effort = Eigen::VectorXd::Constant(1, 5.0);
  run.steps(100);
  EXPECT_FALSE(run.state.asleep);
  EXPECT_GT(run.state.q(0), slept.q(0) + 0.01);
}

// Dropped flat from 0.4 m onto a floor of restitution 0.5, it leaves at half
// the speed it arrives with (all eight corners at once: a uniform bounce).
TEST(ArticulationContacts, ArmDroppedFlatBouncesAtRestitution) {
  const ArticulationModel model = lyingArm();
  ArticulationState start = restState(model);
  start.X_WB.translation = Vec3(0.0, 0.0, 0.45);
  ModelSpec settings = groundSettings(0.5);
  settings.contact.restitution = 0.5;
  Robot run(model, settings, start);
  double fastest_down = 0.0, fastest_up = 0.0;
  int bounce = -1;
  for (int i = 0; i < 600; ++i) {
    const double before = run.state.V_B(5);
    run.steps(1);
    if (bounce < 0 && run.state.V_B(5) > 0.0) {
      bounce = i;
      fastest_down = -(before - kG * kH);  // what it arrived with in the bounce's step
      fastest_up = run.state.V_B(5);
    }
  }
  ASSERT_GE(bounce, 0);
  EXPECT_NEAR(fastest_down, std::sqrt(2.0 * kG * 0.4), 0.02);
  EXPECT_NEAR(fastest_up, 0.5 * fastest_down, 1e-9);
  EXPECT_LT(run.state.V_B.head<3>().norm(), 1e-9);  // flat: no turn
}

// Bent and pushed sideways at 0.5 m/s, it slides to rest. The friction on
// it is at most μ m g, so its centre of mass needs at least v/(μ g) to stop
// and goes at least v²/(2 μ g); exactly that if every contact slid straight
// back, farther if the arm turns as it slides (the friction then spreads
// over directions, as a spinning puck's does). How it turns depends on how
// its weight splits between its contacts, which rigid contacts leave
// undetermined (a warm start changes it).
TEST(ArticulationContacts, ArmSlidingOnTheFloorStops) {
  const ArticulationModel model = lyingArm();
  ArticulationState start = restState(model);
  start.X_WB.translation = Vec3(0.0, 0.0, 0.05);
  start.V_B.tail<3>() = Vec3(0.0, 0.5, 0.0);
  start.v(0) = 0.0;
  Robot run(model, groundSettings(0.5), start);
  // While it slides, the floor's friction is the whole cone: Σ |λ_T| = μ Σ λ_N
  // (row-by-row friction, clipped to the disk, gave 84 % of it here).
  run.steps(5);
  double normal = 0.0, friction = 0.0;
  Vec3 tangent = Vec3::Zero();
  for (const Contact& c : run.contacts()) {
    normal += c.normal_impulse;
    friction += c.tangent_impulse_W.norm();
    tangent += c.tangent_impulse_W;
  }
  EXPECT_NEAR(normal, 2.0 * kG * kH, 1e-9);
  EXPECT_NEAR(friction, 0.5 * normal, 1e-9 * normal);
  EXPECT_GT(-tangent.y(), 0.999 * friction);  // against the slide
  run.steps(995);
  EXPECT_LT(run.state.V_B.norm(), 1e-6);
  const double y =
      centreOfMass(model, kinematics(model, run.state)).y() - centreOfMass(model, kinematics(model, start)).y();
  const double least = 0.25 / (2.0 * 0.5 * kG);
  std::printf("slid %.6g m, at least v²/(2 μ g) = %.6g m; turned %.3g rad\n", y, least,
              2.0 * std::atan2(run.state.X_WB.rotation.z(), run.state.X_WB.rotation.w()));
  EXPECT_GE(y, least - 1e-9);
  EXPECT_LT(y, 1.1 * least);
}

// The wheeled base driven by equal efforts: it rolls, the base's speed ω r.
/// A 5 kg chassis on four wheels of radius r = 0.1 m (cylinders about y,
/// on continuous joints).
ArticulationModel wheeledBase() {
  const double r = 0.1;
  ArticulationModel model;
  model.fixed_base = false;
  model.links.resize(5);
  model.links[0].name = "chassis";
  model.links[0].mass = boxMass(5.0, Vec3(0.6, 0.4, 0.1), Vec3::Zero());
  const double xs[4] = {0.2, 0.2, -0.2, -0.2}, ys[4] = {0.25, -0.25, 0.25, -0.25};
  for (int i = 1; i <= 4; ++i) {
    ArticulatedLink& w = model.links[i];
    w.name = "wheel" + std::to_string(i);
    w.joint = "axle" + std::to_string(i);
    w.parent = 0;
    w.type = JointType::Continuous;
    w.X_PJ.translation = Vec3(xs[i - 1], ys[i - 1], 0.0);
    w.axis_J = Vec3::UnitY();
    w.mass.mass = 0.5;
    w.mass.I_C_F =
        Vec3(0.5 * (3 * r * r + 0.05 * 0.05) / 12.0, 0.5 * r * r / 2.0, 0.5 * (3 * r * r + 0.05 * 0.05) / 12.0)
            .asDiagonal();
    CollisionShape c;
    c.kind = CollisionShape::Kind::kCylinder;
    c.radius = r;
    c.length = 0.05;
    c.X_LS.rotation = Quat(Eigen::AngleAxisd(M_PI / 2.0, Vec3::UnitX()));  // its z along y
    w.collision = {c};
  }
  checkArticulation(model);
  return model;
}

TEST(ArticulationContacts, WheeledBaseRollsAtOmegaR) {
  const double r = 0.1;
  const ArticulationModel model = wheeledBase();
  ArticulationState start = restState(model);
  start.X_WB.translation = Vec3(0.0, 0.0, r);
  Robot run(model, groundSettings(0.8), start);
  run.loads.effort = Eigen::VectorXd::Constant(4, 0.2);
  run.steps(1000);
  const double omega = run.state.v.mean();
  const double speed = run.state.V_B(3);
  // 8 N on 7 kg, less the wheels' share of the work: well short of slipping.
  EXPECT_GT(speed, 0.5);
  EXPECT_NEAR(speed, omega * r, 1e-3 * speed);
  EXPECT_NEAR(run.state.X_WB.translation.z(), r, 1e-4);
  EXPECT_LT(std::abs(run.state.X_WB.translation.y()), 1e-6);
}

// The detection splits its work over the threads it is given; the
// trajectory is the same to the bit at one thread and two.
TEST(ArticulationContacts, BitIdenticalAtOneThreadAndTwo) {
  const ArticulationModel model = wheeledBase();
  ArticulationState start = restState(model);
  start.X_WB.translation = Vec3(0.0, 0.0, 0.1);
  start.X_WB.rotation = Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
  start.v = Eigen::Vector4d(12.0, 9.0, 11.0, 8.0);  // unequal: it turns as it goes
  std::vector<ArticulationState> ends;
  for (const int threads : {1, 2}) {
    Robot run(model, groundSettings(0.8), start);
    run.alone.workspace().bodies.threads = threads;
    run.alone.workspace().bodies.min_parallel_work = 0;
    run.steps(1500);
    ends.push_back(run.state);
  }
  EXPECT_EQ(ends[0].q, ends[1].q);
  EXPECT_EQ(ends[0].v, ends[1].v);
  EXPECT_EQ(ends[0].V_B, ends[1].V_B);
  EXPECT_EQ(ends[0].X_WB.translation, ends[1].X_WB.translation);
  EXPECT_EQ(ends[0].X_WB.rotation.coeffs(), ends[1].X_WB.rotation.coeffs());
  EXPECT_GT(ends[0].X_WB.translation.norm(), 0.1);  // it went somewhere
}

/// Three bars hinged about z, floating in zero gravity: a 1 m base, a
/// 0.3 m link at its end, a 0.8 m link at that one's end, folded so the
/// last swings down across the base.
ArticulationModel scissors() {
  ArticulationModel model;
  model.fixed_base = false;
  model.links.resize(3);
  const double lengths[3] = {1.0, 0.3, 0.8};
  for (int i = 0; i < 3; ++i) {
    ArticulatedLink& l = model.links[i];
    l.name = "bar" + std::to_string(i);
    const Vec3 size(lengths[i], 0.1, 0.1);
    const Vec3 centre = i == 0 ? Vec3::Zero() : Vec3(lengths[i] / 2.0, 0.0, 0.0);
    l.mass = boxMass(1.0, size, centre);
    l.collision = {boxShape(size, centre)};
    if (i == 0) continue;
    l.joint = "hinge" + std::to_string(i);
    l.parent = i - 1;
    l.type = JointType::Continuous;
    l.X_PJ.translation = Vec3(i == 1 ? 0.5 : 0.3, 0.0, 0.0);
    l.axis_J = Vec3::UnitZ();
  }
  checkArticulation(model);
  return model;
}

/// The deepest the last bar's sides go into the base bar (m, < 0 inside;
/// the base's box, half sizes 0.5, 0.05, 0.05, as a distance), sampled
/// every centimetre along them.
double lastBarIntoBase(const ArticulationModel& model, const ArticulationState& state) {
  const ArticulationKinematics kin = kinematics(model, state);
  const Mat3 R_BW = kin.X_WL[0].R_PC.transpose();
  double deepest = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= 80; ++k) {
    for (const double y : {-0.05, 0.05}) {  // in the bars' common mid-plane
      const Vec3 p_W = kin.X_WL[2].p_PC + kin.X_WL[2].R_PC * Vec3(0.01 * k, y, 0.0);
      const Vec3 p_B = R_BW * (p_W - kin.X_WL[0].p_PC);
      deepest = std::min(deepest, (p_B.cwiseAbs() - Vec3(0.5, 0.05, 0.05)).maxCoeff());
    }
  }
  return deepest;
}

// Self-collision is a setting (contact.self_collision), off by default
// (Gazebo's): off, the last bar
// swings through the base; on, it stops on it, no deeper than the slop
// (links joined by a joint still never touch: the bars meet at the hinges).
TEST(ArticulationContacts, SelfCollisionIsASettingOffByDefault) {
  const ArticulationModel model = scissors();
  ArticulationState start = restState(model);
  start.q = Eigen::Vector2d(M_PI / 2.0, M_PI / 2.0);  // the last bar back along the base, 0.3 m beside it
  start.v = Eigen::Vector2d(0.0, 3.0);                // swinging down across it
  ModelSpec settings;
  settings.scene.clear();
  settings.sleep.enabled = false;
  for (const bool self : {false, true}) {
    settings.contact.self_collision = self;
    test::LoneRobot alone(model, Vec3::Zero(), kH, settings.limits, settings);
    ArticulationState state = start;
    double deepest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 1000; ++i) {
      ASSERT_TRUE(alone.step(state));
      deepest = std::min(deepest, lastBarIntoBase(model, state));
    }
    std::printf("self-collision %s: the last bar's deepest into the base %.3g m\n", self ? "on" : "off", deepest);
    if (self) {
      EXPECT_GT(deepest, -2e-4) << "the bar went into the base";
    } else {
      EXPECT_LT(deepest, -0.04) << "the bar should pass through the base";
    }
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
