// A wheeled base's controller: diff_drive.h, docs/physics.md §11.12 and §11.13.
#include "rigid_body_sim/core/controllers/diff_drive.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::core {

double TwistLimiter::limit(double v, double v0, double v1, double dt) const {
  if (has_jerk_limits) {  // the change of the change, over two steps
    const double dv = v - v0, dv0 = v0 - v1, dt2 = 2.0 * dt * dt;
    v = v0 + dv0 + std::clamp(dv - dv0, min_jerk * dt2, max_jerk * dt2);
  }
  if (has_acceleration_limits) v = v0 + std::clamp(v - v0, min_acceleration * dt, max_acceleration * dt);
  if (has_velocity_limits) v = std::clamp(v, min_velocity, max_velocity);
  return v;
}

PidGains servoGains(double inertia, double effort_limit) {
  constexpr double kTau = 0.02;  // s, both poles of the speed loop
  PidGains g;
  g.p = 2.0 * inertia / kTau;
  g.i = inertia / (kTau * kTau);
  g.d = 0.0;
  g.i_clamp = std::isfinite(effort_limit) ? effort_limit : 100.0 * g.p;
  return g;
}

PidGains defaultWheelGains(const ArticulationModel& model, int wheel, double wheel_radius, int wheels) {
  double robot_mass = 0.0;
  for (const ArticulatedLink& link : model.links) robot_mass += link.mass.mass;
  const ArticulatedLink& link = model.links.at(wheel);
  const Vec3 axis = link.axis_J.normalized();
  const double own = axis.dot(link.mass.I_C_F * axis);  // about its axle (through its centre of mass)
  return servoGains(own + robot_mass * wheel_radius * wheel_radius / std::max(wheels, 1), link.limits.effort);
}

namespace {

[[noreturn]] void fail(const DiffDriveSpec& s, const std::string& what) {
  throw std::invalid_argument("controller '" + s.name + "': " + what);
}

bool positive(double x) { return std::isfinite(x) && x > 0.0; }

/// Each limit pair finite and holding 0 between its bounds: a pair above or
/// below 0 would turn a zero command into a drive (ros_controllers would
/// clamp a stopped base to min_velocity > 0 and drive it off).
void checkLimits(const DiffDriveSpec& s, const TwistLimiter& l, const char* axis) {
  const auto pair = [&](bool on, double lo, double hi, const char* what) {
    if (on && !(std::isfinite(lo) && std::isfinite(hi) && lo <= 0.0 && 0.0 <= hi)) {
      fail(s, std::string(axis) + ": min_" + what + " and max_" + what + " must be finite, min <= 0 <= max");
    }
  };
  pair(l.has_velocity_limits, l.min_velocity, l.max_velocity, "velocity");
  pair(l.has_acceleration_limits, l.min_acceleration, l.max_acceleration, "acceleration");
  pair(l.has_jerk_limits, l.min_jerk, l.max_jerk, "jerk");
}

/// sin(a) / a, exact near 0.
double sinc(double a) { return std::abs(a) < 1e-4 ? 1.0 - a * a / 6.0 : std::sin(a) / a; }

}  // namespace

