// Joint controllers through effort: joint_control.h, docs/physics.md §11.10.
#include "rigid_body_sim/core/controllers/joint_control.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::core {

double Pid::command(double error, double rate, double dt) {
  integral_ += dt * error;
  const double i_term = std::clamp(gains_.i * integral_, -gains_.i_clamp, gains_.i_clamp);
  last_error_ = error;
  has_last_ = true;
  return gains_.p * error + i_term + gains_.d * rate;
}

double Pid::command(double error, double dt) {
  const double rate = has_last_ && dt > 0.0 ? (error - last_error_) / dt : 0.0;
  return command(error, rate, dt);
}

double Pid::servo(double error, double dt, double response, double limit) {
  const double before = integral_;
  const double stiffness = gains_.p * dt * response;  // 0 · ∞ (no gain on a massless joint) is none
  const double u = command(error, dt) / (1.0 + (std::isnan(stiffness) ? 0.0 : stiffness));
  if (std::abs(u) <= limit) return u;
  // Held: the integral takes back what pushed it further that way.
  if ((u > 0.0) == (error > 0.0)) integral_ = before;
  return std::clamp(u, -limit, limit);
}

void Pid::reset() {
  integral_ = 0.0;
  last_error_ = 0.0;
  has_last_ = false;
}

namespace {

[[noreturn]] void fail(const JointControllerSpec& c, const std::string& what) {
  throw std::invalid_argument("controller '" + c.name + "': " + what);
}

}  // namespace

bool validGains(const PidGains& g) {
  for (const double x : {g.p, g.i, g.d, g.i_clamp}) {
    if (!(std::isfinite(x) && x >= 0.0)) return false;
  }
  return true;
}

JointControllers::JointControllers(const ArticulationModel& model, std::vector<JointControllerSpec> specs)
    : specs_(std::move(specs)), owner_(model.links.size(), -1) {
  for (const ArticulatedLink& link : model.links) {
    type_.push_back(link.type);
    limits_.push_back(link.limits);
  }
  for (std::size_t c = 0; c < specs_.size(); ++c) {
    const JointControllerSpec& spec = specs_[c];
    if (spec.joints.empty()) fail(spec, "names no joint");
    const bool pid = spec.mode != ControlMode::kEffort;
    if (pid && spec.gains.size() != spec.joints.size()) fail(spec, "needs PID gains for each of its joints");
    std::vector<Pid> pids;
    std::vector<double> target;
    for (std::size_t k = 0; k < spec.joints.size(); ++k) {
      const int j = spec.joints[k];
      if (j < 1 || j >= static_cast<int>(model.links.size())) fail(spec, "joint index " + std::to_string(j));
      const ArticulatedLink& link = model.links[j];
      if (link.mimic.joint >= 0) {
        fail(spec, "joint '" + link.joint + "' mimics '" + model.links[link.mimic.joint].joint +
                       "': command that one (a mimic joint follows it)");
      }
      if (owner_[j] >= 0) {
        fail(spec, "joint '" + link.joint + "' is already controller '" + specs_[owner_[j]].name + "''s");
      }
      owner_[j] = static_cast<int>(c);
      if (pid && !validGains(spec.gains[k])) {
        fail(spec, "joint '" + link.joint + "': PID gains p, i, d, i_clamp must be finite and >= 0");
      }
      pids.emplace_back(pid ? spec.gains[k] : PidGains{});
      target.push_back(0.0);
    }
    // A trajectory controller holds its joints at 0 until restart() says where they are.
    trajectory_.push_back(spec.mode == ControlMode::kTrajectory ? JointTrajectory(target) : JointTrajectory());
    pids_.push_back(std::move(pids));
    target_.push_back(std::move(target));
  }
}

int JointControllers::ownerOf(int joint) const {
  return joint >= 0 && joint < static_cast<int>(owner_.size()) ? owner_[joint] : -1;
}

namespace {

/// The most a command of `mode` may be (ranges.h): 1e308 is finite, but a
/// PID made inf and NaN of it.
double mostOf(ControlMode mode) {
  switch (mode) {
    case ControlMode::kEffort:
      return ranges::kMaxCommandEffort;
    case ControlMode::kVelocity:
      return ranges::kMaxCommandSpeed;
    case ControlMode::kPosition:
    case ControlMode::kTrajectory:
      break;
  }
  return ranges::kMaxCommandPosition;
}

bool sane(ControlMode mode, double value) { return std::abs(value) <= mostOf(mode); }  // NaN is not

}  // namespace

bool JointControllers::command(std::size_t c, const std::vector<double>& values, std::vector<Clipped>& clipped) {
  const JointControllerSpec& spec = specs_.at(c);
  if (spec.mode == ControlMode::kTrajectory || values.size() != spec.joints.size()) return false;
  for (const double v : values) {
    if (!sane(spec.mode, v)) return false;
  }
  for (std::size_t k = 0; k < values.size(); ++k) {
    target_[c][k] = withinLimits(spec.joints[k], spec.mode, values[k], clipped);
  }
  return true;
}

