// Touching pairs (docs/physics.md §10.3) against closed forms: a box at rest
// on the ground is held up by m g, the contact under the upper box of a
// stack carries its weight, a sliding box's friction is μ N against its
// slip, a body in flight touches nothing; a sleeping stack still reports
// its contacts and weights (ContactLedger), and a deleted body's go.
#include "rigid_body_sim/core/contacts/contact_report.h"

#include <gtest/gtest.h>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

const Vec3 kHalf(0.2, 0.1, 0.05);
constexpr double kG = 9.81;

core::ModelSpec awake(core::ModelSpec s) {
  s.sleep.enabled = false;  // the step reports only awake bodies' contacts (the node keeps a sleeper's)
  return s;
}

std::vector<core::ContactPairReport> pairsAfter(const core::Model& model, core::State& s, double seconds) {
  core::Workspace ws;
  for (int n = 0; n < static_cast<int>(std::lround(seconds / model.dt())); ++n) core::step(model, s, {}, &ws);
  return core::contactPairs(model, s, ws.contacts);
}

TEST(ContactPairs, ABoxAtRestOnTheGroundIsHeldUpByItsWeight) {
  const double mass = 2.5;
  const core::Model model(awake(onGround(boxBody(kHalf, mass), impulse(0.0, 0.5))));
  core::LinkState link;
  link.p_WL = Vec3(0, 0, kHalf.z());
  core::State s = stateOf(model, link);
  const auto pairs = pairsAfter(model, s, 1.0);
  ASSERT_EQ(pairs.size(), 1u);
  const core::ContactPairReport& p = pairs[0];
  EXPECT_EQ(p.body, 0);
  EXPECT_EQ(p.other, -1);
  EXPECT_EQ(p.item, 0);
  EXPECT_NEAR(p.normal_force_W.z(), mass * kG, 1e-6 * mass * kG);
  EXPECT_LT(p.normal_force_W.head<2>().norm(), 1e-9);
  EXPECT_LT(p.friction_force_W.norm(), 1e-6);
  EXPECT_NEAR(p.normal_W.z(), 1.0, 1e-12);
  EXPECT_GE(p.points_W.size(), 3u);
  for (const Vec3& q : p.points_W) EXPECT_NEAR(q.z(), 0.0, 1e-3);
}

TEST(ContactPairs, TheContactUnderTheUpperBoxOfAStackCarriesItsWeight) {
  // The upper box is the smaller, so its corners rest inside the lower's top
  // face (where the lower box's distance has a clear normal, not on its edges).
  core::BodySpec bottom = boxBody(kHalf, 3.0), top = boxBody(Vec3(0.1, 0.05, 0.05), 1.5);
  bottom.name = "bottom";
  top.name = "top";
  core::ModelSpec spec = awake(onGround(bottom, impulse(0.0, 0.5)));
  spec.bodies = {bottom, top};
  const core::Model model(spec);
  core::State s;
  for (int i = 0; i < 2; ++i) {
    core::LinkState link;
    link.p_WL = Vec3(0, 0, (2 * i + 1) * kHalf.z());
    s.bodies.push_back(core::bodyStateFromLink(model.body(i), link));
  }
  const auto pairs = pairsAfter(model, s, 1.0);
  ASSERT_EQ(pairs.size(), 2u);  // bottom on the ground, top on bottom
  const core::ContactPairReport& ground = pairs[0];
  const core::ContactPairReport& stack = pairs[1];
  EXPECT_EQ(ground.item, 0);
  EXPECT_NEAR(ground.normal_force_W.z(), 4.5 * kG, 1e-6 * 4.5 * kG);
  EXPECT_EQ(stack.body, 0);
  EXPECT_EQ(stack.other, 1);
  // On the lower body: the upper one presses down with its weight.
  EXPECT_NEAR(stack.normal_force_W.z(), -1.5 * kG, 1e-6 * 1.5 * kG);
  EXPECT_NEAR(stack.normal_W.z(), -1.0, 1e-9);
}

TEST(ContactPairs, ASlidingBoxsFrictionIsMuNAgainstItsSlip) {
  const double mu = 0.3, mass = 2.0;
  const core::Model model(awake(onGround(boxBody(kHalf, mass), impulse(0.0, mu))));
  core::LinkState link;
  link.p_WL = Vec3(0, 0, kHalf.z());
  link.v_WL = Vec3(2.0, 1.0, 0.0);
  core::State s = stateOf(model, link);
  const auto pairs = pairsAfter(model, s, 0.1);  // still sliding: it stops after 0.76 s
  ASSERT_EQ(pairs.size(), 1u);
  const Vec3 slip = s.bodies[0].v_WB.normalized();
  const Vec3 f = pairs[0].friction_force_W;
  EXPECT_NEAR(f.norm(), mu * mass * kG, 1e-6 * mu * mass * kG);
  EXPECT_NEAR(f.normalized().dot(slip), -1.0, 1e-9);
}

