// The IMU (docs/physics.md §10.1) against closed forms, on bodies the step
// moves: at rest it reads +g up turned by its mount, in free fall nothing,
// spinning the centripetal −ω² r, pushed by F on frictionless ground F/m and
// g, an impulse as its mean over the sample; its noise has the configured statistics, its biases walk as σ_b² t.
#include "rigid_body_sim/core/devices/imu.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

const Vec3 kHalf(0.2, 0.1, 0.05);
constexpr double kG = 9.81;

core::ImuSettings mountedAt(const Vec3& p_LS, const Quat& q_LS = Quat::Identity()) {
  core::ImuSettings s;
  s.X_LS = {q_LS, p_LS};
  return s;
}

/// Steps `model` from `s` for `seconds`, sampling `imu` at its rate; the last reading.
core::ImuReading run(const core::Model& model, core::State& s, core::Imu& imu, double seconds,
                     const core::Loads& loads = {}) {
  const int every = static_cast<int>(std::lround(1.0 / (imu.settings().rate * model.dt())));
  const int steps = static_cast<int>(std::lround(seconds / model.dt()));
  core::ImuReading last;
  for (int n = 1; n <= steps; ++n) {
    core::step(model, s, loads);
    if (n % every == 0) last = imu.sample(model.body(0), s.bodies[0], model.gravity(), every * model.dt());
  }
  return last;
}

TEST(Imu, AtRestItReadsGUpTurnedByItsMount) {
  const core::Model model(onGround(boxBody(kHalf), impulse(0.0, 0.5)));
  core::LinkState link;
  link.p_WL = Vec3(0, 0, kHalf.z());
  link.q_WL = Quat(Eigen::AngleAxisd(0.7, Vec3::UnitZ()));  // turned on the ground: no change of "up"
  core::State s = stateOf(model, link);
  const Quat q_LS(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()));
  core::Imu imu(mountedAt(Vec3(0.1, -0.05, 0.05), q_LS), core::linkState(model.body(0), s.bodies[0]));
  const core::ImuReading r = run(model, s, imu, 2.0);
  const Vec3 expected = (link.q_WL * q_LS).conjugate() * Vec3(0, 0, kG);
  EXPECT_LT((r.f_S - expected).norm(), 1e-6 * kG) << r.f_S.transpose();
  EXPECT_LT(r.w_S.norm(), 1e-9);
  EXPECT_LT(r.q_WS.angularDistance(link.q_WL * q_LS), 1e-6);
}

TEST(Imu, InFreeFallItReadsNothing) {
  const core::Model model(spec(boxBody(kHalf), 1e-3, Vec3(0, 0, -kG)));
  core::LinkState link;
  link.v_WL = Vec3(1, 0, 3);
  core::State s = stateOf(model, link);
  core::Imu imu(mountedAt(Vec3(0.2, 0, 0)), core::linkState(model.body(0), s.bodies[0]));
  const core::ImuReading r = run(model, s, imu, 0.5);
  EXPECT_LT(r.f_S.norm(), 1e-9) << r.f_S.transpose();
}

TEST(Imu, SpinningAboutZItReadsTheCentripetalAcceleration) {
  // A ball spinning at ω about z, the IMU at r = 0.2 m along x of the link:
  // it reads −ω² r along its x, and ω about its z (the sample's mean over
  // 10 ms differs from the instant's by (ω T)² / 24 = 4e-5 of it).
  const double w = 3.0, r = 0.2;
  const core::Model model(spec(ballBody(0.1), 1e-3, Vec3::Zero()));
  core::LinkState link;
  link.w_W = Vec3(0, 0, w);
  core::State s = stateOf(model, link);
  core::Imu imu(mountedAt(Vec3(r, 0, 0)), core::linkState(model.body(0), s.bodies[0]));
  const core::ImuReading reading = run(model, s, imu, 1.0);
  EXPECT_NEAR(reading.f_S.x(), -w * w * r, 1e-4 * w * w * r);
  EXPECT_NEAR(reading.f_S.y(), 0.0, 1e-9);
  // The step turns by 2 atan(ω Δt / 2) a step (physics §5.7), (ω Δt)² / 12 short of ω Δt: the IMU reads that.
  EXPECT_NEAR(reading.w_S.z(), 2.0 * std::atan(0.5 * w * model.dt()) / model.dt(), 1e-12);
  EXPECT_NEAR(reading.w_S.head<2>().norm(), 0.0, 1e-9);
}

