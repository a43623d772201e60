// Noisy odometry (docs/physics.md §10.2).
#include "rigid_body_sim/core/devices/odom_noise.h"

#include <cmath>

#include "bodies/validate.h"

namespace rigid_body_sim::core {

void validateOdomNoise(const OdomNoiseSettings& s, const std::string& key) {
  detail::requireWithin(s.position, 0.0, 1e3, key + ".position", "m");
  detail::requireWithin(s.orientation, 0.0, M_PI, key + ".orientation", "rad");
  detail::requireWithin(s.linear_velocity, 0.0, 1e3, key + ".linear_velocity", "m/s");
  detail::requireWithin(s.angular_velocity, 0.0, 1e3, key + ".angular_velocity", "rad/s");
  detail::requireWithin(s.drift_x, 0.0, 1e3, key + ".drift.x", "m/sqrt(s)");
  detail::requireWithin(s.drift_y, 0.0, 1e3, key + ".drift.y", "m/sqrt(s)");
  detail::requireWithin(s.drift_yaw, 0.0, M_PI, key + ".drift.yaw", "rad/sqrt(s)");
}

OdomReport exactOdom(const LinkState& link) {
  OdomReport r;
  r.p_WL = link.p_WL;
  r.q_WL = link.q_WL;
  const Quat q_LW = link.q_WL.conjugate();
  r.v_L = q_LW * link.v_WL;
  r.w_L = q_LW * link.w_W;
  return r;
}

double OdomNoise::gaussian(double sigma) { return sigma == 0.0 ? 0.0 : sigma * normal_(rng_); }

OdomReport OdomNoise::report(const LinkState& link, double elapsed) {
  const OdomNoiseSettings& s = settings_;
  const double root = std::sqrt(elapsed);
  drift_ += Vec3(gaussian(s.drift_x * root), gaussian(s.drift_y * root), gaussian(s.drift_yaw * root));
  drift_time_ += elapsed;
  OdomReport r = exactOdom(link);
  // The drift: an offset of x and y and a turn about the world z of the
  // orientation; then white noise on every component.
  r.p_WL += Vec3(drift_.x(), drift_.y(), 0.0);
  r.q_WL = Quat(Eigen::AngleAxisd(drift_.z(), Vec3::UnitZ())) * r.q_WL;
  const double px = gaussian(s.position), py = gaussian(s.position), pz = gaussian(s.position);
  r.p_WL += Vec3(px, py, pz);
  const Vec3 tilt(gaussian(s.orientation), gaussian(s.orientation), gaussian(s.orientation));
  const double angle = tilt.norm();
  if (angle > 0.0) r.q_WL = (r.q_WL * Quat(Eigen::AngleAxisd(angle, tilt / angle))).normalized();
  const double vx = gaussian(s.linear_velocity), vy = gaussian(s.linear_velocity), vz = gaussian(s.linear_velocity);
  r.v_L += Vec3(vx, vy, vz);
  const double wx = gaussian(s.angular_velocity), wy = gaussian(s.angular_velocity), wz = gaussian(s.angular_velocity);
  r.w_L += Vec3(wx, wy, wz);
  const double p2 = s.position * s.position, o2 = s.orientation * s.orientation;
  r.pose_variance = {p2 + s.drift_x * s.drift_x * drift_time_,    p2 + s.drift_y * s.drift_y * drift_time_, p2, o2, o2,
                     o2 + s.drift_yaw * s.drift_yaw * drift_time_};
  const double v2 = s.linear_velocity * s.linear_velocity, w2 = s.angular_velocity * s.angular_velocity;
  r.twist_variance = {v2, v2, v2, w2, w2, w2};
  return r;
}

}  // namespace rigid_body_sim::core
