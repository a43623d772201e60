// Model validation: each bad value is refused with its field and value.
#include "rigid_body_sim/core/bodies/model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

core::ModelSpec good() { return spec(shippedBox(), 1e-3, Vec3(0, 0, -9.81)); }

void expectRefused(const core::ModelSpec& s, std::initializer_list<std::string> parts) {
  expectThrowsWith<std::invalid_argument>([&] { core::Model m(s); }, parts);
}

TEST(ModelValidation, AcceptsTheShippedBox) { EXPECT_NO_THROW(core::Model m(good())); }

// A pile of equal boxes keeps one copy of their points and solid (the N =
// 10,000 pile went from 6.6 to 4.0 KB per body, bench/HISTORY.md); a body of
// other shape or mass properties gets its own, and each is what it would
// be alone.
TEST(Model, BodiesBuiltAlikeShareTheirPointsAndSolid) {
  core::ModelSpec spec;
  core::BodySpec a = boxBody(Vec3(0.2, 0.1, 0.05)), b = a, heavier = a, other = boxBody(Vec3(0.1, 0.1, 0.1));
  a.name = "a";
  b.name = "b";
  b.friction = 0.9;  // a surface of its own does not matter
  heavier.name = "heavier";
  heavier.I_C_L *= 2.0;
  other.name = "other";
  spec.bodies = {a, other, b, heavier};
  const core::Model model(spec);
  EXPECT_TRUE(model.body(0).contact_points.sameAs(model.body(2).contact_points));
  EXPECT_TRUE(model.body(0).solid_B.sameAs(model.body(2).solid_B));
  EXPECT_TRUE(model.body(0).extreme_groups.sameAs(model.body(2).extreme_groups));
  EXPECT_EQ(model.body(2).friction, 0.9);
  EXPECT_FALSE(model.body(0).contact_points.sameAs(model.body(1).contact_points));
  EXPECT_FALSE(model.body(0).contact_points.sameAs(model.body(3).contact_points));
  core::ModelSpec alone = spec;
  alone.bodies = {b, other};
  const core::Model alone_model(alone);
  const core::BodyModel& built = alone_model.body(0);
  ASSERT_EQ(built.contact_points.size(), model.body(2).contact_points.size());
  for (std::size_t i = 0; i < built.contact_points.size(); ++i) {
    EXPECT_EQ(built.contact_points[i].r_B, model.body(2).contact_points[i].r_B);
  }
  EXPECT_EQ(built.bound_radius, model.body(2).bound_radius);
}

TEST(ModelValidation, Mass) {
  for (double bad :
       {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 1e-300, 1e300}) {
    core::ModelSpec s = good();
    s.bodies[0].mass = bad;
    expectRefused(s, {"body 'box': mass = ", "must be within [1e-06, 10000000] kg"});
  }
  core::ModelSpec s = good();
  s.bodies[0].mass = -2.5;
  expectRefused(s, {"mass = -2.5"});
}

TEST(ModelValidation, Inertia) {
  core::ModelSpec s = good();
  s.bodies[0].I_C_L = Vec3(1.0, 1.0, 3.0).asDiagonal();
  expectRefused(s, {"body 'box': inertia = (ixx=1, iyy=1, izz=3", "triangle inequality"});
  s.bodies[0].I_C_L = Vec3(1.0, 0.0, 1.0).asDiagonal();
  expectRefused(s, {"body 'box': inertia", "positive definite"});
  s.bodies[0].I_C_L(0, 2) = 0.5;
  expectRefused(s, {"body 'box': inertia", "symmetric"});
}

TEST(ModelValidation, CentreOfMass) {
  core::ModelSpec s = good();
  s.bodies[0].p_LC.x() = std::numeric_limits<double>::infinity();
  expectRefused(s, {"body 'box': centre of mass = [inf, 0, 0]", "finite"});
}

TEST(ModelValidation, TimeStep) {
  for (double bad : {0.0, -1e-3, std::numeric_limits<double>::quiet_NaN(), 300000.0, 1e-9}) {
    core::ModelSpec s = good();
    s.dt = bad;
    expectRefused(s, {"dt = ", "must be within [1e-06, 0.1] s"});
  }
}

