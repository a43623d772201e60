// Round features (round_contact.cpp): a cylinder's rims and side and a
// capsule's segment, found where they are deepest instead of sampled. The
// closed forms of docs/physics.md §5.1 and §9: rest at the radius, rolling
// without loss, ⅔ g sin θ down an incline, the slide-then-roll time
// v₀ k / (μ g (1 + k)), k = I / (m r²), and a cylinder standing on its cap.
#include "contacts/round_contact.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/diagnostics.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

constexpr double kG = 9.81;
constexpr double kR = 0.1, kL = 0.3, kMass = 2.0;  // radius, length (a capsule's segment), kg

/// A body of mass kMass along its z with the inertia (across, across, axis)
/// and one round shape of radius kR and length kL.
core::BodySpec roundBody(const char* name, core::CollisionShape::Kind kind, double across, double axis) {
  core::BodySpec b;
  b.name = name;
  b.mass = kMass;
  b.I_C_L = Vec3(across, across, axis).asDiagonal();
  core::CollisionShape shape;
  shape.kind = kind;
  shape.radius = kR;
  shape.length = kL;
  b.collision = {shape};
  return b;
}

/// A solid cylinder along its z: I = m r²/2 about the axis, m (3 r² + L²)/12 across.
core::BodySpec cylinderBody() {
  return roundBody("cylinder", core::CollisionShape::Kind::kCylinder, kMass * (3 * kR * kR + kL * kL) / 12,
                   0.5 * kMass * kR * kR);
}

/// A solid capsule along its z (uniform density: a cylinder of length L and
/// two half balls). About the axis ρ(V_c r²/2 + V_s 2r²/5); across, the
/// half balls' centres of mass are 3r/8 beyond the segment's ends.
core::BodySpec capsuleBody() {
  const double vc = M_PI * kR * kR * kL, vs = 4.0 / 3.0 * M_PI * kR * kR * kR;
  const double mc = kMass * vc / (vc + vs), ms = kMass * vs / (vc + vs);
  const double axis = mc * kR * kR / 2 + ms * 2 * kR * kR / 5;
  const double across = mc * (3 * kR * kR + kL * kL) / 12 + ms * (2 * kR * kR / 5 + kL * kL / 4 + 3 * kL * kR / 8);
  return roundBody("capsule", core::CollisionShape::Kind::kCapsule, across, axis);
}

/// k = I_axis / (m r²): ½ for the cylinder.
double rollingK(const core::BodySpec& b) { return b.I_C_L(2, 2) / (b.mass * kR * kR); }

/// Lying: the body's z along the world's y, so it rolls along x.
const Quat kLying(Eigen::AngleAxisd(-M_PI / 2, Vec3::UnitX()));

core::Workspace stepFor(const core::Model& model, core::State& s, double seconds) {
  core::Workspace ws;
  const int steps = static_cast<int>(std::lround(seconds / model.dt()));
  for (int n = 0; n < steps; ++n) core::step(model, s, {}, &ws);
  return ws;
}

TEST(RimOnPlane, TheDeepestPointAndTheTwoAt120DegreesInClosedForm) {
  core::RoundFeature rim;
  rim.centre_B = Vec3(0, 0, 0.2);
  rim.rho = 0.1;
  const Vec3 n = Vec3(1, 0, 1).normalized();  // tilted 45° toward +x
  for (int phase = 0; phase < 3; ++phase) {
    const core::detail::RoundHit hit = core::detail::rimOnPlane(rim, phase, n, 0.5);
    const double angle = M_PI + 2 * M_PI / 3 * (phase == 2 ? -1 : phase);  // from +x, about +z
    const Vec3 expected = rim.centre_B + 0.1 * Vec3(std::cos(angle), std::sin(angle), 0);
    EXPECT_LT((hit.r_B - expected).norm(), 1e-15) << phase;
    EXPECT_NEAR(hit.phi, 0.5 + n.dot(expected), 1e-15) << phase;
  }
  // Flat on the plane: the first point goes to `across`.
  const core::detail::RoundHit flat = core::detail::rimOnPlane(rim, 0, Vec3(0, 0, -1), 0.0);
  EXPECT_LT((flat.r_B - Vec3(0.1, 0, 0.2)).norm(), 1e-15);
}

