// A free body's sensors (docs/physics.md §10.1–10.2): its IMU, sampled at
// its rate of sim time on the world's step count, and its noisy odometry,
// reported at the odometry's publish period of steps (and at the start),
// with the exact state beside it. One body's set is one object, as a
// robot's link sensors are (link_sensors.h): the node turns its samples
// into messages, rbsim into rows of a file, and both get the same numbers.
// ROS-free.
#pragma once

#include <memory>
#include <optional>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/devices/imu.h"
#include "rigid_body_sim/core/devices/odom_noise.h"

namespace rigid_body_sim::core {

class BodySensors {
 public:
  /// Steps of `dt` s.
  explicit BodySensors(double dt) : dt_(dt) {}

  /// An IMU at settings.X_LS in the body's root link frame, settings.rate
  /// Hz rounded to whole steps (at least one).
  void addImu(const ImuSettings& settings);
  /// Noise on the body's odometry (config odom_noise).
  void addOdometryNoise(const OdomNoiseSettings& settings);
  /// The body enters the world at `now`, sim time t: the IMU's first
  /// period starts there, and the odometry's drift.
  void start(const BodyModel& body, const BodyState& now, double t);

  /// After the world's step `steps` (1 the first) left the body at `state`:
  /// the IMU samples if due, and imuFresh() says so.
  void sample(const BodyModel& body, const BodyState& state, const Vec3& gravity_W, long long steps);
  /// The noisy report of the body's root link `link` at sim time t, its
  /// drift walked for the time since the last report (a std::logic_error
  /// without noise). Called at each of the odometry's publish times.
  OdomReport report(const LinkState& link, double t);

  /// The body was put somewhere (set_state): the IMU's next period starts at `now`.
  void restart(const BodyModel& body, const BodyState& now);
  /// A reset: the IMU's period, and the odometry's drift from zero.
  void restartAll(const BodyModel& body, const BodyState& now);

  const Imu* imu() const { return imu_.get(); }
  long long imuEvery() const { return imu_every_; }
  bool imuFresh() const { return imu_fresh_; }
  const ImuReading& imuReading() const { return imu_reading_; }
  bool noisy() const { return noise_ != nullptr; }
  bool empty() const { return !imu_ && !noise_; }

 private:
  double dt_;
  // Held apart: a random generator is 2.5 KB, and most bodies have none.
  std::unique_ptr<Imu> imu_;
  long long imu_every_ = 1;  ///< steps per IMU sample
  bool imu_fresh_ = false;
  ImuReading imu_reading_;
  std::unique_ptr<OdomNoise> noise_;
  double last_report_ = 0.0;  ///< s of sim time of the last report (the drift's)
};

}  // namespace rigid_body_sim::core