TEST(ContactPairs, ABodyInFlightTouchesNothing) {
  const core::Model model(awake(onGround(boxBody(kHalf), impulse(0.0, 0.5))));
  core::LinkState link;
  link.p_WL = Vec3(0, 0, 1.0);
  link.v_WL = Vec3(0, 0, 5.0);
  core::State s = stateOf(model, link);
  EXPECT_TRUE(pairsAfter(model, s, 0.2).empty());
}

/// A two-box stack (the upper box the smaller) resting on the ground, its
/// model and state, with sleep on.
struct Stack {
  core::Model model;
  core::State state;
};

Stack restingStack() {
  core::BodySpec bottom = boxBody(kHalf, 3.0), top = boxBody(Vec3(0.1, 0.05, 0.05), 1.5);
  bottom.name = "bottom";
  top.name = "top";
  core::ModelSpec spec = onGround(bottom, impulse(0.0, 0.5));
  spec.bodies = {bottom, top};
  Stack st{core::Model(spec), {}};
  for (int i = 0; i < 2; ++i) {
    core::LinkState link;
    link.p_WL = Vec3(0, 0, (2 * i + 1) * kHalf.z());
    st.state.bodies.push_back(core::bodyStateFromLink(st.model.body(i), link));
  }
  return st;
}

TEST(ContactLedger, ASleepingStackStillReportsWhatHoldsItUp) {
  Stack st = restingStack();
  core::Workspace ws;
  core::ContactLedger ledger;
  for (int n = 0; n < 2000; ++n) {
    core::step(st.model, st.state, {}, &ws);
    ledger.update(st.state, ws.contacts);
  }
  ASSERT_TRUE(st.state.bodies[0].asleep && st.state.bodies[1].asleep);
  // The step reports no contacts for sleepers; the ledger kept theirs.
  EXPECT_TRUE(core::contactPairs(st.model, st.state, ws.contacts).empty());
  const auto pairs = core::contactPairs(st.model, st.state, ledger.touchingNow(st.state, ws.contacts));
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_NEAR(pairs[0].normal_force_W.z(), 4.5 * kG, 1e-6 * 4.5 * kG);   // the stack on the ground
  EXPECT_NEAR(pairs[1].normal_force_W.z(), -1.5 * kG, 1e-6 * 1.5 * kG);  // the top box on the bottom one
  // Woken, they report the step's contacts again, none kept twice.
  core::wakeAll(st.state);
  core::step(st.model, st.state, {}, &ws);
  ledger.update(st.state, ws.contacts);
  EXPECT_TRUE(ledger.kept().empty());
  EXPECT_EQ(core::contactPairs(st.model, st.state, ledger.touchingNow(st.state, ws.contacts)).size(), 2u);
}

TEST(ContactLedger, ADeletedBodysContactsGoAndTheOthersMoveDown) {
  // Two boxes asleep on the ground apart, 3 kg and 1.5 kg; the first goes.
  core::BodySpec a = boxBody(kHalf, 3.0), b = boxBody(kHalf, 1.5);
  a.name = "a";
  b.name = "b";
  core::ModelSpec spec = onGround(a, impulse(0.0, 0.5));
  spec.bodies = {a, b};
  const core::Model model(spec);
  core::State s;
  for (int i = 0; i < 2; ++i) {
    core::LinkState link;
    link.p_WL = Vec3(2.0 * i, 0, kHalf.z());
    s.bodies.push_back(core::bodyStateFromLink(model.body(i), link));
  }
  core::Workspace ws;
  core::ContactLedger ledger;
  for (int n = 0; n < 2000; ++n) {
    core::step(model, s, {}, &ws);
    ledger.update(s, ws.contacts);
  }
  ASSERT_TRUE(s.bodies[0].asleep && s.bodies[1].asleep);
  const core::Model without = model.withoutBody(0);
  core::removeBody(model, s, 0);
  ledger.removeBody(0);
  ASSERT_FALSE(ledger.kept().empty());
  for (const core::Contact& c : ledger.kept()) {
    EXPECT_EQ(c.body, 0);  // b, now the first body
    EXPECT_EQ(c.other, -1);
  }
  const auto pairs = core::contactPairs(without, s, ledger.touchingNow(s, {}));
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_NEAR(pairs[0].normal_force_W.z(), 1.5 * kG, 1e-6 * 1.5 * kG);
}

}  // namespace
}  // namespace rigid_body_sim::test