TEST(RoundOnSdf, ASegmentAcrossABoxEdgeTouchesInsideAndOnlyThere) {
  core::RoundFeature segment;
  segment.kind = core::RoundFeature::Kind::kSegment;
  segment.half_length = 0.5;
  const core::Sdf beam = core::Sdf::box(Vec3(0.02, 2, 0.02));  // top at z = 0.01, across x = ±0.01
  core::detail::RoundHit hit;
  // The segment along x, 0.05 above the beam's top, centred 0.2 off it.
  ASSERT_TRUE(core::detail::roundOnSdf(segment, 0, beam, Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix(),
                                       Vec3(0.2, 0, 0.06), hit));
  // Level within 1e-3: a point at most 2.5e-8 m beyond the edge, 50 mm above it.
  EXPECT_NEAR(hit.phi, 0.05, 1e-7);
  EXPECT_LT(std::abs(hit.r_B.z() + 0.2), 0.01 + 1e-4);  // on the beam's top: x within ±0.01
  // Along the beam, level: its ends hold it, no point inside.
  EXPECT_FALSE(core::detail::roundOnSdf(segment, 0, beam, Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX()).toRotationMatrix(),
                                        Vec3(0, 0, 0.06), hit));
}

TEST(RoundOnSdf, ARimAgainstABallSettlesOnTheClosestPoint) {
  core::RoundFeature rim;
  rim.rho = 0.1;
  const core::Sdf ball = core::Sdf::sphere(0.5);
  core::detail::RoundHit hit;
  // A rim level 0.2 above the ball's top, its centre 0.3 to the side.
  ASSERT_TRUE(core::detail::roundOnSdf(rim, 0, ball, Mat3::Identity(), Vec3(0.3, 0, 0.7), hit));
  // The closest rim point lies in the x-z plane toward the ball's axis: (0.2, 0, 0.7).
  EXPECT_LT((hit.r_B - Vec3(-0.1, 0, 0)).norm(), 1e-9);
  EXPECT_NEAR(hit.phi, std::hypot(0.2, 0.7) - 0.5, 1e-12);
}

class RoundBodies : public ::testing::TestWithParam<bool> {  // true: the cylinder, false: the capsule
 protected:
  core::BodySpec body() const { return GetParam() ? cylinderBody() : capsuleBody(); }
};

TEST_P(RoundBodies, LyingItRestsAtItsRadiusAndDoesNotCreep) {
  core::ModelSpec ms = onGround(body(), impulse(0.0, 0.5));
  const core::Model model(ms);
  core::State s = stateAt(model, Vec3(0, 0, kR + 0.01), kLying);
  stepFor(model, s, 1.0);
  const Vec3 settled = s.bodies[0].p_WB;
  EXPECT_NEAR(settled.z(), kR, 1e-6);
  stepFor(model, s, 4.0);
  EXPECT_LT((s.bodies[0].p_WB - settled).norm(), 1e-6);
  EXPECT_TRUE(s.bodies[0].asleep);
}

TEST_P(RoundBodies, RollingOnFlatGroundItKeepsItsSpeed) {
  const double v0 = 1.0;
  core::ModelSpec ms = onGround(body(), impulse(0.0, 0.5));
  ms.sleep.enabled = false;
  const core::Model model(ms);
  core::State s = stateAt(model, Vec3(0, 0, kR), kLying, Vec3(v0, 0, 0), Vec3(0, v0 / kR, 0));
  core::Workspace ws;
  double slowest = v0, fastest = v0, highest = kR, lowest = kR;
  for (int n = 0; n < 5000; ++n) {
    core::step(model, s, {}, &ws);
    slowest = std::min(slowest, s.bodies[0].v_WB.x());
    fastest = std::max(fastest, s.bodies[0].v_WB.x());
    highest = std::max(highest, s.bodies[0].p_WB.z());
    lowest = std::min(lowest, s.bodies[0].p_WB.z());
  }
  EXPECT_GT(slowest, 0.99 * v0);
  EXPECT_LT(fastest, 1.01 * v0);
  EXPECT_NEAR(s.bodies[0].p_WB.x(), 5.0 * v0, 0.01 * 5.0 * v0);
  EXPECT_LT(highest - kR, 1e-6);
  EXPECT_LT(kR - lowest, 1e-6);
}

TEST_P(RoundBodies, DownAnInclineItRollsWithGSinThetaOverOnePlusK) {
  const double theta = 20 * M_PI / 180;  // μ = 0.5 holds it: rolling needs tan θ k/(1+k) ≤ 0.13
  core::ModelSpec ms = onGround(body(), impulse(0.0, 0.5));
  const Vec3 normal(std::sin(theta), 0, std::cos(theta)), down_slope(std::cos(theta), 0, -std::sin(theta));
  ms.scene = {core::Sdf::plane(normal)};
  ms.sleep.enabled = false;
  const core::Model model(ms);
  core::State s = stateAt(model, kR * normal, kLying);
  stepFor(model, s, 1.0);
  const double a = kG * std::sin(theta) / (1 + rollingK(body()));
  EXPECT_NEAR(s.bodies[0].v_WB.dot(down_slope), a * s.time, 0.01 * a * s.time);
  EXPECT_NEAR(s.bodies[0].p_WB.dot(normal), kR, 1e-6);  // on the plane
}

