#include "rigid_body_sim/core/bodies/inertia.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "../../test_util.h"

namespace rigid_body_sim::test {
namespace {

TEST(PointMasses, InertiaIsTheNotesSum) {
  // Eight masses m at (±a, ±b, ±c): Ixx = 8 m (b² + c²), products zero.
  std::vector<double> m(8, 0.25);
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? 0.2 : -0.2, i & 2 ? 0.1 : -0.1, i & 4 ? 0.05 : -0.05);
  for (Vec3& x : p) x += Vec3(1.0, 2.0, 3.0);  // re-centred on the centre of mass
  const core::MassProperties mp = core::pointMassProperties(m, p);
  EXPECT_DOUBLE_EQ(mp.mass, 2.0);
  EXPECT_LT((mp.p_FC - Vec3(1, 2, 3)).norm(), 1e-15);
  const Mat3 expected = Vec3(2.0 * (0.01 + 0.0025), 2.0 * (0.04 + 0.0025), 2.0 * (0.04 + 0.01)).asDiagonal();
  EXPECT_LT((mp.I_C_F - expected).norm(), 1e-15);
}

TEST(PointMasses, ParallelAxisMatchesTheSumAboutAnotherPoint) {
  const std::vector<double> m{1.0, 2.0, 0.5};
  const std::vector<Vec3> p{Vec3(0.1, 0, 0), Vec3(0, 0.3, -0.1), Vec3(0.2, 0.2, 0.2)};
  const core::MassProperties mp = core::pointMassProperties(m, p);
  const Vec3 o(0.5, -0.2, 0.1);
  Mat3 about_o = Mat3::Zero();
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Vec3 r = p[i] - o;
    about_o += m[i] * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }
  EXPECT_LT((core::parallelAxis(mp.I_C_F, mp.mass, mp.p_FC - o) - about_o).norm(), 1e-14);
}

TEST(Combine, TwoBoxesMatchTheParallelAxisClosedForm) {
  // Two 1 kg cubes of side 0.2 m centred at x = 0 and x = 0.2: a 0.4 × 0.2 × 0.2 bar.
  const Mat3 cube = boxInertia(1.0, Vec3(0.1, 0.1, 0.1));
  const core::MassProperties total = core::combine({{1.0, Vec3(0, 0, 0), cube}, {1.0, Vec3(0.2, 0, 0), cube}});
  EXPECT_DOUBLE_EQ(total.mass, 2.0);
  EXPECT_LT((total.p_FC - Vec3(0.1, 0, 0)).norm(), 1e-16);
  EXPECT_LT((total.I_C_F - boxInertia(2.0, Vec3(0.2, 0.1, 0.1))).norm(), 1e-15);
}

TEST(Validate, AcceptsPhysicalTensorsIncludingAThinPlate) {
  EXPECT_NO_THROW(core::validateInertia(boxInertia(1.0, Vec3(0.2, 0.1, 0.05)), "inertia"));
  EXPECT_NO_THROW(core::validateInertia(Vec3(1.0, 2.0, 3.0).asDiagonal(), "inertia"));  // Izz = Ixx + Iyy
  EXPECT_NO_THROW(core::validateInertia(Mat3::Zero(), "inertia", /*allow_zero=*/true));
}

TEST(Validate, RefusesWithTheFieldAndTheValue) {
  Mat3 nan = Mat3::Identity();
  nan(1, 1) = std::nan("");
  expectThrowsWith<std::invalid_argument>([&] { core::validateInertia(nan, "inertia"); },
                                          {"inertia = (ixx=1, iyy=nan", "must be finite"});
  Mat3 asym = Mat3::Identity();
  asym(0, 1) = 0.1;
  expectThrowsWith<std::invalid_argument>([&] { core::validateInertia(asym, "inertia"); },
                                          {"ixy=0.1", "must be symmetric"});
  expectThrowsWith<std::invalid_argument>([&] { core::validateInertia(Vec3(1.0, -1.0, 1.0).asDiagonal(), "inertia"); },
                                          {"iyy=-1", "must be positive definite"});
  expectThrowsWith<std::invalid_argument>([&] { core::validateInertia(Mat3::Zero(), "inertia"); },
                                          {"must be positive definite"});
  expectThrowsWith<std::invalid_argument>([&] { core::validateInertia(Vec3(1.0, 1.0, 3.0).asDiagonal(), "inertia"); },
                                          {"izz=3", "triangle inequality", "1 + 1 < 3"});
}