TEST(ModelValidation, MagnitudesOutsidePhysicalSenseAreRefused) {
  core::ModelSpec s = good();
  s.gravity_W = Vec3(0.0, 0.0, -1e308);
  expectRefused(s, {"gravity = [0, 0, -1e+308]", "must be at most 1000 m/s^2"});
  s = good();
  s.bodies[0].I_C_L = Vec3(5e-324, 5e-324, 5e-324).asDiagonal();
  expectRefused(s, {"body 'box': inertia"});
  s = good();
  s.bodies[0].I_C_L = Vec3(1e-20, 1e-20, 1e-20).asDiagonal();
  expectRefused(s, {"body 'box': inertia", "principal moments", "must be within [1e-15, 1e+12] kg*m^2"});
  s = onGround(boxBody(Vec3(0.2, 0.1, 0.05)), impulse(0.0, 0.5));
  s.bodies[0].collision[0].size.x() = 1e30;
  expectRefused(s, {"body 'box': collision", "1e+30 m", "at most 1000 m"});
  for (const double spacing : {1e-5, 1e-12}) {
    s = onGround(boxBody(Vec3(0.2, 0.1, 0.05)), impulse(0.0, 0.5));
    s.contact.sample_spacing = spacing;
    expectRefused(s, {"contact.sample_spacing = ", "must be within [0.0001, 1000] m"});
  }
  s = onGround(boxBody(Vec3(100.0, 100.0, 100.0)), impulse(0.0, 0.5));
  s.contact.sample_spacing = 1e-3;  // 8e15 lattice points
  expectRefused(s, {"contact.sample_spacing = 0.001", "body 'box' would get", "more than 1000000"});
  s = onGround(boxBody(Vec3(0.2, 0.1, 0.05)), impulse(0.0, 0.5));
  s.contact.method = core::ContactMethod::kPenaltyQuadratic;
  s.contact.penalty_stiffness = 1e300;
  expectRefused(s, {"contact.penalty_stiffness = 1e+300", "k*dt^2/mass", "for body 'box'"});
  for (const double bad : {0.0, -1.0, 1e5, std::numeric_limits<double>::quiet_NaN()}) {
    s = good();
    s.limits.max_linear_speed = bad;
    expectRefused(s, {"limits.max_linear_speed = ", "at most 10000 m/s"});
    s = good();
    s.limits.max_angular_speed = bad;
    expectRefused(s, {"limits.max_angular_speed = ", "at most 10000 rad/s"});
  }
}

TEST(ModelValidation, AMeshTooBigForItsDistanceGridIsRefused) {
  // In a world a mesh body gets a distance grid costing cells × triangles:
  // 200,000 triangles do not fit the bound even at 8³ cells.
  core::BodySpec mesh = boxBody(Vec3(0.5, 0.5, 0.5));
  core::CollisionShape shape;
  shape.kind = core::CollisionShape::Kind::kPoints;
  shape.name = "soup";
  for (int i = 0; i < 200000; ++i) {
    const double t = i * 1e-6;
    shape.mesh.vertices.push_back(Vec3(t, 0.0, 0.0));
    shape.mesh.triangles.push_back({0, 0, 0});
  }
  shape.mesh.vertices.resize(3, Vec3::Zero());
  shape.mesh.vertices[1] = Vec3(0.1, 0.0, 0.0);
  shape.mesh.vertices[2] = Vec3(0.0, 0.1, 0.0);
  for (auto& t : shape.mesh.triangles) t = {0, 1, 2};
  mesh.collision = {shape};
  core::ModelSpec s = onGround(mesh, impulse(0.0, 0.5));
  core::BodySpec other = boxBody(Vec3(0.1, 0.1, 0.1));
  other.name = "other";
  s.bodies.push_back(other);
  expectRefused(s, {"body 'box': collision mesh 'soup'", "200000 triangles", "simplify the mesh"});
}

TEST(ModelValidation, Gravity) {
  core::ModelSpec s = good();
  s.gravity_W.z() = std::numeric_limits<double>::quiet_NaN();
  expectRefused(s, {"gravity = [0, 0, nan]", "must be finite"});
}

TEST(ModelValidation, Damping) {
  core::ModelSpec s = good();
  s.damping.linear = -0.5;
  expectRefused(s, {"damping.linear = -0.5", "must be within [0, 1000000] 1/s"});
  s = good();
  s.damping.angular = std::numeric_limits<double>::infinity();
  expectRefused(s, {"damping.angular = inf"});
  s = good();
  s.damping.linear_drag = 2000.0;  // σ Δt / M = 2
  expectRefused(s, {"damping.linear_drag = 2000", "sigma*dt/mass = 2", "damping.linear"});
  s = good();
  s.damping.angular_drag = 10.0;  // σ Δt / I_min = 10·1e-3/0.0041667 = 2.4
  expectRefused(s, {"damping.angular_drag = 10", "sigma*dt/I_min"});
}

TEST(Model, AnEmptyWorldStepsItsClock) {
  core::ModelSpec s = good();
  s.bodies.clear();
  const core::Model m(s);
  EXPECT_EQ(m.bodyCount(), 0u);
  core::State state;
  core::Workspace ws;
  for (int k = 0; k < 10; ++k) core::step(m, state, {}, &ws);
  EXPECT_TRUE(state.bodies.empty());
  EXPECT_DOUBLE_EQ(state.time, 10 * m.dt());
}

TEST(Model, PrincipalFrameOfANonDiagonalInertia) {
  core::ModelSpec s = good();
  const Quat q(Eigen::AngleAxisd(0.4, Vec3::UnitZ()));
  const Mat3 R = q.toRotationMatrix();
  s.bodies[0].I_C_L = R * Vec3(0.1, 0.2, 0.25).asDiagonal() * R.transpose();
  const core::Model m(s);
  const Mat3 P = m.body(0).q_LB.toRotationMatrix();
  EXPECT_LT((P * m.body(0).inertia_B.asDiagonal() * P.transpose() - s.bodies[0].I_C_L).norm(), 1e-14);
}

}  // namespace
}  // namespace rigid_body_sim::test

