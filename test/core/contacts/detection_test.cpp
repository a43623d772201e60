// Contact detection (src/core/detection.cpp): which points touch, their
// separations and normals, the reduction to regions, the order by key, and
// the broad phase between bodies.
#include <gtest/gtest.h>

#include <algorithm>

#include "../../test_util.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/step/workspace.h"

namespace rigid_body_sim::test {
namespace {

const Vec3 kHalf(0.2, 0.1, 0.05);  // the shipped box (urdf/box.urdf)

core::State at(const core::Model& model, const Vec3& p, const Quat& q = Quat::Identity()) {
  core::LinkState link;
  link.p_WL = p;
  link.q_WL = q;
  return stateOf(model, link);
}

TEST(Detection, ABoxPressedIntoTheGroundTouchesAtItsFourLowCornersByTheirDepth) {
  const core::Model model(onGround(boxBody(kHalf), impulse(0.0, 0.5)));
  core::State s = at(model, Vec3(0, 0, kHalf.z() - 1e-3));  // 1 mm deep
  core::Workspace ws;
  core::detectContacts(model, s, model.dt(), ws);
  ASSERT_EQ(ws.contacts.size(), 4u);  // the bottom face's points, reduced to the four that span it
  for (const core::Contact& c : ws.contacts) {
    EXPECT_NEAR(c.separation, -1e-3, 1e-15);
    EXPECT_EQ(c.normal_W, Vec3::UnitZ());
    EXPECT_NEAR(std::abs(c.r_W.x()), kHalf.x(), 1e-15);  // corners
    EXPECT_NEAR(std::abs(c.r_W.y()), kHalf.y(), 1e-15);
  }
  EXPECT_NEAR(ws.deepest_penetration, 1e-3, 1e-15);
  EXPECT_TRUE(std::is_sorted(ws.contacts.begin(), ws.contacts.end(),
                             [](const core::Contact& a, const core::Contact& b) { return a.key() < b.key(); }));
}

TEST(Detection, ABodyFartherThanItCanMoveThisStepTouchesNothing) {
  const core::Model model(onGround(boxBody(kHalf), impulse(0.0, 0.5)));
  core::State s = at(model, Vec3(0, 0, kHalf.z() + 0.01));  // 1 cm up, at rest: beyond the margin
  core::Workspace ws;
  core::detectContacts(model, s, model.dt(), ws);
  EXPECT_TRUE(ws.contacts.empty());
  s.bodies[0].v_WB = Vec3(0, 0, -20.0);  // 2 cm in this step: a speculative contact, not yet touching
  core::detectContacts(model, s, model.dt(), ws);
  ASSERT_FALSE(ws.contacts.empty());
  EXPECT_NEAR(ws.contacts.front().separation, 0.01, 1e-12);
  EXPECT_EQ(ws.deepest_penetration, 0.0);
}

TEST(Detection, TwoOverlappingBodiesTouchBothWaysAndFarOnesNot) {
  core::ModelSpec ms = onGround(boxBody(Vec3(0.1, 0.1, 0.1)), impulse(0.0, 0.5));
  ms.scene.clear();
  for (int i = 1; i < 3; ++i) {
    core::BodySpec b = boxBody(Vec3(0.1, 0.1, 0.1));
    b.name = "box" + std::to_string(i);
    ms.bodies.push_back(b);
  }
  const core::Model model(ms);
  core::State s = core::restState(model);
  s.bodies[0].p_WB = Vec3(0, 0, 0);
  s.bodies[1].p_WB = Vec3(0.05, 0.03, 0.199);  // on body 0, 1 mm deep, no sample on body 0's edges
  s.bodies[2].p_WB = Vec3(5, 0, 0);            // far away
  core::Workspace ws;
  core::detectContacts(model, s, model.dt(), ws);
  bool zero_on_one = false, one_on_zero = false;
  for (const core::Contact& c : ws.contacts) {
    EXPECT_NE(c.body, 2);
    EXPECT_NE(c.other, 2);
    zero_on_one |= c.body == 0 && c.other == 1;
    one_on_zero |= c.body == 1 && c.other == 0;
    if (c.body == 1) {
      EXPECT_LT((c.normal_W - Vec3::UnitZ()).norm(), 1e-12);  // out of body 0, toward body 1
    }
  }
  EXPECT_TRUE(zero_on_one);
  EXPECT_TRUE(one_on_zero);
  EXPECT_NEAR(ws.deepest_penetration, 1e-3, 1e-12);
}

TEST(Detection, ARoomsCornerGivesSeparateRegionsOfAtMostFourPoints) {
  core::ModelSpec ms = onGround(boxBody(kHalf), impulse(0.0, 0.5));
  ms.scene = {room()};
  const core::Model model(ms);
  // Pressed 0.1 mm into the floor and both walls of the (+x, +y) corner.
  core::State s = at(model, Vec3(1 - kHalf.x() + 1e-4, 1 - kHalf.y() + 1e-4, kHalf.z() - 1e-4));
  core::Workspace ws;
  core::detectContacts(model, s, model.dt(), ws);
  // Group the contacts by normal: each group is one region, at most four points.
  std::vector<std::pair<Vec3, int>> groups;
  for (const core::Contact& c : ws.contacts) {
    auto g =
        std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first.isApprox(c.normal_W, 1e-9); });
    if (g == groups.end()) {
      groups.emplace_back(c.normal_W, 1);
    } else {
      ++g->second;
    }
  }
  auto count = [&](const Vec3& n) {
    auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first.isApprox(n, 1e-9); });
    return g == groups.end() ? 0 : g->second;
  };
  // The floor and both walls push separately (the edges pressed into two
  // surfaces at once get the diagonal normal of the nearest free space).
  EXPECT_GE(count(Vec3::UnitZ()), 3);
  EXPECT_GE(count(-Vec3::UnitX()), 2);
  EXPECT_GE(count(-Vec3::UnitY()), 2);
  for (const auto& g : groups) EXPECT_LE(g.second, 4) << g.first.transpose();
}

}  // namespace
}  // namespace rigid_body_sim::test
