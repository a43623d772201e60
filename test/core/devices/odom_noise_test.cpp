// Noisy odometry (docs/physics.md §10.2): the difference between the noisy
// report and the exact state has the configured statistics, the drift's
// variance grows as σ² t and the reported covariances say so.
#include "rigid_body_sim/core/devices/odom_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../test_util.h"

namespace rigid_body_sim::test {
namespace {

core::LinkState moving() {
  core::LinkState link;
  link.p_WL = Vec3(1, -2, 0.5);
  link.q_WL = Quat(Eigen::AngleAxisd(0.8, Vec3(0.2, 0.3, 1).normalized()));
  link.v_WL = Vec3(0.5, 0.1, 0);
  link.w_W = Vec3(0, 0, 0.3);
  return link;
}

TEST(OdomNoise, WithoutNoiseItIsTheExactState) {
  const core::LinkState link = moving();
  core::OdomNoise none(core::OdomNoiseSettings{});
  const core::OdomReport r = none.report(link, 0.01);
  EXPECT_EQ(r.p_WL, link.p_WL);
  EXPECT_EQ(r.q_WL.coeffs(), link.q_WL.coeffs());
  EXPECT_LT((link.q_WL * r.v_L - link.v_WL).norm(), 1e-15);
  EXPECT_LT((link.q_WL * r.w_L - link.w_W).norm(), 1e-15);
  for (double v : r.pose_variance) EXPECT_EQ(v, 0.0);
}

TEST(OdomNoise, TheDifferenceFromTheTruthHasTheConfiguredSigmas) {
  core::OdomNoiseSettings s;
  s.position = 0.02;
  s.orientation = 0.01;
  s.linear_velocity = 0.05;
  s.angular_velocity = 0.03;
  s.seed = 11;
  core::OdomNoise noise(s);
  const core::LinkState link = moving();
  const core::OdomReport exact = core::exactOdom(link);
  std::vector<std::vector<double>> p(3), o(3), v(3), w(3);
  for (int k = 0; k < 100000; ++k) {
    const core::OdomReport r = noise.report(link, 0.01);
    ASSERT_NEAR(r.q_WL.norm(), 1.0, 1e-15);
    const Eigen::AngleAxisd aa(exact.q_WL.conjugate() * r.q_WL);
    const Vec3 tilt = aa.angle() * aa.axis();
    for (int i = 0; i < 3; ++i) {
      p[i].push_back(r.p_WL[i] - exact.p_WL[i]);
      o[i].push_back(tilt[i]);
      v[i].push_back(r.v_L[i] - exact.v_L[i]);
      w[i].push_back(r.w_L[i] - exact.w_L[i]);
    }
  }
  const auto check = [](const std::vector<double>& x, double sigma, const char* what) {
    const auto [mean, sd] = meanAndSigma(x);
    EXPECT_LT(std::abs(mean), 0.02 * sigma) << what;
    EXPECT_NEAR(sd, sigma, 0.02 * sigma) << what;
  };
  for (int i = 0; i < 3; ++i) {
    check(p[i], s.position, "position");
    check(o[i], s.orientation, "orientation");
    check(v[i], s.linear_velocity, "linear velocity");
    check(w[i], s.angular_velocity, "angular velocity");
  }
  const core::OdomReport r = noise.report(link, 0.01);
  EXPECT_EQ(r.pose_variance[0], s.position * s.position);
  EXPECT_EQ(r.pose_variance[5], s.orientation * s.orientation);
  EXPECT_EQ(r.twist_variance[0], s.linear_velocity * s.linear_velocity);
  EXPECT_EQ(r.twist_variance[5], s.angular_velocity * s.angular_velocity);
}

TEST(OdomNoise, TheDriftsVarianceGrowsAsSigmaSquaredTimesTimeAndTheCovarianceSaysSo) {
  // 2000 odometries with their own seeds, 100 reports 10 ms apart: at t = 1 s
  // the x, y and yaw offsets have variance σ² t (sampling error 3%).
  core::OdomNoiseSettings s;
  s.drift_x = 0.05;
  s.drift_y = 0.02;
  s.drift_yaw = 0.01;
  const core::LinkState link = moving();
  std::vector<double> x, y, yaw;
  core::OdomReport last;
  for (int seed = 0; seed < 2000; ++seed) {
    s.seed = static_cast<std::uint64_t>(seed);
    core::OdomNoise noise(s);
    for (int k = 0; k < 100; ++k) last = noise.report(link, 0.01);
    x.push_back(last.p_WL.x() - link.p_WL.x());
    y.push_back(last.p_WL.y() - link.p_WL.y());
    yaw.push_back(noise.drift().z());
    // The reported orientation is the truth turned by the yaw offset about the world z.
    const Quat turned = Quat(Eigen::AngleAxisd(noise.drift().z(), Vec3::UnitZ())) * link.q_WL;
    ASSERT_LT(turned.angularDistance(last.q_WL), 1e-12);
  }
  EXPECT_NEAR(std::pow(meanAndSigma(x).second, 2), s.drift_x * s.drift_x, 0.1 * s.drift_x * s.drift_x);
  EXPECT_NEAR(std::pow(meanAndSigma(y).second, 2), s.drift_y * s.drift_y, 0.1 * s.drift_y * s.drift_y);
  EXPECT_NEAR(std::pow(meanAndSigma(yaw).second, 2), s.drift_yaw * s.drift_yaw, 0.1 * s.drift_yaw * s.drift_yaw);
  EXPECT_NEAR(last.pose_variance[0], s.drift_x * s.drift_x * 1.0, 1e-15);
  EXPECT_NEAR(last.pose_variance[1], s.drift_y * s.drift_y * 1.0, 1e-15);
  EXPECT_NEAR(last.pose_variance[5], s.drift_yaw * s.drift_yaw * 1.0, 1e-15);
  EXPECT_EQ(last.pose_variance[2], 0.0);
}

TEST(OdomNoise, BadSettingsAreRefusedNamingTheKey) {
  core::OdomNoiseSettings s;
  s.position = -0.1;
  expectThrowsWith<std::invalid_argument>([&] { core::validateOdomNoise(s, "odom_noise"); },
                                          {"odom_noise.position = -0.1"});
  s = {};
  s.drift_yaw = std::nan("");
  expectThrowsWith<std::invalid_argument>([&] { core::validateOdomNoise(s, "bodies[2].odom_noise"); },
                                          {"bodies[2].odom_noise.drift.yaw = nan"});
}

}  // namespace
}  // namespace rigid_body_sim::test
