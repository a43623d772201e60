// The position correction (src/core/position_correction.cpp, docs/physics.md
// §5.8): a penetrating body is pushed out to the slop, its velocity untouched.
#include <gtest/gtest.h>

#include "../../test_util.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/step/workspace.h"

namespace rigid_body_sim::test {
namespace {

TEST(PositionCorrection, PushesAPenetratingBoxOutToTheSlopWithoutTouchingItsVelocity) {
  const Vec3 half(0.2, 0.1, 0.05);
  const core::Model model(onGround(boxBody(half), core::ContactSettings{}));
  core::LinkState link;
  link.p_WL = Vec3(0, 0, half.z() - 5e-3);  // 5 mm into the ground
  core::State s = stateOf(model, link);
  core::Workspace ws;
  core::detectContacts(model, s, model.dt(), ws);
  ASSERT_TRUE(core::solveContactImpulses(model, s, model.dt(), ws));  // the islands and predictions
  const core::BodyState before = s.bodies[0];
  core::correctPositions(model, s, ws);
  // Every corner ends within the slop, from 5 mm deep (sequential pushes at
  // the corners, four Gauss-Seidel sweeps: it may tilt a little, not sink).
  const double slop = model.contact().position_slop;
  double deepest = 0.0;
  for (const core::ContactPoint& p : model.body(0).contact_points) {
    deepest = std::min(deepest, (s.bodies[0].p_WB + s.bodies[0].q_WB * p.r_B).z());
  }
  EXPECT_GE(deepest, -slop - 1e-9);  // out to the slop
  EXPECT_LT(deepest, 0.0);           // not beyond: the contact stays
  EXPECT_LT(s.bodies[0].q_WB.angularDistance(before.q_WB), 1e-3);
  EXPECT_EQ(s.bodies[0].v_WB, before.v_WB);
  EXPECT_EQ(s.bodies[0].w_B, before.w_B);
}

TEST(PositionCorrection, LeavesAContactWithinTheSlopAlone) {
  const Vec3 half(0.2, 0.1, 0.05);
  const core::Model model(onGround(boxBody(half), core::ContactSettings{}));
  core::LinkState link;
  link.p_WL = Vec3(0, 0, half.z() - 0.2 * model.contact().position_slop);
  core::State s = stateOf(model, link);
  core::Workspace ws;
  core::detectContacts(model, s, model.dt(), ws);
  ASSERT_TRUE(core::solveContactImpulses(model, s, model.dt(), ws));
  const core::State before = s;
  core::correctPositions(model, s, ws);
  EXPECT_TRUE(bitIdentical(s, before));
}

}  // namespace
}  // namespace rigid_body_sim::test
