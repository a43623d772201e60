// The penalty responses keep a resting body inside their buffer; the log
// barrier never lets φ reach 0.
#include <gtest/gtest.h>

#include <cmath>

#include "../test_util.h"
#include "rigid_body_sim/core/contact.h"
#include "rigid_body_sim/core/diagnostics.h"
#include "rigid_body_sim/core/step.h"

namespace rigid_body_sim::test {
namespace {

const Vec3 kHalf(0.2, 0.1, 0.05);

core::Model penaltyModel(core::ContactMethod method) {
  core::ContactSettings c;
  c.method = method;
  core::ModelSpec ms = onGround(boxBody(kHalf), c);
  ms.sleep.enabled = false;
  return core::Model(ms);
}

/// Smallest and largest φ of the body's corners (the box's lowest points).
std::pair<double, double> cornerGap(const core::Model& model, const core::State& s) {
  double lo = 1e9, hi = -1e9;
  for (std::size_t i = 0; i < model.body(0).extreme_points; ++i) {
    const double z = (s.bodies[0].p_WB + s.bodies[0].q_WB * model.body(0).contact_points[i].r_B).z();
    if (z < 0.05) {  // the bottom face's corners
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
  }
  return {lo, hi};
}

TEST(Penalty, QuadraticNeverGainsEnergyInAFastImpact) {
  // Its spring is integrated explicitly and its damper dissipates: whatever
  // the speed (the model refuses k dt²/m > 1), a body leaves with less energy
  // than it brought. Dropped at up to 400 m/s, turned or flat.
  const core::Model model = penaltyModel(core::ContactMethod::kPenaltyQuadratic);
  for (const double speed : {10.0, 100.0, 400.0}) {
    for (const Vec3& rpy : {Vec3(0, 0, 0), Vec3(0.3, 0.2, 0.1), Vec3(1.0, 0.5, 0.0)}) {
      core::LinkState link;
      link.p_WL = Vec3(0, 0, 0.5);
      link.q_WL = Eigen::AngleAxisd(rpy.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Vec3::UnitY()) *
                  Eigen::AngleAxisd(rpy.x(), Vec3::UnitX());
      link.v_WL = Vec3(0, 0, -speed);
      core::State s = stateOf(model, link);
      const double e0 = core::totalEnergy(model, s);
      double most = e0;
      for (int n = 0; n < 2000; ++n) {
        core::step(model, s);
        most = std::max(most, core::totalEnergy(model, s));
      }
      EXPECT_LE(most, e0 * (1 + 1e-12)) << speed << " m/s, rpy " << rpy.transpose();
    }
  }
}

TEST(Penalty, QuadraticKeepsARestingBodyInsideItsBuffer) {
  const core::Model model = penaltyModel(core::ContactMethod::kPenaltyQuadratic);
  const double buffer = model.contact().penalty_buffer;
  core::LinkState link;
  link.p_WL = Vec3(0, 0, kHalf.z() + 0.5 * buffer);
  core::State s = stateOf(model, link);
  double lowest = 1e9;
  for (int n = 0; n < 3000; ++n) {
    core::step(model, s);
    lowest = std::min(lowest, cornerGap(model, s).first);
  }
  const auto [lo, hi] = cornerGap(model, s);
  EXPECT_GT(lowest, 0.0);  // never through the surface
  EXPECT_GT(lo, 0.0);
  EXPECT_LT(hi, buffer);
  // At rest the springs carry the weight: 4 k (ε − φ) = M g.
  EXPECT_NEAR(lo, buffer - 9.81 / (4 * model.contact().penalty_stiffness), 1e-5);
  EXPECT_LT(s.bodies[0].v_WB.norm(), 1e-6);
}

TEST(Penalty, LogBarrierNeverLetsPhiReachZero) {
  const core::Model model = penaltyModel(core::ContactMethod::kPenaltyLogBarrier);
  const double buffer = model.contact().barrier_buffer;
  core::LinkState link;
  link.p_WL = Vec3(0, 0, 0.3);  // dropped from 25 cm above its resting height
  core::State s = stateOf(model, link);
  double lowest = 1e9;
  for (int n = 0; n < 4000; ++n) {
    core::step(model, s);
    lowest = std::min(lowest, core::minSeparation(model, s.bodies[0], 0, 1.0));
  }
  EXPECT_GT(lowest, 0.0);
  const auto [lo, hi] = cornerGap(model, s);
  EXPECT_GT(lo, 0.0);
  EXPECT_LT(hi, buffer);
  // At rest: 4 ρ (1/φ − 1/ε) = M g.
  const double rho = model.contact().barrier_strength;
  EXPECT_NEAR(lo, 1.0 / (9.81 / (4 * rho) + 1.0 / buffer), 1e-5);
}

}  // namespace
}  // namespace rigid_body_sim::test
