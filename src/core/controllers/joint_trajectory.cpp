// Joint trajectories through waypoints: joint_trajectory.h, docs/physics.md §11.11.
#include "rigid_body_sim/core/controllers/joint_trajectory.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::core {

namespace {

/// The order a point gives: 0 positions, 1 with velocities, 2 with accelerations.
int orderOf(const TrajectoryPoint& p) { return !p.acceleration.empty() ? 2 : !p.velocity.empty() ? 1 : 0; }

/// The polynomial from (q0, v0, a0) to (q1, v1, a1) over T > 0 of the given
/// order: the boundary conditions it uses fix it (linear: the positions;
/// cubic: positions and velocities; quintic: all three). With c0..c2 set by
/// the start, h, dv and da are what the higher terms must add at T.
std::array<double, 6> coefficients(const Setpoint& a, const Setpoint& b, double T, int order) {
  std::array<double, 6> c{a.position, 0.0, 0.0, 0.0, 0.0, 0.0};
  if (order == 0) {
    c[1] = (b.position - a.position) / T;
    return c;
  }
  c[1] = a.velocity;
  if (order == 1) {
    const double h = b.position - a.position - a.velocity * T, dv = b.velocity - a.velocity;
    c[2] = (3.0 * h - dv * T) / (T * T);
    c[3] = (-2.0 * h + dv * T) / (T * T * T);
    return c;
  }
  c[2] = 0.5 * a.acceleration;
  const double h = b.position - a.position - a.velocity * T - c[2] * T * T;
  const double dv = b.velocity - a.velocity - a.acceleration * T, da = b.acceleration - a.acceleration;
  const double T2 = T * T, T3 = T2 * T;
  c[3] = (10.0 * h - 4.0 * dv * T + 0.5 * da * T2) / T3;
  c[4] = (-15.0 * h + 7.0 * dv * T - da * T2) / (T3 * T);
  c[5] = (6.0 * h - 3.0 * dv * T + 0.5 * da * T2) / (T3 * T2);
  return c;
}

}  // namespace

JointTrajectory::JointTrajectory(const std::vector<double>& position) : joints_(position.size()) {
  Piece hold;
  for (const double q : position) hold.coefficients.push_back({q, 0.0, 0.0, 0.0, 0.0, 0.0});
  pieces_.push_back(std::move(hold));
}

std::string orderTrajectory(const std::vector<std::string>& joints, const std::vector<std::string>& names,
                            std::vector<TrajectoryPoint>& points) {
  const std::size_t n = joints.size();
  if (names.size() != n) {
    return "joint_names has " + std::to_string(names.size()) + " names; the controller's " + std::to_string(n) +
           " joints must each be named once";
  }
  std::vector<std::size_t> from(n, n);  // from[k]: where joint k is in the names
  for (std::size_t m = 0; m < n; ++m) {
    const std::size_t k = static_cast<std::size_t>(std::find(joints.begin(), joints.end(), names[m]) - joints.begin());
    if (k == n) return "joint_names[" + std::to_string(m) + "]: '" + names[m] + "' is not its joint";
    if (from[k] != n) return "joint_names[" + std::to_string(m) + "]: '" + names[m] + "' twice";
    from[k] = m;
  }
  const auto ordered = [&](std::vector<double>& values) {
    if (values.size() != n) return;
    std::vector<double> out(n);
    for (std::size_t k = 0; k < n; ++k) out[k] = values[from[k]];
    values = std::move(out);
  };
  for (TrajectoryPoint& p : points) {
    ordered(p.position);
    ordered(p.velocity);
    ordered(p.acceleration);
  }
  return "";
}