namespace rigid_body_sim::test {
namespace {

TEST(ModelTuning, RetunedChangesTheSettingsAndKeepsEachBodysOwnSurface) {
  core::ModelSpec s = spec(boxBody(Vec3(0.2, 0.1, 0.05)), 1e-3, Vec3(0, 0, -9.81));
  core::BodySpec ball = ballBody(0.1);
  ball.friction = 0.9;  // its own
  s.bodies.push_back(ball);
  s.scene = {core::Sdf::plane(Vec3::UnitZ())};
  const core::Model model(s);
  core::Tuning t = model.tuning();
  EXPECT_EQ(t.gravity_W, Vec3(0, 0, -9.81));
  t.gravity_W = Vec3(0, 0, -2);
  t.damping.linear = 0.5;
  t.friction = 0.3;
  t.restitution = 0.4;
  const core::Model tuned = model.retuned(t);
  EXPECT_EQ(tuned.gravity(), Vec3(0, 0, -2));
  EXPECT_EQ(tuned.linearDecay(), std::exp(-0.5 * 1e-3));
  EXPECT_EQ(tuned.friction(0, -1), 0.3);  // the box follows the scene's surface
  EXPECT_EQ(tuned.friction(1, -1), 0.3);  // min(0.9, 0.3)
  EXPECT_EQ(tuned.body(1).friction, 0.9);
  EXPECT_TRUE(tuned.bounces());
  EXPECT_EQ(tuned.restitutionThreshold(), model.restitutionThreshold());  // 0.1 m/s > 2 |g| dt either way
  // The original is untouched.
  EXPECT_EQ(model.gravity(), Vec3(0, 0, -9.81));
  EXPECT_EQ(model.friction(0, -1), 0.5);
  EXPECT_FALSE(model.bounces());
  // A free fall under the new gravity: the Euler-Cromer velocity exactly.
  // A free fall under the new gravity and decay: v_N = h g α (1 − α^N) / (1 − α).
  core::State state;
  core::LinkState high;
  high.p_WL = Vec3(0, 0, 100);
  state.bodies.push_back(core::bodyStateFromLink(tuned.body(0), high));
  high.p_WL = Vec3(5, 0, 100);
  state.bodies.push_back(core::bodyStateFromLink(tuned.body(1), high));
  const int steps = 1000;
  for (int n = 0; n < steps; ++n) core::step(tuned, state);
  const double a = tuned.linearDecay(), expected = 1e-3 * -2.0 * a * (1 - std::pow(a, steps)) / (1 - a);
  EXPECT_NEAR(state.bodies[0].v_WB.z(), expected, 1e-12 * std::abs(expected));
}

TEST(ModelTuning, ARefusedTuningNamesTheKeyAndChangesNothing) {
  const core::Model model(spec(boxBody(Vec3(0.2, 0.1, 0.05)), 1e-3, Vec3(0, 0, -9.81)));
  core::Tuning t = model.tuning();
  t.gravity_W = Vec3(1000, 1000, 0);
  expectThrowsWith<std::invalid_argument>([&] { (void)model.retuned(t); }, {"gravity", "must be at most 1000"});
  t = model.tuning();
  t.friction = std::nan("");
  expectThrowsWith<std::invalid_argument>([&] { (void)model.retuned(t); }, {"contact.friction"});
  t = model.tuning();
  t.damping.linear = -1.0;
  expectThrowsWith<std::invalid_argument>([&] { (void)model.retuned(t); }, {"damping.linear"});
  EXPECT_EQ(model.gravity(), Vec3(0, 0, -9.81));
}

TEST(LinkPose, AChainOfFixedLinksComposesTheirJointsFromTheRoot) {
  // root → arm (1 m along x, turned 90° about z) → hand (0.5 m along the
  // arm's x): the hand sits at (1, 0.5, 0) in the root link frame, turned 90°.
  core::BodyModel body;
  body.link = "root";
  const Quat quarter(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
  body.fixed_links = {{"hand", "arm", core::Pose{Quat::Identity(), Vec3(0.5, 0, 0)}},
                      {"arm", "root", core::Pose{quarter, Vec3(1, 0, 0)}}};
  const std::optional<core::Pose> hand = core::linkPose(body, "hand");
  ASSERT_TRUE(hand.has_value());
  EXPECT_LT((hand->translation - Vec3(1, 0.5, 0)).norm(), 1e-15);
  EXPECT_LT(hand->rotation.angularDistance(quarter), 1e-15);
  EXPECT_EQ(core::linkPose(body, "root")->translation, Vec3::Zero());
  EXPECT_EQ(core::linkPose(body, "")->translation, Vec3::Zero());
  EXPECT_FALSE(core::linkPose(body, "foot").has_value());
  // A cycle a URDF could not give is refused, not followed for ever.
  body.fixed_links = {{"a", "b", core::Pose{}}, {"b", "a", core::Pose{}}};
  EXPECT_FALSE(core::linkPose(body, "a").has_value());
}

}  // namespace
}  // namespace rigid_body_sim::test