TEST_P(RoundBodies, WithLittleFrictionItSlidesThenRollsAsCoulombSays) {
  const double v0 = 2.0, mu = 0.1, k = rollingK(body());
  core::ModelSpec ms = onGround(body(), impulse(0.0, mu));
  ms.sleep.enabled = false;
  const core::Model model(ms);
  core::State s = stateAt(model, Vec3(0, 0, kR), kLying, Vec3(v0, 0, 0));
  double t_roll = -1.0, v_roll = 0.0;
  for (int n = 0; n < 5000 && t_roll < 0; ++n) {
    core::step(model, s);
    const Vec3 w = core::angularVelocityWorld(s.bodies[0]);
    if ((s.bodies[0].v_WB + w.cross(Vec3(0, 0, -kR))).x() < 1e-9) {
      t_roll = s.time;
      v_roll = s.bodies[0].v_WB.x();
    }
  }
  const double expected_t = v0 * k / (mu * kG * (1 + k));  // v₀/(3μg) for the cylinder
  EXPECT_NEAR(t_roll, expected_t, 0.01 * expected_t);
  EXPECT_NEAR(v_roll, v0 / (1 + k), 0.01 * v0 / (1 + k));
  stepFor(model, s, 1.0);  // then it rolls on at that speed
  EXPECT_NEAR(s.bodies[0].v_WB.x(), v0 / (1 + k), 0.01 * v0 / (1 + k));
}

INSTANTIATE_TEST_SUITE_P(CylinderAndCapsule, RoundBodies, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& param) {
                           return param.param ? "Cylinder" : "Capsule";
                         });

TEST(Cylinder, StoodOnItsCapItRestsFlat) {
  const core::Model model(onGround(cylinderBody(), impulse(0.0, 0.5)));
  core::State s = stateAt(model, Vec3(0, 0, kL / 2 + 0.01), Quat::Identity());
  stepFor(model, s, 2.0);
  EXPECT_NEAR(s.bodies[0].p_WB.z(), kL / 2, 1e-6);
  EXPECT_LT(s.bodies[0].q_WB.angularDistance(Quat::Identity()), 1e-6);
  EXPECT_LT(s.bodies[0].p_WB.head<2>().norm(), 1e-6);
  EXPECT_TRUE(s.bodies[0].asleep);
}

/// A body lying across a beam 2 cm wide, dropped a little tilted (0.01 rad)
/// so it lands on one edge first: it stays on the beam, within the
/// position slop of its top (an edge holds it at one point while it tilts
/// more than 1e-3, so it rests in the slop, not exactly; docs/physics.md §5.1).
void restsAcrossABeam(const core::BodySpec& body) {
  core::ModelSpec ms = onGround(body, impulse(0.0, 0.5));
  ms.scene = {core::Sdf::box(Vec3(0.02, 2, 0.02))};  // top at z = 0.01; the rims hang 0.14 m beyond it
  const core::Model model(ms);
  core::State s =
      stateAt(model, Vec3(0, 0, 0.01 + kR + 0.005), Quat(Eigen::AngleAxisd(M_PI / 2 + 0.01, Vec3::UnitY())));
  stepFor(model, s, 2.0);
  EXPECT_NEAR(s.bodies[0].p_WB.z(), 0.01 + kR, 1.5 * ms.contact.position_slop) << body.name;
  EXPECT_LT(std::abs(s.bodies[0].p_WB.x()), 0.01) << body.name;
}

TEST(Cylinder, LyingAcrossAThinBeamItStaysOnItsSide) { restsAcrossABeam(cylinderBody()); }

TEST(Capsule, LyingAcrossAThinBeamItStaysOnItsSegment) { restsAcrossABeam(capsuleBody()); }

TEST(Cylinder, LyingOnAnotherBodyItRestsAtItsRadiusAboveIt) {
  core::ModelSpec ms = onGround(boxBody(Vec3(0.5, 0.5, 0.05), 10.0), impulse(0.0, 0.5));
  ms.bodies.push_back(cylinderBody());
  const core::Model model(ms);
  core::State s;
  s.bodies = {core::bodyStateFromLink(model.body(0), {Vec3(0, 0, 0.05), Quat::Identity()}),
              core::bodyStateFromLink(model.body(1), {Vec3(0, 0, 0.1 + kR + 0.005), kLying})};
  stepFor(model, s, 1.0);
  EXPECT_NEAR(s.bodies[1].p_WB.z(), 0.1 + kR, 1e-6);
}

}  // namespace
}  // namespace rigid_body_sim::test