TEST(NearestValidInertia, AValidTensorComesBackBitForBit) {
  const Quat q(Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.3).normalized()));
  const Mat3 R = q.toRotationMatrix();
  for (const Mat3& I : {Mat3(boxInertia(2.0, Vec3(0.3, 0.1, 0.05))),
                        Mat3(R * Vec3(1.0, 2.0, 3.0).asDiagonal() * R.transpose()), Mat3(Mat3::Zero())}) {
    const core::InertiaRepair fix = core::nearestValidInertia(I, "inertia");
    EXPECT_FALSE(fix.changed);
    EXPECT_EQ(fix.change, 0.0);
    EXPECT_TRUE((fix.I.array() == I.array()).all());
  }
}

TEST(NearestValidInertia, CadRoundingIsProjectedOntoTheTriangleInequality) {
  // PR2's sensor_mount_link: 0.001 + 0.001 < 0.01. One face is active, so the
  // repair is m − (a·m / |a|²) a with a = (1, 1, −1): a·m = −0.008, and the
  // moments become (0.011, 0.011, 0.022) / 3, a change of 0.008 / √3.
  const core::InertiaRepair fix = core::nearestValidInertia(Vec3(0.001, 0.001, 0.01).asDiagonal(), "inertia");
  ASSERT_TRUE(fix.changed);
  EXPECT_LT((fix.repaired - Vec3(0.011, 0.011, 0.022) / 3.0).norm(), 1e-17);
  EXPECT_LT((fix.I - Mat3((Vec3(0.011, 0.011, 0.022) / 3.0).asDiagonal())).norm(), 1e-17);
  EXPECT_NEAR(fix.change, 0.008 / std::sqrt(3.0), 1e-17);
  EXPECT_NO_THROW(core::validateInertia(fix.I, "repaired"));
  // Turned: the same moments on turned axes, so the repair turns with them.
  const Mat3 R = Quat(Eigen::AngleAxisd(0.9, Vec3(0.2, 1, -0.4).normalized())).toRotationMatrix();
  const core::InertiaRepair turned =
      core::nearestValidInertia(R * Vec3(0.001, 0.001, 0.01).asDiagonal() * R.transpose(), "inertia");
  EXPECT_LT((turned.I - R * fix.I * R.transpose()).norm(), 1e-15);
  EXPECT_NEAR(turned.change, fix.change, 1e-15);
}

TEST(NearestValidInertia, ASlightlyNegativeMomentMeetsTwoFaces) {
  // (−3.5e-8, 1e-4, 1e-4) breaks m₁ + m₂ ≥ m₃ and m₁ + m₃ ≥ m₂: the nearest
  // point of the cone lies on both faces, the line (0, t, t), at t = 1e-4: a
  // thin rod along the first axis, 3.5e-8 kg·m² away.
  const core::InertiaRepair fix = core::nearestValidInertia(Vec3(-3.5e-8, 1e-4, 1e-4).asDiagonal(), "inertia");
  ASSERT_TRUE(fix.changed);
  EXPECT_LT((fix.repaired - Vec3(0.0, 1e-4, 1e-4)).norm(), 1e-19);
  EXPECT_NEAR(fix.change, 3.5e-8, 1e-19);
  EXPECT_NO_THROW(core::validateInertia(fix.I, "repaired", /*allow_zero=*/true));
}

