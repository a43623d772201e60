// The state (src/core/state.cpp): the link frame users see against the
// principal body frame the core integrates, and the contact key's order.
#include "rigid_body_sim/core/bodies/state.h"

#include <gtest/gtest.h>

#include "../../test_util.h"

namespace rigid_body_sim::test {
namespace {

/// A body whose centre of mass is off the link origin and whose principal
/// axes are turned from the link's: the two frames differ in every way.
core::Model offsetBody() {
  core::BodySpec b = shippedBox();
  b.p_LC = Vec3(0.3, -0.1, 0.2);
  const Mat3 R = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).toRotationMatrix();
  b.I_C_L = R * boxInertia(1.0, Vec3(0.2, 0.1, 0.05)) * R.transpose();
  return core::Model(spec(b, 1e-3, Vec3::Zero()));
}

TEST(State, LinkAndBodyStatesConvertBothWays) {
  const core::Model model = offsetBody();
  core::LinkState link;
  link.p_WL = Vec3(1, 2, 3);
  link.q_WL = Quat(Eigen::AngleAxisd(1.1, Vec3(0, 1, 1).normalized()));
  link.v_WL = Vec3(0.5, 0, -1);
  link.w_W = Vec3(0.2, -0.3, 2);
  const core::BodyState s = core::bodyStateFromLink(model.body(0), link);
  const core::LinkState back = core::linkState(model.body(0), s);
  EXPECT_LT((back.p_WL - link.p_WL).norm(), 1e-14);
  EXPECT_LT(back.q_WL.angularDistance(link.q_WL), 1e-14);
  EXPECT_LT((back.v_WL - link.v_WL).norm(), 1e-14);
  EXPECT_LT((back.w_W - link.w_W).norm(), 1e-14);
  // The centre of mass moves with the lever arm: v_WB = v_WL + ω × (R_WL p_LC).
  const Vec3 arm = link.q_WL * Vec3(0.3, -0.1, 0.2);
  EXPECT_LT((s.p_WB - (link.p_WL + arm)).norm(), 1e-14);
  EXPECT_LT((s.v_WB - (link.v_WL + link.w_W.cross(arm))).norm(), 1e-14);
}

TEST(State, TheRestStateHasEveryLinkAtTheOriginAtRest) {
  const core::Model model = offsetBody();
  const core::State s = core::restState(model);
  const core::LinkState link = core::linkState(model.body(0), s.bodies[0]);
  EXPECT_LT(link.p_WL.norm(), 1e-15);
  EXPECT_LT(link.q_WL.angularDistance(Quat::Identity()), 1e-15);
  EXPECT_EQ(s.bodies[0].v_WB, Vec3::Zero());
  EXPECT_EQ(s.time, 0.0);
}

TEST(State, ContactKeysOrderByBodyThenOtherThenItemThenPoint) {
  const auto key = [](int body, int other, int item, int point) { return core::ContactKey{body, other, item, point}; };
  EXPECT_LT(key(0, 5, -1, 9), key(1, -1, 0, 0));
  EXPECT_LT(key(1, -1, 0, 0), key(1, 0, -1, 0));  // the scene (−1) before other bodies
  EXPECT_LT(key(1, -1, 0, 7), key(1, -1, 1, 0));
  EXPECT_LT(key(1, -1, 1, 2), key(1, -1, 1, 3));
  EXPECT_FALSE(key(1, -1, 1, 3) < key(1, -1, 1, 3));
  EXPECT_EQ(key(1, -1, 1, 3), key(1, -1, 1, 3));
  core::ContactImpulse a, b;
  a.body = b.body = 2;
  a.normal = 1.0;
  b.normal = 2.0;
  EXPECT_EQ(a.key(), b.key());  // the same contact, other impulses
  EXPECT_FALSE(a == b);
}

TEST(State, AtRestMeansAsleepOrStillForTheSleepTime) {
  const core::Model model = offsetBody();
  core::BodyState s;
  EXPECT_FALSE(core::atRest(model, s));
  s.still_time = model.sleep().time;
  EXPECT_TRUE(core::atRest(model, s));
  s.still_time = 0.0;
  s.asleep = true;
  EXPECT_TRUE(core::atRest(model, s));
}

// A frame fixed in a link: a link at (1, 2, 3) turned a quarter about z,
// spinning at 2 rad/s about z and moving at (0, 0, 1) m/s; the frame 0.5 m
// along the link's x (world y) and turned a quarter more is at (1, 2.5, 3),
// turned a half, and moves at ω × r = (−1, 0, 0) more.
TEST(State, AFrameFixedInALinkMovesWithIt) {
  core::LinkState link;
  link.p_WL = core::Vec3(1.0, 2.0, 3.0);
  link.q_WL = core::Quat(Eigen::AngleAxisd(M_PI / 2, core::Vec3::UnitZ()));
  link.w_W = core::Vec3(0.0, 0.0, 2.0);
  link.v_WL = core::Vec3(0.0, 0.0, 1.0);
  const core::Pose X_LS{core::Quat(Eigen::AngleAxisd(M_PI / 2, core::Vec3::UnitZ())), core::Vec3(0.5, 0.0, 0.0)};
  const core::LinkState frame = core::frameState(link, X_LS);
  EXPECT_LT((frame.p_WL - core::Vec3(1.0, 2.5, 3.0)).norm(), 1e-15);
  EXPECT_LT(frame.q_WL.angularDistance(core::Quat(Eigen::AngleAxisd(M_PI, core::Vec3::UnitZ()))), 1e-15);
  EXPECT_LT((frame.v_WL - core::Vec3(-1.0, 0.0, 1.0)).norm(), 1e-15);
  EXPECT_EQ(frame.w_W, link.w_W);
}

}  // namespace
}  // namespace rigid_body_sim::test
