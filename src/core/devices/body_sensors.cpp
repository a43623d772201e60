// A free body's sensors: body_sensors.h.
#include "rigid_body_sim/core/devices/body_sensors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rigid_body_sim::core {

void BodySensors::addImu(const ImuSettings& settings) {
  imu_ = std::make_unique<Imu>(settings);
  imu_every_ = std::max(1LL, std::llround(1.0 / (settings.rate * dt_)));
}

void BodySensors::addOdometryNoise(const OdomNoiseSettings& settings) {
  noise_ = std::make_unique<OdomNoise>(settings);
}

void BodySensors::start(const BodyModel& body, const BodyState& now, double t) {
  restart(body, now);
  last_report_ = t;
}

void BodySensors::sample(const BodyModel& body, const BodyState& state, const Vec3& gravity_W, long long steps) {
  imu_fresh_ = imu_ && steps % imu_every_ == 0;
  if (imu_fresh_) imu_reading_ = imu_->sample(body, state, gravity_W, static_cast<double>(imu_every_) * dt_);
}

OdomReport BodySensors::report(const LinkState& link, double t) {
  if (!noise_) throw std::logic_error("BodySensors::report: the body's odometry has no noise");
  OdomReport r = noise_->report(link, t - last_report_);
  last_report_ = t;
  return r;
}

void BodySensors::restart(const BodyModel& body, const BodyState& now) {
  if (imu_) imu_->restart(linkState(body, now));
}

void BodySensors::restartAll(const BodyModel& body, const BodyState& now) {
  restart(body, now);
  if (noise_) noise_->restart();  // the drift starts again
}

}  // namespace rigid_body_sim::core