double JointControllers::withinLimits(int j, ControlMode mode, double v, std::vector<Clipped>& clipped) const {
  const JointLimits& lim = limits_[j];
  const auto hold = [&](double lo, double hi, const char* what) {
    if (v < lo || v > hi) {
      v = std::clamp(v, lo, hi);
      clipped.push_back({j, what});
    }
  };
  switch (mode) {
    case ControlMode::kEffort:
      hold(-lim.effort, lim.effort, "effort");
      break;
    case ControlMode::kVelocity:
      hold(-lim.velocity, lim.velocity, "velocity");
      break;
    case ControlMode::kPosition:
    case ControlMode::kTrajectory:
      if (type_[j] != JointType::Continuous) hold(lim.lower, lim.upper, "position range");
      break;
  }
  return v;
}

std::string JointControllers::commandJoint(int joint, ControlMode mode, double value, std::vector<Clipped>& clipped) {
  const int c = ownerOf(joint);
  if (c < 0) return "no controller owns it";
  const JointControllerSpec& spec = specs_[c];
  static const char* const kNames[] = {"effort", "velocity", "position", "trajectories"};
  if (spec.mode != mode) {
    return std::string("its controller '") + spec.name + "' takes " + kNames[static_cast<int>(spec.mode)] + ", not " +
           kNames[static_cast<int>(mode)];
  }
  if (!std::isfinite(value)) return "not finite";
  if (!sane(mode, value)) return "absurd: its size is beyond " + std::to_string(mostOf(mode));
  std::size_t k = 0;
  while (spec.joints[k] != joint) ++k;
  target_[c][k] = withinLimits(joint, mode, value, clipped);
  return "";
}

std::string JointControllers::followTrajectory(std::size_t c, double now, double start,
                                               std::vector<TrajectoryPoint> points, std::vector<Clipped>& clipped,
                                               int& dropped) {
  const JointControllerSpec& spec = specs_.at(c);
  if (spec.mode != ControlMode::kTrajectory) return "controller '" + spec.name + "' takes no trajectories";
  std::string problem = JointTrajectory::check(points, spec.joints.size());
  if (!problem.empty()) return problem;
  std::vector<Clipped> held;
  std::vector<char> wraps;
  for (std::size_t k = 0; k < spec.joints.size(); ++k) {
    const int j = spec.joints[k];
    wraps.push_back(type_[j] == JointType::Continuous ? 1 : 0);
    for (TrajectoryPoint& p : points) {
      p.position[k] = withinLimits(j, ControlMode::kTrajectory, p.position[k], held);
      if (!p.velocity.empty()) p.velocity[k] = withinLimits(j, ControlMode::kVelocity, p.velocity[k], held);
    }
  }
  JointTrajectory next = trajectory_[c];
  dropped = next.follow(now, start, points, wraps);
  if (dropped < 0)
    return "every point is past (the last was due at " + std::to_string(start + points.back().time) + " s, now is " +
           std::to_string(now) + " s)";
  trajectory_[c] = std::move(next);
  clipped.insert(clipped.end(), held.begin(), held.end());
  return {};
}

void JointControllers::hold(std::size_t c, const ArticulationState& state) {
  std::vector<double> q;
  for (const int j : specs_.at(c).joints) q.push_back(state.q(j - 1));
  trajectory_[c] = JointTrajectory(q);
  for (Pid& pid : pids_[c]) pid.reset();
}

void JointControllers::efforts(const ArticulationState& state, double t, double dt, Eigen::VectorXd& effort) {
  if (owner_.empty()) {  // made without a model: nothing to drive
    effort.resize(0);
    return;
  }
  effort.setZero(static_cast<Eigen::Index>(owner_.size()) - 1);
  for (std::size_t c = 0; c < specs_.size(); ++c) {
    const JointControllerSpec& spec = specs_[c];
    for (std::size_t k = 0; k < spec.joints.size(); ++k) {
      const int j = spec.joints[k];
      const double q = state.q(j - 1), v = state.v(j - 1), target = target_[c][k];
      double u = 0.0;
      switch (spec.mode) {
        case ControlMode::kEffort:
          u = target;
          break;
        case ControlMode::kVelocity:
          u = pids_[c][k].command(target - v, dt);
          break;
        case ControlMode::kPosition: {
          // A continuous joint turns the short way to its target.
          const double error = type_[j] == JointType::Continuous ? std::remainder(target - q, 2.0 * M_PI) : target - q;
          u = pids_[c][k].command(error, -v, dt);
          break;
        }
        case ControlMode::kTrajectory: {
          const Setpoint s = trajectory_[c].sample(t, k);
          u = pids_[c][k].command(s.position - q, s.velocity - v, dt);
          break;
        }
      }
      effort(j - 1) = limits_[j].heldEffort(u);
    }
  }
}

void JointControllers::restart(const ArticulationState& state) {
  for (std::size_t c = 0; c < specs_.size(); ++c) {
    if (specs_[c].mode == ControlMode::kTrajectory) hold(c, state);
    for (std::size_t k = 0; k < specs_[c].joints.size(); ++k) {
      pids_[c][k].reset();
      target_[c][k] = specs_[c].mode == ControlMode::kPosition ? state.q(specs_[c].joints[k] - 1) : 0.0;
    }
  }
}

}  // namespace rigid_body_sim::core
