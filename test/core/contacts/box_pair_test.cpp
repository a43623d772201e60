// Two boxes in contact (src/core/box_pair.cpp, docs/physics.md §5.1): one
// normal for the pair, edges that cross between the samples, the corners of
// a shared region that are neither box's corner, and an edge striking an
// edge against the closed-form impulse.
#include "contacts/box_pair.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../../test_util.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/step/step.h"
#include "rigid_body_sim/core/step/workspace.h"

namespace rigid_body_sim::test {
namespace {

/// Two box bodies (half extents lower, upper), no scene, gravity g.
core::Model twoBoxes(const Vec3& lower, const Vec3& upper, const Vec3& g, const core::ContactSettings& contact) {
  core::ModelSpec ms;
  ms.bodies = {boxBody(lower), boxBody(upper)};
  ms.bodies[0].name = "lower";
  ms.bodies[1].name = "upper";
  ms.gravity_W = g;
  ms.contact = contact;
  return core::Model(ms);
}

core::BodyState placed(const core::Model& model, int i, const Vec3& p, const Quat& q, const Vec3& v = Vec3::Zero()) {
  core::LinkState link;
  link.p_WL = p;
  link.q_WL = q;
  link.v_WL = v;
  return core::bodyStateFromLink(model.body(i), link);
}

/// Of a box with half extents `half` turned by q: the middle of its edge
/// along its own x axis that lies lowest (world z), relative to its centre.
Vec3 lowestXEdge(const Vec3& half, const Quat& q) {
  Vec3 best = Vec3::Zero();
  double lowest = INFINITY;
  for (const double y : {-half.y(), half.y()}) {
    for (const double z : {-half.z(), half.z()}) {
      const Vec3 m = q * Vec3(0.0, y, z);
      if (m.z() < lowest) {
        lowest = m.z();
        best = m;
      }
    }
  }
  return best;
}

// The shipped box (0.4 × 0.2 × 0.1 m, samples 0.1 m apart) lies turned 30°
// about its long axis, so its top edge is a ridge; a second one, across it
// and turned 20° about its own long axis, presses its lowest edge 1 mm into
// that ridge, where neither edge has a sample. Before the pair had one
// normal, this gave no contact at all.
TEST(BoxPair, EdgesCrossingBetweenSamplesTouchAtTheCrossingAlongTheirCommonNormal) {
  const Vec3 half(0.2, 0.1, 0.05);
  const core::Model model = twoBoxes(half, half, Vec3::Zero(), impulse(0.0, 0.5));
  const Quat q_lower(Eigen::AngleAxisd(M_PI / 6.0, Vec3::UnitX()));
  const Quat q_upper =
      Quat(Eigen::AngleAxisd(M_PI / 9.0, Vec3::UnitY())) * Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
  // The ridge: the lower box's highest x edge; the crossing 5 cm along it.
  Vec3 ridge = Vec3::Zero();
  for (const double y : {-half.y(), half.y()}) {
    for (const double z : {-half.z(), half.z()}) {
      const Vec3 m = q_lower * Vec3(0.0, y, z);
      if (m.z() > ridge.z()) ridge = m;
    }
  }
  const Vec3 crossing = ridge + Vec3(0.05, 0.0, 0.0);
  // The upper box's lowest edge passes through the crossing, 5 cm from its
  // middle (between samples), 1 mm below the ridge.
  const Vec3 edge_mid = lowestXEdge(half, q_upper);
  const Vec3 p_upper = crossing - edge_mid - 0.05 * (q_upper * Vec3::UnitX()) - Vec3(0.0, 0.0, 1e-3);
  core::State s;
  s.bodies = {placed(model, 0, Vec3::Zero(), q_lower), placed(model, 1, p_upper, q_upper)};
  core::Workspace ws;
  core::detectContacts(model, s, model.dt(), ws);
  Vec3 n = (q_upper * Vec3::UnitX()).cross(q_lower * Vec3::UnitX()).normalized();
  if (n.z() < 0.0) n = -n;  // out of the lower box, toward the upper
  int at_crossing = 0;
  ASSERT_FALSE(ws.contacts.empty());
  for (const core::Contact& c : ws.contacts) {
    const Vec3 expected = c.body == 1 ? n : Vec3(-n);
    EXPECT_LT((c.normal_W - expected).norm(), 1e-12) << "contact of body " << c.body << ", point " << c.point;
    const Vec3 point = s.bodies[c.body].p_WB + c.r_W;
    if ((point - crossing).norm() < 2e-3) {  // the lower edge's point, or the upper's 1 mm under it
      ++at_crossing;
      EXPECT_NEAR(c.separation, -1e-3 * n.z(), 1e-12);  // 1 mm down, along the common normal
    }
  }
  EXPECT_EQ(at_crossing, 2);  // each edge's point, one each way
}

// A cube turned 45° about z lies 1 mm into a long bar of the same width,
// its middle off every sample of the bar's edges: its bottom is a diamond
// whose left and right corners hang over the bar. The region they share
// has six corners: two of the cube's and four where the cube's edges cross
// the bar's sides. Before, only the two cube corners touched, on a line
// through the centre.
TEST(BoxPair, ABoxLyingAcrossAnotherTouchesWhereItsEdgesCrossTheFaceSides) {
  const Vec3 bar(0.2, 0.05, 0.05), cube(0.05, 0.05, 0.05);
  const core::Model model = twoBoxes(bar, cube, Vec3::Zero(), impulse(0.0, 0.5));
  const Quat turned(Eigen::AngleAxisd(M_PI / 4.0, Vec3::UnitZ()));
  const double x = 0.05;  // the bar's edge samples are at 0 and 0.1
  core::State s;
  s.bodies = {placed(model, 0, Vec3::Zero(), Quat::Identity()), placed(model, 1, Vec3(x, 0.0, 0.1 - 1e-3), turned)};
  core::Workspace ws;
  core::detectContacts(model, s, model.dt(), ws);
  const double reach = std::sqrt(2.0) * cube.x() - bar.y();  // where the diamond's edges cross y = ±0.05, from x
  int on_side[2] = {0, 0};
  int of_cube = 0;
  for (const core::Contact& c : ws.contacts) {
    if (c.body != 1) continue;
    ++of_cube;
    EXPECT_LT((c.normal_W - Vec3::UnitZ()).norm(), 1e-12);
    EXPECT_NEAR(c.separation, -1e-3, 1e-12);
    const Vec3 point = s.bodies[1].p_WB + c.r_W;
    if (std::abs(std::abs(point.y()) - bar.y()) < 1e-12) {
      EXPECT_NEAR(std::abs(point.x() - x), reach, 1e-12);
      ++on_side[point.y() > 0.0];
    }
  }
  EXPECT_EQ(of_cube, 4);  // the region reduced to the four that span it
  EXPECT_EQ(on_side[0], 1);
  EXPECT_EQ(on_side[1], 1);
}

// Cubes of 10 cm (samples only at the corners), frictionless, e = 0, no
// gravity. The upper is turned 45° about y, so its lowest edge lies along y
// under its centre; the lower is turned 40° about x, so its ridge runs
// along x, off its centre by y_r. The upper comes down at v onto the ridge
// and the edges meet at right angles, touching: their common normal is z.
// One impulse J along z through the upper's centre: it keeps no sideways
// velocity and no spin, and with K = 2/m + y_r² / I (I = m s² / 6) the
// contact stops closing, J = v / K.
TEST(BoxPair, AnEdgeStrikingAnEdgePushesAlongTheirCommonNormalByTheClosedForm) {
  const double h = 0.05, m = 1.0, v = 1.0;
  const Vec3 half = Vec3::Constant(h);
  const core::Model model = twoBoxes(half, half, Vec3::Zero(), impulse(0.0, 0.0));
  const Quat q_lower(Eigen::AngleAxisd(M_PI * 40.0 / 180.0, Vec3::UnitX()));
  const Quat q_upper(Eigen::AngleAxisd(M_PI / 4.0, Vec3::UnitY()));
  Vec3 ridge = Vec3::Zero();
  for (const double y : {-h, h}) {
    for (const double z : {-h, h}) {
      const Vec3 c = q_lower * Vec3(0.0, y, z);
      if (c.z() > ridge.z()) ridge = c;
    }
  }
  const double lowest = std::sqrt(2.0) * h;  // the upper's edge below its centre
  core::State s;
  s.bodies = {placed(model, 0, Vec3::Zero(), q_lower),
              placed(model, 1, Vec3(0.0, ridge.y(), ridge.z() + lowest), q_upper, Vec3(0.0, 0.0, -v))};
  core::Workspace ws;
  core::step(model, s, {}, &ws);
  const double inertia = m * (2.0 * h) * (2.0 * h) / 6.0;
  const double K = 2.0 / m + ridge.y() * ridge.y() / inertia;
  const double J = v / K;
  const core::BodyState &lower = s.bodies[0], &upper = s.bodies[1];
  EXPECT_LT(upper.v_WB.head<2>().norm(), 1e-9);
  EXPECT_LT(upper.w_B.norm(), 1e-9);
  EXPECT_NEAR(upper.v_WB.z(), -v + J / m, 1e-6);
  EXPECT_NEAR(lower.v_WB.z(), -J / m, 1e-6);
  EXPECT_LT(lower.v_WB.head<2>().norm(), 1e-9);
  const Vec3 w_lower_W = lower.q_WB * lower.w_B;
  EXPECT_NEAR(w_lower_W.x(), -J * ridge.y() / inertia, 1e-6);
  EXPECT_LT(w_lower_W.tail<2>().norm(), 1e-9);
}

// The separating axis alone: two boxes face to face pick the lower index's
// face both ways, so both directions of the pair push along one line.
TEST(BoxPair, FaceToFaceBothDirectionsPickTheSameLine) {
  core::detail::BoxInFrame lower, upper;
  lower.half = Vec3(0.2, 0.1, 0.05);
  upper.half = lower.half;
  upper.centre_F = Vec3(0.03, 0.01, 0.0999);
  const core::detail::PairPlane up = core::detail::boxPairPlane(lower, upper, true);
  const core::detail::PairPlane down = core::detail::boxPairPlane(upper, lower, false);
  EXPECT_EQ(up.n_F, Vec3::UnitZ());
  EXPECT_EQ(down.n_F, -Vec3::UnitZ());
  EXPECT_EQ(up.base_face, 2);
  EXPECT_EQ(down.base_face, -1);  // the other box's face
  EXPECT_NEAR(up.support, 0.05, 1e-15);
  EXPECT_NEAR(down.support, -(0.0999 - 0.05), 1e-15);
}

}  // namespace
}  // namespace rigid_body_sim::test
