// The IMU (docs/physics.md §10.1).
#include "rigid_body_sim/core/devices/imu.h"

#include <cmath>

#include "bodies/validate.h"
#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::core {
namespace {

/// The rotation vector of a unit quaternion (its axis times its angle, the
/// shorter way round).
Vec3 logMap(Quat q) {
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const double s = q.vec().norm();
  if (s < 1e-12) return 2.0 * q.vec();  // sin(θ/2) ≈ θ/2
  return (2.0 * std::atan2(s, q.w()) / s) * q.vec();
}

/// The unit quaternion of rotation vector r.
Quat expMap(const Vec3& r) {
  const double angle = r.norm();
  if (angle < 1e-12) return Quat(1.0, 0.5 * r.x(), 0.5 * r.y(), 0.5 * r.z()).normalized();
  return Quat(Eigen::AngleAxisd(angle, r / angle));
}

}  // namespace

void validateImu(const ImuSettings& s, double dt, const std::string& key) {
  // A sample every step at most, and one every 100 s at least (ranges::kMinRate).
  detail::requireWithin(s.rate, ranges::kMinRate, 1.0 / dt, key + ".rate",
                        "Hz (at most one sample a step, 1/dt; at least one every 100 s)");
  detail::requireWithin(s.gyro_noise, 0.0, 1e3, key + ".gyro_noise", "rad/s");
  detail::requireWithin(s.accel_noise, 0.0, 1e4, key + ".accel_noise", "m/s^2");
  detail::requireWithin(s.gyro_bias_walk, 0.0, 1e3, key + ".gyro_bias_walk", "rad/s/sqrt(s)");
  detail::requireWithin(s.accel_bias_walk, 0.0, 1e4, key + ".accel_bias_walk", "m/s^2/sqrt(s)");
  detail::requireWithin(s.orientation_noise, 0.0, M_PI, key + ".orientation_noise", "rad");
  detail::requireFinite(s.X_LS.translation, key + ".pose.position");
  if (s.X_LS.translation.norm() > ranges::kMaxExtent) {
    detail::fail(key + ".pose.position", detail::str(s.X_LS.translation),
                 "is more than " + detail::str(ranges::kMaxExtent) + " m from the link frame");
  }
}

ImuReading exactImuReading(const LinkState& previous, const LinkState& now, const Pose& X_LS, const Vec3& gravity_W,
                           double period) {
  const auto at = [&](const LinkState& link) {
    const LinkState sensor = frameState(link, X_LS);
    return std::make_pair(sensor.q_WL, sensor.v_WL);
  };
  const auto [q0, v0] = at(previous);
  const auto [q1, v1] = at(now);
  ImuReading r;
  r.q_WS = q1;
  r.w_S = logMap(q0.conjugate() * q1) / period;
  const Quat q_mid = q0.slerp(0.5, q1);
  r.f_S = q_mid.conjugate() * ((v1 - v0) / period - gravity_W);
  return r;
}

ImuReading exactImuReading(const BodyModel& body, const BodyState& previous, const BodyState& now, const Pose& X_LS,
                           const Vec3& gravity_W, double period) {
  return exactImuReading(linkState(body, previous), linkState(body, now), X_LS, gravity_W, period);
}

Imu::Imu(const ImuSettings& settings, const LinkState& now)
    : settings_(settings), previous_(now), rng_(settings.seed) {}

Vec3 Imu::gaussian(double sigma) {
  if (sigma == 0.0) return Vec3::Zero();
  const double x = normal_(rng_), y = normal_(rng_), z = normal_(rng_);
  return sigma * Vec3(x, y, z);
}

ImuReading Imu::sample(const LinkState& now, const Vec3& gravity_W, double period) {
  ImuReading r = exactImuReading(previous_, now, settings_.X_LS, gravity_W, period);
  previous_ = now;
  // The biases walk first, then each axis gets its white noise: after k
  // samples Var(bias) = σ_b² k period = σ_b² t.
  gyro_bias_ += gaussian(settings_.gyro_bias_walk * std::sqrt(period));
  accel_bias_ += gaussian(settings_.accel_bias_walk * std::sqrt(period));
  r.w_S += gyro_bias_ + gaussian(settings_.gyro_noise);
  r.f_S += accel_bias_ + gaussian(settings_.accel_noise);
  if (settings_.orientation_noise > 0.0) r.q_WS = (r.q_WS * expMap(gaussian(settings_.orientation_noise))).normalized();
  return r;
}

}  // namespace rigid_body_sim::core
