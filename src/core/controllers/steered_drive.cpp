// The steered mode of a wheeled base's controller (diff_drive.h): its
// steering joints checked, the efforts for a speed and a steering angle,
// and the odometry from its wheels and steering; docs/physics.md §11.14.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/controllers/diff_drive.h"

namespace rigid_body_sim::core {

namespace {

[[noreturn]] void fail(const DiffDriveSpec& s, const std::string& what) {
  throw std::invalid_argument("controller '" + s.name + "': " + what);
}

}  // namespace

void DiffDrive::checkSteering(const ArticulationModel& model, const ArticulationKinematics& rest) {
  const DiffDriveSpec& s = spec_;
  const SteeringSpec& st = *s.steering;
  const std::size_t joints = st.joints.size(), wheels = wheels_.size();
  if (joints == 0) fail(s, "a steered base needs a steering joint");
  if (st.joint_x.size() != joints || st.joint_y.size() != joints || st.joint_sign.size() != joints) {
    fail(s, "needs each steering joint's place and sign");
  }
  if (st.wheel_x.size() != wheels || st.wheel_y.size() != wheels || st.wheel_steer.size() != wheels) {
    fail(s, "needs each driven wheel's place and steering joint");
  }
  if (!(std::isfinite(st.wheelbase) && st.wheelbase > 0.0)) fail(s, "the wheelbase must be finite and > 0 m");
  if (!(st.steering_speed > 0.0)) fail(s, "the steering speed must be > 0 rad/s");
  if (!st.gains.empty() && st.gains.size() != joints) fail(s, "needs one set of PID gains per steering joint");
  for (std::size_t k = 0; k < joints; ++k) {
    const int j = st.joints[k];
    if (j < 1 || j >= static_cast<int>(model.links.size())) fail(s, "steering joint index " + std::to_string(j));
    const ArticulatedLink& link = model.links[j];
    if (link.mimic.joint >= 0) fail(s, "steering joint '" + link.joint + "' is a mimic joint");
    if (link.type != JointType::Revolute && link.type != JointType::Continuous) {
      fail(s, "steering joint '" + link.joint + "' does not turn (continuous or revolute)");
    }
    if (std::find(wheels_.begin(), wheels_.end(), j) != wheels_.end()) {
      fail(s, "steering joint '" + link.joint + "' is a driven wheel's too");
    }
    if (std::find(st.joints.begin(), st.joints.begin() + static_cast<long>(k), j) !=
        st.joints.begin() + static_cast<long>(k)) {
      fail(s, "steering joint '" + link.joint + "' twice");
    }
    if (!std::isfinite(st.joint_x[k]) || !std::isfinite(st.joint_y[k]) || std::abs(st.joint_sign[k]) != 1.0) {
      fail(s, "steering joint '" + link.joint + "': its place must be finite, its sign +1 or -1");
    }
    const PidGains g = st.gains.empty() ? defaultSteeringGains(model, j) : st.gains[k];
    if (!validGains(g)) fail(s, "steering PID gains p, i, d, i_clamp must be finite and >= 0");
    steer_pids_.emplace_back(g);
    steer_limits_.push_back(link.limits);
    steer_response_.push_back(jointResponse(model, rest, j));
  }
  for (std::size_t n = 0; n < wheels; ++n) {
    if (!std::isfinite(st.wheel_x[n]) || !std::isfinite(st.wheel_y[n]) || st.wheel_steer[n] < -1 ||
        st.wheel_steer[n] >= static_cast<int>(joints)) {
      fail(s, "driven wheel '" + model.links[wheels_[n]].joint + "': its place or steering joint");
    }
  }
}

double DiffDrive::heading(const ArticulationState& state, std::size_t k) const {
  const SteeringSpec& st = *spec_.steering;
  return st.joint_sign[k] * state.q(st.joints[k] - 1);
}

void DiffDrive::observeSteered(const ArticulationState& state, double dt) {
  // The steering joints allow one line of motions (v, ω); the wheels' rims
  // give how far along it: the least-squares λ of d_n = λ k_n, k_n the rim
  // speed of wheel n for the unit motion (§11.14).
  const SteeringSpec& st = *spec_.steering;
  if (travel_.size() != wheels_.size()) readTravel(state);
  PlanarMotion dir{0.0, 0.0};
  for (std::size_t k = 0; k < st.joints.size(); ++k) {
    const PlanarMotion d = allowedDirection(st.joint_x[k], st.joint_y[k], heading(state, k));
    dir.v += d.v;
    dir.w += d.w;
  }
  double along = 0.0, norm = 0.0;
  for (std::size_t n = 0; n < wheels_.size(); ++n) {
    const double rim = state.q(wheels_[n] - 1) * rimRadius(n);
    const double a = st.wheel_steer[n] >= 0 ? heading(state, static_cast<std::size_t>(st.wheel_steer[n])) : 0.0;
    const double k = rimSpeed(dir, st.wheel_x[n], st.wheel_y[n], a);
    along += (rim - travel_[n]) * k;
    norm += k * k;
    travel_[n] = rim;
  }
  const double lambda = norm > 0.0 ? along / norm : 0.0;
  integrate(lambda * dir.v, lambda * dir.w);
  if (dt > 0.0) average(lambda * dir.v / dt, lambda * dir.w / dt);
}

void DiffDrive::steeredEfforts(const ArticulationState& state, double v, double delta, double dt,
                               Eigen::VectorXd& effort) {
  constexpr double kSteerTime = 0.05;  // s: a steering joint turns toward its angle at error / this
  const SteeringSpec& st = *spec_.steering;
  delta = steerable(st, delta);
  for (std::size_t k = 0; k < st.joints.size(); ++k) {
    const JointLimits& lim = steer_limits_[k];
    const int j = st.joints[k];
    const double angle = st.joint_sign[k] * steerAngle(delta, st.wheelbase, st.joint_x[k], st.joint_y[k]);
    const double target = std::clamp(angle, lim.lower, lim.upper);
    const double fastest = std::min(lim.velocity, st.steering_speed);
    const double speed = std::clamp((target - state.q(j - 1)) / kSteerTime, -fastest, fastest);
    effort(j - 1) = steer_pids_[k].servo(speed - state.v(j - 1), dt, steer_response_[k], lim.effort);
  }
  // Each driven wheel rolls at its own path's speed for the motion asked
  // (no wheel scrubs), its heading the steering joint's now.
  PlanarMotion m = motionPerSpeed(st, delta);
  m.v *= v;
  m.w *= v;
  for (std::size_t n = 0; n < wheels_.size(); ++n) {
    const JointLimits& lim = limits_[n];
    const int j = wheels_[n];
    const double a = st.wheel_steer[n] >= 0 ? heading(state, static_cast<std::size_t>(st.wheel_steer[n])) : 0.0;
    const double target =
        std::clamp(rimSpeed(m, st.wheel_x[n], st.wheel_y[n], a) / rimRadius(n), -lim.velocity, lim.velocity);
    const double most = std::min(lim.effort, spec_.settings.max_wheel_torque);
    effort(j - 1) = pids_[n].servo(target - state.v(j - 1), dt, response_[n], most);
  }
}

}  // namespace rigid_body_sim::core