TEST(Imu, PushedOnFrictionlessGroundItReadsForceOverMassAndG) {
  const core::Model model(onGround(boxBody(kHalf, 2.0), impulse(0.0, 0.0)));
  core::LinkState link;
  link.p_WL = Vec3(0, 0, kHalf.z());
  core::State s = stateOf(model, link);
  core::Loads loads(1);
  loads[0].force_W = Vec3(3.0, 1.0, 0.0);  // 2 kg
  core::Imu imu(mountedAt(Vec3::Zero()), core::linkState(model.body(0), s.bodies[0]));
  run(model, s, imu, 0.5, loads);  // settled on the ground, sliding
  const core::ImuReading r = run(model, s, imu, 0.1, loads);
  EXPECT_NEAR(r.f_S.x(), 1.5, 1e-6);
  EXPECT_NEAR(r.f_S.y(), 0.5, 1e-6);
  EXPECT_NEAR(r.f_S.z(), kG, 1e-6);
}

TEST(Imu, AnImpulseReadsAsItsMeanAccelerationOverTheSample) {
  // 0.5 N·s on 2 kg between two samples of 10 ms: the next sample reads the
  // velocity change 0.25 m/s over 10 ms, 25 m/s², then nothing again.
  const core::Model model(spec(boxBody(kHalf, 2.0), 1e-3, Vec3::Zero()));
  core::State s = stateOf(model, core::LinkState{});
  core::Imu imu(mountedAt(Vec3::Zero()), core::linkState(model.body(0), s.bodies[0]));
  run(model, s, imu, 0.05);
  core::applyImpulse(model.body(0), s.bodies[0], core::Impulse{Vec3(0.5, 0, 0), Vec3::Zero(), Vec3::Zero()});
  EXPECT_NEAR(run(model, s, imu, 0.01).f_S.x(), 25.0, 1e-9);
  EXPECT_NEAR(run(model, s, imu, 0.01).f_S.x(), 0.0, 1e-9);
}

TEST(Imu, ItsWhiteNoiseHasTheConfiguredMeanAndSigma) {
  const core::Model model(spec(boxBody(kHalf), 1e-3, Vec3(0, 0, -kG)));
  const core::State s = stateOf(model, core::LinkState{});
  core::ImuSettings settings = mountedAt(Vec3::Zero());
  settings.gyro_noise = 0.01;
  settings.accel_noise = 0.2;
  settings.orientation_noise = 0.03;
  settings.seed = 7;
  core::Imu imu(settings, core::linkState(model.body(0), s.bodies[0]));
  const int n = 100000;
  std::vector<std::vector<double>> gyro(3), accel(3), tilt(3);
  for (int k = 0; k < n; ++k) {
    // The body does not move between samples: the exact reading is (0, 0, g), no rotation.
    const core::ImuReading r = imu.sample(model.body(0), s.bodies[0], model.gravity(), 0.01);
    ASSERT_NEAR(r.q_WS.norm(), 1.0, 1e-15);
    const Eigen::AngleAxisd aa(r.q_WS);
    const Vec3 rotation = aa.angle() * aa.axis();
    for (int i = 0; i < 3; ++i) {
      gyro[i].push_back(r.w_S[i]);
      accel[i].push_back(r.f_S[i] - (i == 2 ? kG : 0.0));
      tilt[i].push_back(rotation[i]);
    }
  }
  for (int i = 0; i < 3; ++i) {
    const auto [gm, gs] = meanAndSigma(gyro[i]);
    const auto [am, as] = meanAndSigma(accel[i]);
    const auto [tm, ts] = meanAndSigma(tilt[i]);
    EXPECT_LT(std::abs(gm), 0.02 * settings.gyro_noise) << i;
    EXPECT_NEAR(gs, settings.gyro_noise, 0.02 * settings.gyro_noise) << i;
    EXPECT_LT(std::abs(am), 0.02 * settings.accel_noise) << i;
    EXPECT_NEAR(as, settings.accel_noise, 0.02 * settings.accel_noise) << i;
    EXPECT_LT(std::abs(tm), 0.02 * settings.orientation_noise) << i;
    EXPECT_NEAR(ts, settings.orientation_noise, 0.02 * settings.orientation_noise) << i;
  }
}