TEST(NearestValidInertia, NoValidTensorIsNearer) {
  // The projection's defining property, against 20,000 valid tensors drawn
  // at random around each invalid one: none is nearer than the repair.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto turn = [&] {
    return Quat(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
  };
  for (const Vec3& bad : {Vec3(1.0, 1.0, 3.0), Vec3(-0.2, 1.0, 1.1), Vec3(-0.5, -0.1, 2.0), Vec3(0.1, 0.2, 0.9)}) {
    const Mat3 R = turn();
    const Mat3 I = R * bad.asDiagonal() * R.transpose();
    const core::InertiaRepair fix = core::nearestValidInertia(I, "inertia");
    EXPECT_NO_THROW(core::validateInertia(fix.I, "repaired", /*allow_zero=*/true));
    EXPECT_NEAR((fix.I - I).norm(), fix.change, 1e-14);
    for (int k = 0; k < 20000; ++k) {
      // Valid moments: a + b ≥ c for any a, b ≥ 0 and c in [|a − b|, a + b].
      const double a = 2.0 * std::abs(u(rng)), b = 2.0 * std::abs(u(rng));
      const double c = std::abs(a - b) + (a + b - std::abs(a - b)) * 0.5 * (1.0 + u(rng));
      const Mat3 Q = k % 2 == 0 ? R : turn();  // half on the input's own axes
      const Mat3 valid = Q * Vec3(a, b, c).asDiagonal() * Q.transpose();
      ASSERT_GE((valid - I).norm(), fix.change - 1e-12) << "a valid tensor nearer than the repair";
    }
  }
}

TEST(NearestValidInertia, RefusesANonFiniteTensorNamingTheField) {
  Mat3 I = Mat3::Identity();
  I(2, 2) = std::numeric_limits<double>::infinity();
  expectThrowsWith<std::invalid_argument>([&] { core::nearestValidInertia(I, "link 'a' <inertia>"); },
                                          {"link 'a' <inertia>", "must be finite"});
}

TEST(WaterSphere, IsASolidSphereOfWaterOfTheMass) {
  // 1 kg of water is a sphere of r = (3 / 4000π)^(1/3) = 0.0620350 m; I = 2/5 m r².
  const double r = std::cbrt(3.0 / (4000.0 * M_PI));
  EXPECT_NEAR(r, 0.0620350, 1e-7);
  EXPECT_NEAR(core::waterSphereInertia(1.0)(1, 1), 0.4 * r * r, 1e-18);
  EXPECT_EQ(core::waterSphereInertia(1.0)(0, 1), 0.0);
  EXPECT_TRUE(core::pointMass(1.3, Mat3::Zero()));
  EXPECT_TRUE(core::pointMass(1.3, Mat3::Identity() * 2.4e-35));
  EXPECT_FALSE(core::pointMass(1.3, Mat3::Identity() * 1e-6));
  EXPECT_FALSE(core::pointMass(0.0, Mat3::Zero()));
}

TEST(PrincipalAxes, DiagonalStaysExactlyIdentity) {
  const core::PrincipalAxes pa = core::principalAxes(Vec3(0.1, 0.3, 0.2).asDiagonal());
  EXPECT_EQ(pa.q_FP.coeffs(), Quat::Identity().coeffs());
  EXPECT_EQ(pa.moments, Vec3(0.1, 0.3, 0.2));
}

TEST(PrincipalAxes, RecoverARotatedTensor) {
  const Quat q(Eigen::AngleAxisd(1.1, Vec3(-1, 2, 0.5).normalized()));
  const Mat3 R = q.toRotationMatrix();
  const Mat3 I = R * Vec3(0.1, 0.3, 0.25).asDiagonal() * R.transpose();
  const core::PrincipalAxes pa = core::principalAxes(I);
  const Mat3 P = pa.q_FP.toRotationMatrix();
  EXPECT_NEAR(P.determinant(), 1.0, 1e-14);
  EXPECT_LT((P * pa.moments.asDiagonal() * P.transpose() - I).norm(), 1e-14);
}

}  // namespace
}  // namespace rigid_body_sim::test
