// Per-body surfaces (issue 14): each body's friction and restitution, and
// the scene's (contact.friction and contact.restitution), combined for a
// pair by the chosen rule. Each rule is held to the closed forms of a
// sliding box (stopping distance v₀²/(2 μ g)) and a bouncing ball (apex
// ratio e²), with μ and e the rule's value for the pair.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../test_util.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

const Vec3 kHalf(0.2, 0.1, 0.05);
constexpr double kG = 9.81;  // m/s², onGround()'s gravity

struct Rule {
  core::CombineRule rule;
  const char* name;
  double (*expected)(double, double);
};

const Rule kRules[] = {
    {core::CombineRule::kMin, "min", [](double a, double b) { return std::min(a, b); }},
    {core::CombineRule::kMax, "max", [](double a, double b) { return std::max(a, b); }},
    {core::CombineRule::kAverage, "average", [](double a, double b) { return 0.5 * (a + b); }},
    {core::CombineRule::kMultiply, "multiply", [](double a, double b) { return a * b; }},
    {core::CombineRule::kGeometric, "geometric", [](double a, double b) { return std::sqrt(a * b); }},
};

/// Body i of `model` at p, moving at v, level.
core::BodyState bodyAt(const core::Model& model, int i, const Vec3& p, const Vec3& v = Vec3::Zero()) {
  core::LinkState link;
  link.p_WL = p;
  link.v_WL = v;
  return core::bodyStateFromLink(model.body(i), link);
}

/// How far body `body` slides along x from state `s` until it stops.
double slideDistance(const core::Model& model, core::State s, int body) {
  const double x0 = s.bodies[body].p_WB.x();
  int n = 0;
  while (s.bodies[body].v_WB.x() > 1e-9 && n++ < 20000) core::step(model, s);
  return s.bodies[body].p_WB.x() - x0;
}

TEST(Materials, EachFrictionRuleGivesTheSlidingDistanceOfItsCoefficient) {
  const double scene = 0.8, own = 0.2, v0 = 2.0;
  for (const Rule& r : kRules) {
    core::ModelSpec ms = onGround(boxBody(kHalf), impulse(0.0, scene));
    ms.sleep.enabled = false;
    ms.contact.friction_combine = r.rule;
    ms.bodies[0].friction = own;
    const core::Model model(ms);
    const double mu = r.expected(own, scene);
    EXPECT_DOUBLE_EQ(model.friction(0, -1), mu) << r.name;
    const double expected = v0 * v0 / (2 * mu * kG);
    core::State s;
    s.bodies = {bodyAt(model, 0, Vec3(0, 0, kHalf.z()), Vec3(v0, 0, 0))};
    EXPECT_NEAR(slideDistance(model, s, 0), expected, 0.02 * expected) << r.name << ", mu " << mu;
  }
}

TEST(Materials, EachRestitutionRuleGivesTheApexRatioOfItsCoefficient) {
  const double scene = 0.9, own = 0.5, radius = 0.1, h = 1.0;
  for (const Rule& r : kRules) {
    core::ModelSpec ms = onGround(ballBody(radius), impulse(scene, 0.5));
    ms.contact.restitution_combine = r.rule;
    ms.bodies[0].restitution = own;
    const core::Model model(ms);
    const double e = r.expected(own, scene);
    core::State s;
    s.bodies = {bodyAt(model, 0, Vec3(0, 0, h + radius))};
    double apex = -1.0, prev_vz = 0.0;
    for (int n = 0; n < 4000 && apex < 0.0; ++n) {
      core::step(model, s);
      const double vz = s.bodies[0].v_WB.z();
      if (prev_vz > 0.0 && vz <= 0.0) apex = s.bodies[0].p_WB.z() - radius;
      prev_vz = vz;
    }
    EXPECT_NEAR(apex / h, e * e, 0.02 * e * e + 1e-3) << r.name << ", e " << e;
  }
}

TEST(Materials, TwoBodiesCombineTheirOwnSurfacesNotTheScenes) {
  // A box slides on a heavy box that rests on the ground: the pair's friction
  // is min(0.3, 0.6) whatever the ground's (1.0), and a body without its own
  // surface takes the scene's.
  core::ModelSpec ms = onGround(boxBody(kHalf, 1.0), impulse(0.0, 1.0));
  ms.sleep.enabled = false;
  core::BodySpec base = boxBody(Vec3(2.0, 1.0, 0.1), 1000.0);
  base.name = "base";
  base.friction = 0.3;
  ms.bodies[0].friction = 0.6;
  ms.bodies.insert(ms.bodies.begin(), base);
  core::BodySpec plain = boxBody(kHalf);
  plain.name = "plain";
  ms.bodies.push_back(plain);
  const core::Model model(ms);
  EXPECT_EQ(model.friction(1, 0), 0.3);
  EXPECT_EQ(model.friction(0, -1), 0.3);
  EXPECT_EQ(model.friction(2, -1), 1.0);
  EXPECT_EQ(model.friction(2, 1), 0.6);
  const double v0 = 1.0, expected = v0 * v0 / (2 * 0.3 * kG);
  core::State s;
  s.bodies = {bodyAt(model, 0, Vec3(0, 0, 0.1)),  // the base on the ground
              bodyAt(model, 1, Vec3(-1.0, 0, 0.2 + kHalf.z()), Vec3(v0, 0, 0)),
              bodyAt(model, 2, Vec3(5, 5, kHalf.z()))};
  EXPECT_NEAR(slideDistance(model, s, 1), expected, 0.01 * expected);
}

TEST(Materials, ASurfaceOutOfRangeIsRefusedNamingTheBody) {
  core::ModelSpec ms = onGround(boxBody(kHalf), impulse(0.0, 0.5));
  ms.bodies[0].friction = -0.1;
  expectThrowsWith<std::invalid_argument>([&] { core::Model m(ms); },
                                          {"body 'box': contact.friction = -0.1", "must be within [0, 10]"});
  ms.bodies[0].friction.reset();
  ms.bodies[0].restitution = 1.5;
  expectThrowsWith<std::invalid_argument>([&] { core::Model m(ms); },
                                          {"body 'box': contact.restitution = 1.5", "must be within [0, 1]"});
}

}  // namespace
}  // namespace rigid_body_sim::test