TEST(Imu, ItsBiasVarianceGrowsAsSigmaSquaredTimesTime) {
  // 2000 IMUs with their own seeds, 100 samples of 10 ms: at t = 1 s and
  // t = 0.25 s each bias axis has variance σ_b² t (sampling error √(2/2000) = 3%).
  const core::Model model(spec(boxBody(kHalf), 1e-3, Vec3(0, 0, -kG)));
  const core::State s = stateOf(model, core::LinkState{});
  const double sigma_g = 0.002, sigma_a = 0.05;
  std::vector<double> gyro_quarter, gyro_one, accel_one;
  for (int seed = 0; seed < 2000; ++seed) {
    core::ImuSettings settings = mountedAt(Vec3::Zero());
    settings.gyro_bias_walk = sigma_g;
    settings.accel_bias_walk = sigma_a;
    settings.seed = static_cast<std::uint64_t>(seed);
    core::Imu imu(settings, core::linkState(model.body(0), s.bodies[0]));
    for (int k = 1; k <= 100; ++k) {
      imu.sample(model.body(0), s.bodies[0], model.gravity(), 0.01);
      if (k == 25) gyro_quarter.push_back(imu.gyroBias().x());
    }
    gyro_one.push_back(imu.gyroBias().y());
    accel_one.push_back(imu.accelBias().z());
  }
  const double var_q = std::pow(meanAndSigma(gyro_quarter).second, 2),
               var_g = std::pow(meanAndSigma(gyro_one).second, 2), var_a = std::pow(meanAndSigma(accel_one).second, 2);
  EXPECT_NEAR(var_q, sigma_g * sigma_g * 0.25, 0.1 * sigma_g * sigma_g * 0.25);
  EXPECT_NEAR(var_g, sigma_g * sigma_g * 1.0, 0.1 * sigma_g * sigma_g);
  EXPECT_NEAR(var_a, sigma_a * sigma_a * 1.0, 0.1 * sigma_a * sigma_a);
}

TEST(Imu, TheSameSeedGivesTheSameReadingsBitForBit) {
  const core::Model model(spec(boxBody(kHalf), 1e-3, Vec3(0, 0, -kG)));
  const core::State s = stateOf(model, core::LinkState{});
  core::ImuSettings settings = mountedAt(Vec3(0.1, 0, 0));
  settings.gyro_noise = settings.accel_noise = settings.orientation_noise = 0.1;
  settings.gyro_bias_walk = settings.accel_bias_walk = 0.1;
  settings.seed = 3;
  const core::LinkState start = core::linkState(model.body(0), s.bodies[0]);
  core::Imu a(settings, start), b(settings, start);
  settings.seed = 4;
  core::Imu c(settings, start);
  for (int k = 0; k < 100; ++k) {
    const core::ImuReading ra = a.sample(model.body(0), s.bodies[0], model.gravity(), 0.01);
    const core::ImuReading rb = b.sample(model.body(0), s.bodies[0], model.gravity(), 0.01);
    const core::ImuReading rc = c.sample(model.body(0), s.bodies[0], model.gravity(), 0.01);
    ASSERT_EQ(std::memcmp(ra.f_S.data(), rb.f_S.data(), sizeof(double) * 3), 0);
    ASSERT_EQ(std::memcmp(ra.q_WS.coeffs().data(), rb.q_WS.coeffs().data(), sizeof(double) * 4), 0);
    ASSERT_NE(ra.f_S, rc.f_S);
  }
}

TEST(Imu, BadSettingsAreRefusedNamingTheKey) {
  core::ImuSettings s;
  s.rate = 0.0;
  expectThrowsWith<std::invalid_argument>([&] { core::validateImu(s, 1e-3, "imu"); }, {"imu.rate = 0"});
  s.rate = 2000.0;
  expectThrowsWith<std::invalid_argument>([&] { core::validateImu(s, 1e-3, "imu"); }, {"imu.rate = 2000"});
  // Slower than a sample every 100 s: 1e-300 Hz overflowed the node's
  // step counter and sampled at every step.
  s.rate = 1e-300;
  expectThrowsWith<std::invalid_argument>([&] { core::validateImu(s, 1e-3, "imu"); }, {"imu.rate = 1e-300"});
  s.rate = 0.009;
  expectThrowsWith<std::invalid_argument>([&] { core::validateImu(s, 1e-3, "imu"); }, {"imu.rate = 0.009"});
  s.rate = 0.01;
  EXPECT_NO_THROW(core::validateImu(s, 1e-3, "imu"));
  s = {};
  s.gyro_noise = -1.0;
  expectThrowsWith<std::invalid_argument>([&] { core::validateImu(s, 1e-3, "bodies[1].imu"); },
                                          {"bodies[1].imu.gyro_noise = -1"});
  s = {};
  s.accel_bias_walk = std::nan("");
  expectThrowsWith<std::invalid_argument>([&] { core::validateImu(s, 1e-3, "imu"); }, {"imu.accel_bias_walk = nan"});
}

}  // namespace
}  // namespace rigid_body_sim::test