DiffDrive::DiffDrive(const ArticulationModel& model, DiffDriveSpec spec) : spec_(std::move(spec)) {
  const DiffDriveSpec& s = spec_;
  if (s.steering) {
    if (s.left.empty() || !s.right.empty()) fail(s, "a steered base's driven wheels are `left`, `right` empty");
  } else if (s.left.empty() || s.right.empty()) {
    fail(s, "needs left and right wheels");
  } else if (s.left.size() != s.right.size()) {
    fail(s, std::to_string(s.left.size()) + " left wheels and " + std::to_string(s.right.size()) +
                " right wheels: give as many on each side");
  }
  if (s.mecanum && s.left.size() != 2) fail(s, "a mecanum base has four wheels, a front and a back one a side");
  wheels_ = s.left;
  wheels_.insert(wheels_.end(), s.right.begin(), s.right.end());
  std::vector<int> seen;
  for (const int j : wheels_) {
    if (j < 1 || j >= static_cast<int>(model.links.size())) fail(s, "wheel joint index " + std::to_string(j));
    const ArticulatedLink& link = model.links[j];
    if (link.mimic.joint >= 0) fail(s, "wheel joint '" + link.joint + "' is a mimic joint");
    if (link.type != JointType::Revolute && link.type != JointType::Continuous) {
      fail(s, "wheel joint '" + link.joint + "' does not turn (a wheel's joint is continuous or revolute)");
    }
    if (std::find(seen.begin(), seen.end(), j) != seen.end()) fail(s, "wheel joint '" + link.joint + "' twice");
    seen.push_back(j);
    limits_.push_back(link.limits);
  }
  const ArticulationKinematics rest = kinematics(model, restState(model));
  for (const int j : wheels_) response_.push_back(jointResponse(model, rest, j));
  const DiffDriveSettings& k = s.settings;
  for (const auto& [value, what] : {std::pair<double, const char*>{s.wheel_separation, "wheel_separation"},
                                    {s.wheel_radius, "wheel_radius"},
                                    {k.wheel_separation_multiplier, "wheel_separation_multiplier"},
                                    {k.left_wheel_radius_multiplier, "left_wheel_radius_multiplier"},
                                    {k.right_wheel_radius_multiplier, "right_wheel_radius_multiplier"}}) {
    if (!positive(value)) fail(s, std::string(what) + " must be finite and > 0, got " + std::to_string(value));
  }
  if (!(k.cmd_vel_timeout >= 0.0)) fail(s, "cmd_vel_timeout must be >= 0 (infinite: held)");
  if (!(k.max_wheel_torque > 0.0)) fail(s, "max_wheel_torque must be > 0 N*m (infinite: the joints' limits alone)");
  if (k.velocity_rolling_window_size < 1) fail(s, "velocity_rolling_window_size must be >= 1");
  checkLimits(s, k.linear, "linear/x");
  checkLimits(s, k.angular, "angular/z");
  checkLimits(s, k.lateral, "linear/y");
  separation_ = s.wheel_separation * k.wheel_separation_multiplier;
  left_radius_ = s.wheel_radius * k.left_wheel_radius_multiplier;
  right_radius_ = s.wheel_radius * k.right_wheel_radius_multiplier;
  const std::vector<int>& all = wheels_;
  if (!s.gains.empty() && s.gains.size() != all.size()) fail(s, "needs one set of PID gains per wheel");
  for (std::size_t w = 0; w < all.size(); ++w) {
    const PidGains g =
        s.gains.empty() ? defaultWheelGains(model, all[w], rimRadius(w), static_cast<int>(all.size())) : s.gains[w];
    if (!validGains(g)) fail(s, "wheel PID gains p, i, d, i_clamp must be finite and >= 0");
    pids_.emplace_back(g);
  }
  if (s.steering) checkSteering(model, rest);
}

bool DiffDrive::command(double linear, double angular, double t, double lateral) {
  const auto within = [](double x) { return std::abs(x) <= ranges::kMaxCommandSpeed; };  // NaN is not
  if (!within(linear) || !within(angular) || !within(lateral) || !std::isfinite(t)) return false;
  linear_ = linear;
  angular_ = angular;
  lateral_ = spec_.mecanum ? lateral : 0.0;
  stamp_ = t;
  commanded_ = true;
  return true;
}

double DiffDrive::meanPosition(const ArticulationState& state, const std::vector<int>& joints) {
  double sum = 0.0;
  for (const int j : joints) sum += state.q(j - 1);
  return sum / static_cast<double>(joints.size());
}

void DiffDrive::integrate(double ds, double dtheta, double dlat) {
  // The arc of constant curvature: the body's displacement (ds, dlat)
  // shortened to its chord by sinc(dθ/2) and turned to the mean heading.
  const double scale = sinc(0.5 * dtheta), mid = odometry_.heading + 0.5 * dtheta;
  const double c = std::cos(mid), s = std::sin(mid);
  odometry_.x += scale * (ds * c - dlat * s);
  odometry_.y += scale * (ds * s + dlat * c);
  odometry_.heading = std::remainder(odometry_.heading + dtheta, 2.0 * M_PI);
}

void DiffDrive::average(double linear, double angular, double lateral) {
  const std::size_t n = static_cast<std::size_t>(spec_.settings.velocity_rolling_window_size);
  if (linear_window_.size() < n) {
    linear_window_.push_back(linear);
    angular_window_.push_back(angular);
    lateral_window_.push_back(lateral);
  } else {
    linear_window_[window_next_] = linear;
    angular_window_[window_next_] = angular;
    lateral_window_[window_next_] = lateral;
    window_next_ = (window_next_ + 1) % n;
  }
  const double count = static_cast<double>(linear_window_.size());
  odometry_.linear = std::accumulate(linear_window_.begin(), linear_window_.end(), 0.0) / count;
  odometry_.angular = std::accumulate(angular_window_.begin(), angular_window_.end(), 0.0) / count;
  odometry_.lateral = std::accumulate(lateral_window_.begin(), lateral_window_.end(), 0.0) / count;
}

namespace {

/// Wheel n of a mecanum base (left front, left back, right front, right
/// back): the sign its rim takes of v_y, and of ω k (a left wheel −, a right +).
double lateralSign(std::size_t n) { return n == 0 || n == 3 ? -1.0 : 1.0; }
double sideSign(std::size_t n) { return n < 2 ? -1.0 : 1.0; }

}  // namespace

void DiffDrive::readTravel(const ArticulationState& state) {
  travel_.clear();
  for (std::size_t n = 0; n < wheels_.size(); ++n) travel_.push_back(state.q(wheels_[n] - 1) * rimRadius(n));
}

