// The checks of a model's settings (model_checks.h).
#include "model_checks.h"

#include <algorithm>
#include <cmath>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/core/bodies/setting_keys.h"
#include "step/barrier.h"
#include "validate.h"

namespace rigid_body_sim::core {

void validateDamping(const Damping& d, double dt, const std::vector<BodyModel>& bodies) {
  // The explicit drag step v ← v (1 − σΔt/M) reverses v when σΔt/M ≥ 1.
  for (const BodyModel& b : bodies) {
    const double lin = d.linear_drag * dt * b.inv_mass;
    const double ang = d.angular_drag * dt * b.inv_inertia_B.maxCoeff();
    if (lin >= 1.0) {
      detail::fail("damping.linear_drag", detail::str(d.linear_drag),
                   "sigma*dt/mass = " + detail::str(lin) + " >= 1 for body '" + b.name +
                       "' (explicit drag would reverse the velocity; use damping.linear, a decay rate)");
    }
    if (ang >= 1.0) {
      detail::fail("damping.angular_drag", detail::str(d.angular_drag),
                   "sigma*dt/I_min = " + detail::str(ang) + " >= 1 for body '" + b.name +
                       "' (explicit drag would reverse the spin; use damping.angular, a decay rate)");
    }
  }
}

void validatePenalty(const ContactSettings& c, double dt, const std::vector<BodyModel>& bodies) {
  if (c.method != ContactMethod::kPenaltyQuadratic && c.method != ContactMethod::kPenaltyLogBarrier) return;
  for (const BodyModel& b : bodies) {
    const double stiff = c.penalty_stiffness * dt * dt * b.inv_mass;
    if (c.method == ContactMethod::kPenaltyQuadratic && stiff > ranges::kMaxPenaltyStiffnessRatio) {
      detail::fail("contact.penalty_stiffness", detail::str(c.penalty_stiffness),
                   "k*dt^2/mass = " + detail::str(stiff) + " > " + detail::str(ranges::kMaxPenaltyStiffnessRatio) +
                       " for body '" + b.name + "' (the explicit spring would be unstable; lower k or dt)");
    }
    const double damp = c.penalty_damping * dt * b.inv_mass;
    if (damp >= 1.0) {
      detail::fail("contact.penalty_damping", detail::str(c.penalty_damping),
                   "c*dt/mass = " + detail::str(damp) + " >= 1 for body '" + b.name +
                       "' (the explicit damper would reverse the velocity)");
    }
  }
}

/// The log barrier can only stop what its potential can hold: U(φ) down to
/// the floor at one contact point must exceed the kinetic energy a body can
/// bring to one point at the speed limits, ½ m (v + ω R)² (against another
/// body, the closing speed of both), plus gravity's work across the buffer
/// (docs/physics.md §7.2). Otherwise the speeds it cannot stop are refused.
void validateBarrier(const ContactSettings& c, const SpeedLimits& limits, const Vec3& gravity,
                     const std::vector<BodyModel>& bodies) {
  if (c.method != ContactMethod::kPenaltyLogBarrier) return;
  const double holds = barrierPotential(c, SolverSettings::kBarrierFloor);
  const auto reach = [&](const BodyModel& b) {
    return limits.max_linear_speed + limits.max_angular_speed * b.bound_radius;
  };
  double fastest = 0.0;
  if (bodies.size() > 1) {
    for (const BodyModel& b : bodies) fastest = std::max(fastest, reach(b));
  }
  for (const BodyModel& b : bodies) {
    const double closing = reach(b) + fastest;
    const double brings = 0.5 * b.mass * closing * closing + b.mass * gravity.norm() * c.barrier_buffer;
    if (brings > holds) {
      detail::fail("contact.barrier_strength", detail::str(c.barrier_strength),
                   "holds at most " + detail::str(holds) + " J at a contact point, but body '" + b.name +
                       "' can bring " + detail::str(brings) + " J to one at limits.max_linear_speed " +
                       detail::str(limits.max_linear_speed) + " m/s and limits.max_angular_speed " +
                       detail::str(limits.max_angular_speed) + " rad/s; raise it to at least " +
                       detail::str(c.barrier_strength * brings / holds) + " or lower the limits");
    }
  }
}

void validateSettings(const ModelSpec& spec) {
  checkSettings(spec);
  const SolverSettings& s = spec.solver;
  detail::requireNonNegative(s.rounding_speed, "solver.rounding_speed", "m/s");
  detail::requireCount(s.large_mesh_grid_resolution, 2, ranges::kMaxGridResolution,
                       "solver.large_mesh_grid_resolution");
  if (s.point_group_size < 1)
    detail::fail("solver.point_group_size", std::to_string(s.point_group_size), "must be >= 1");
}

}  // namespace rigid_body_sim::core
