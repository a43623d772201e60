#include "rigid_body_sim/core/inertia.h"

#include <gtest/gtest.h>

#include "../test_util.h"

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
