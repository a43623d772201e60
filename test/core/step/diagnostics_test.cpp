// Energy and momentum (src/core/diagnostics.cpp), against their definitions.
#include "rigid_body_sim/core/step/diagnostics.h"

#include <gtest/gtest.h>

#include <tuple>

#include "../../test_util.h"

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

// How deep a start lies in the ground is what the start warning says. A
// wheel (a cylinder of radius 0.1 m lying on its side) with its axis 0.05 m
// up is 0.05 m deep at its rim's lowest point; the check of contact points
// alone saw only the rim's centre and said 0 (the four-wheeled base started
// with its wheels 100 mm deep got no warning). A box's corner and a ball
// are measured as before.
TEST(Diagnostics, SceneDepthIsTheDeepestPointOfCornersBallsAndRims) {
  core::BodySpec wheel = ballBody(0.1);
  wheel.collision[0].kind = core::CollisionShape::Kind::kCylinder;
  wheel.collision[0].length = 0.05;
  core::BodySpec ball = ballBody(0.1);
  for (const auto& [body, lying, centre, depth] :
       {std::tuple{wheel, Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX())), 0.05, 0.05},
        std::tuple{wheel, Quat::Identity(), 0.0, 0.025},  // standing on a cap: half its length
        std::tuple{ball, Quat::Identity(), 0.03, 0.07},
        std::tuple{boxBody(Vec3(0.2, 0.1, 0.05)), Quat::Identity(), 0.01, 0.04}}) {
    core::ModelSpec ms = spec(body, 1e-3, Vec3(0, 0, -9.81));
    ms.scene = {core::Sdf::plane(Vec3::UnitZ())};
    const core::Model model(ms);
    core::BodyState s;
    s.p_WB = Vec3(0.3, -0.2, centre);
    s.q_WB = lying;
    EXPECT_NEAR(core::sceneDepth(model, 0, s), depth, 1e-12) << "centre " << centre;
    s.p_WB.z() += depth + 1e-3;  // lifted clear
    EXPECT_EQ(core::sceneDepth(model, 0, s), 0.0) << "centre " << centre;
  }
}

}  // namespace
}  // namespace rigid_body_sim::test
