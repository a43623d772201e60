// Energy and momentum (src/core/diagnostics.cpp), against their definitions.
#include "rigid_body_sim/core/diagnostics.h"

#include <gtest/gtest.h>

#include "../test_util.h"

namespace rigid_body_sim::test {
namespace {

TEST(Diagnostics, EnergyIsKineticPlusPotentialAndMomentumIsInTheWorldFrame) {
  const core::Model model(spec(shippedBox(), 1e-3, Vec3(0, 0, -9.81)));
  const core::BodyModel& b = model.body(0);  // 1 kg, I = diag(0.0125, 0.0425, 0.05)/3
  core::BodyState s;
  s.p_WB = Vec3(0, 0, 2);
  s.v_WB = Vec3(3, 0, 4);                                     // |v| = 5
  s.q_WB = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));  // body x along world y
  s.w_B = Vec3(2, 0, 0);
  EXPECT_DOUBLE_EQ(core::kineticEnergy(b, s), 0.5 * 25 + 0.5 * 4 * 0.0125 / 3);
  EXPECT_DOUBLE_EQ(core::potentialEnergy(b, s, model.gravity()), 9.81 * 2);
  core::State state;
  state.bodies = {s};
  EXPECT_DOUBLE_EQ(core::totalEnergy(model, state), 0.5 * 25 + 0.5 * 4 * 0.0125 / 3 + 9.81 * 2);
  EXPECT_LT((core::angularMomentumWorld(b, s) - Vec3(0, 2 * 0.0125 / 3, 0)).norm(), 1e-15);
}

}  // namespace
}  // namespace rigid_body_sim::test