std::string JointTrajectory::check(const std::vector<TrajectoryPoint>& points, std::size_t joints) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const TrajectoryPoint& p = points[i];
    const std::string at = "points[" + std::to_string(i) + "]";
    if (!(p.time >= 0.0 && p.time <= ranges::kMaxDuration))
      return at + ".time_from_start must be finite and >= 0, at most 1e6 s";
    if (i > 0 && !(p.time > points[i - 1].time)) return at + ".time_from_start must be after the point before's";
    if (p.position.size() != joints) {
      return at + ".positions has " + std::to_string(p.position.size()) + " values for " + std::to_string(joints) +
             " joints";
    }
    for (const auto& [field, values, most] : {std::tuple<const char*, const std::vector<double>*, double>{
                                                  "positions", &p.position, ranges::kMaxCommandPosition},
                                              {"velocities", &p.velocity, ranges::kMaxCommandSpeed},
                                              {"accelerations", &p.acceleration, ranges::kMaxCommandAcceleration}}) {
      if (!values->empty() && values->size() != joints) {
        return at + "." + field + " has " + std::to_string(values->size()) + " values for " + std::to_string(joints) +
               " joints (none, or one per joint)";
      }
      for (std::size_t k = 0; k < values->size(); ++k) {
        if (!std::isfinite((*values)[k])) return at + "." + field + "[" + std::to_string(k) + "] is not finite";
        if (!(std::abs((*values)[k]) <= most)) {  // 1e308 is finite, but its spline is not
          return at + "." + field + "[" + std::to_string(k) + "] is absurd: its size is beyond " + std::to_string(most);
        }
      }
    }
    if (!p.acceleration.empty() && p.velocity.empty()) return at + " has accelerations without velocities";
  }
  return {};
}

JointTrajectory::Piece JointTrajectory::piece(double t0, const std::vector<Setpoint>& a, double t1,
                                              const std::vector<Setpoint>& b, int order) {
  Piece p;
  p.start = t0;
  p.end = t1;
  const double T = t1 - t0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    // A point due at the switch itself is jumped to: the controller pulls the joint there.
    p.coefficients.push_back(T > 0.0 ? coefficients(a[k], b[k], T, order)
                                     : std::array<double, 6>{b[k].position, 0.0, 0.0, 0.0, 0.0, 0.0});
  }
  return p;
}

std::size_t JointTrajectory::pieceAt(double t) const {
  std::size_t i = 0;
  while (i + 1 < pieces_.size() && pieces_[i + 1].start <= t) ++i;
  return i;
}

Setpoint JointTrajectory::sample(double t, std::size_t k) const {
  if (pieces_.empty()) return {};
  const Piece& p = pieces_[pieceAt(t)];
  const std::array<double, 6>& c = p.coefficients[k];
  const double duration = p.end - p.start, tau = std::clamp(t - p.start, 0.0, duration);
  Setpoint s;
  for (int i = 5; i >= 0; --i) s.position = s.position * tau + c[i];  // Horner
  if (t - p.start < 0.0 || t - p.start > duration) return s;          // outside its span: at rest
  for (int i = 5; i >= 1; --i) s.velocity = s.velocity * tau + i * c[i];
  for (int i = 5; i >= 2; --i) s.acceleration = s.acceleration * tau + i * (i - 1) * c[i];
  return s;
}

int JointTrajectory::follow(double now, double start, const std::vector<TrajectoryPoint>& points,
                            const std::vector<char>& wraps) {
  std::size_t first = 0;
  while (first < points.size() && start + points[first].time <= now) ++first;
  if (first == points.size()) return -1;
  const double t_switch = std::max(start, now);
  std::vector<Setpoint> from(joints_);
  for (std::size_t k = 0; k < joints_; ++k) from[k] = sample(t_switch, k);
  // What is left to follow of this trajectory until the switch.
  std::vector<Piece> pieces;
  for (std::size_t i = pieces_.empty() ? 0 : pieceAt(now); i < pieces_.size() && pieces_[i].start < t_switch; ++i) {
    pieces.push_back(std::move(pieces_[i]));
  }
  std::vector<double> offset(joints_, 0.0);
  for (std::size_t k = 0; k < joints_; ++k) {
    if (k < wraps.size() && wraps[k] != 0) {
      const double turn = 2.0 * M_PI;
      offset[k] = turn * std::round((from[k].position - points[first].position[k]) / turn);
    }
  }
  double t0 = t_switch;
  int order0 = 2;
  for (std::size_t i = first; i < points.size(); ++i) {
    const TrajectoryPoint& p = points[i];
    std::vector<Setpoint> to(joints_);
    for (std::size_t k = 0; k < joints_; ++k) {
      to[k].position = p.position[k] + offset[k];
      if (!p.velocity.empty()) to[k].velocity = p.velocity[k];
      if (!p.acceleration.empty()) to[k].acceleration = p.acceleration[k];
    }
    const double t1 = start + p.time;
    pieces.push_back(piece(t0, from, t1, to, std::min(order0, orderOf(p))));
    from = std::move(to);
    t0 = t1;
    order0 = orderOf(p);
  }
  pieces_ = std::move(pieces);
  return static_cast<int>(first);
}

}  // namespace rigid_body_sim::core