void DiffDrive::observeMecanum(const ArticulationState& state, double dt) {
  // Each rim's travel d = v_x ∓ v_y ∓ k ω: the twist is the mean of
  // d, of ±d (its v_y sign) and of ±d / k (its side's), inverting it exactly.
  if (travel_.size() != wheels_.size()) readTravel(state);  // the first update: where the wheels start
  double dx = 0.0, dy = 0.0, dk = 0.0;
  for (std::size_t n = 0; n < wheels_.size(); ++n) {
    const double rim = state.q(wheels_[n] - 1) * rimRadius(n);
    const double d = rim - travel_[n];
    travel_[n] = rim;
    dx += 0.25 * d;
    dy += 0.25 * lateralSign(n) * d;
    dk += 0.25 * sideSign(n) * d;
  }
  const double dtheta = dk / (0.5 * separation_);
  integrate(dx, dtheta, dy);
  if (dt > 0.0) average(dx / dt, dtheta / dt, dy / dt);
}

void DiffDrive::observe(const ArticulationState& state, double dt) {
  if (spec_.settings.open_loop) {
    double v = last0_linear_, w = last0_angular_;
    if (spec_.steering) {  // ω is a steering angle: the motion it gives
      const PlanarMotion m = motionPerSpeed(*spec_.steering, steerable(*spec_.steering, w));
      w = v * m.w;
      v *= m.v;
    }
    integrate(v * dt, w * dt, last0_lateral_ * dt);
    odometry_.linear = v;
    odometry_.angular = w;
    odometry_.lateral = last0_lateral_;
    return;
  }
  if (spec_.mecanum) return observeMecanum(state, dt);
  if (spec_.steering) return observeSteered(state, dt);
  const double left = meanPosition(state, spec_.left) * left_radius_;
  const double right = meanPosition(state, spec_.right) * right_radius_;
  if (!has_travel_) {  // the first update: where the wheels start
    left_travel_ = left;
    right_travel_ = right;
    has_travel_ = true;
  }
  const double d_left = left - left_travel_, d_right = right - right_travel_;
  left_travel_ = left;
  right_travel_ = right;
  const double ds = 0.5 * (d_left + d_right), dtheta = (d_right - d_left) / separation_;
  integrate(ds, dtheta);
  if (dt > 0.0) average(ds / dt, dtheta / dt);
}

void DiffDrive::efforts(const ArticulationState& state, double t, double dt, Eigen::VectorXd& effort) {
  const DiffDriveSettings& k = spec_.settings;
  // The command: zero once too old, then limited against the last two.
  double v = linear_, w = angular_, vy = lateral_;
  if (!commanded_ || t - stamp_ > k.cmd_vel_timeout) v = w = vy = 0.0;
  v = k.linear.limit(v, last0_linear_, last1_linear_, dt);
  w = k.angular.limit(w, last0_angular_, last1_angular_, dt);
  vy = k.lateral.limit(vy, last0_lateral_, last1_lateral_, dt);
  last1_linear_ = last0_linear_;
  last1_angular_ = last0_angular_;
  last1_lateral_ = last0_lateral_;
  last0_linear_ = v;
  last0_angular_ = w;
  last0_lateral_ = vy;
  if (spec_.steering) return steeredEfforts(state, v, w, dt, effort);
  // Each wheel's speed, tracked through effort.
  const double left_speed = (v - 0.5 * w * separation_) / left_radius_;
  const double right_speed = (v + 0.5 * w * separation_) / right_radius_;
  const std::vector<int>& all = wheels_;
  for (std::size_t n = 0; n < all.size(); ++n) {
    const JointLimits& lim = limits_[n];
    const bool left = n < spec_.left.size();
    double speed = left ? left_speed : right_speed;
    if (spec_.mecanum) speed += lateralSign(n) * vy / (left ? left_radius_ : right_radius_);
    const double target = std::clamp(speed, -lim.velocity, lim.velocity);
    const int j = all[n];
    const double most = std::min(lim.effort, k.max_wheel_torque);
    effort(j - 1) = pids_[n].servo(target - state.v(j - 1), dt, response_[n], most);
  }
}

void DiffDrive::restart(const ArticulationState& state, bool zero_pose) {
  left_travel_ = meanPosition(state, spec_.left) * left_radius_;
  right_travel_ = meanPosition(state, spec_.right) * right_radius_;
  has_travel_ = true;
  for (Pid& pid : pids_) pid.reset();
  for (Pid& pid : steer_pids_) pid.reset();
  travel_.clear();
  if (spec_.mecanum || spec_.steering) readTravel(state);
  linear_window_.clear();
  angular_window_.clear();
  lateral_window_.clear();
  window_next_ = 0;
  linear_ = angular_ = lateral_ = 0.0;
  commanded_ = false;
  last0_linear_ = last0_angular_ = last1_linear_ = last1_angular_ = last0_lateral_ = last1_lateral_ = 0.0;
  if (zero_pose) odometry_ = PlanarOdometry{};
  odometry_.linear = odometry_.angular = odometry_.lateral = 0.0;
}

}  // namespace rigid_body_sim::core
