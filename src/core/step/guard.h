// The speed limits and the finite-state guard (docs/physics.md §5.9): what
// keeps every state a step returns finite. Private to the core. Both run
// inside the stages' own loops over the bodies, where the body is already
// at hand: a separate pass cost the one-body step a third more.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/workspace.h"

// Not exported from the library (only its own files and the core tests,
// which link its objects, call these), so link-time optimisation may inline them.
#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// Scales v and ω back to the limits, keeping their directions, and lists
/// body `i` in ws.speed_limited (the slow path of limitSpeeds).
void holdToLimits(const Model& model, int i, BodyState& s, Workspace& ws);

/// Body `i`'s v and ω within the model's speed limits: scaled back to them
/// when faster. A velocity with a non-finite component is left to the guard.
inline void limitSpeeds(const Model& model, int i, BodyState& s, Workspace& ws) {
  const SpeedLimits& l = model.limits();
  if (s.v_WB.squaredNorm() <= l.max_linear_speed * l.max_linear_speed &&
      s.w_B.squaredNorm() <= l.max_angular_speed * l.max_angular_speed)
    return;
  holdToLimits(model, i, s, ws);
}

/// Whether every component of the body's state is finite: one vector sum
/// (NaN and ±∞ carry through it); only a finite sum that overflows, never
/// seen in practice, needs the component checks.
inline bool finiteState(const BodyState& s) {
  const double sum = (s.p_WB + s.v_WB + s.w_B).sum() + s.q_WB.coeffs().sum() + s.still_time;
  if (std::isfinite(sum)) return true;
  return s.p_WB.allFinite() && s.v_WB.allFinite() && s.q_WB.coeffs().allFinite() && s.w_B.allFinite() &&
         std::isfinite(s.still_time);
}

/// The guard, as MuJoCo's mj_checkPos and mj_checkVel: body `i`, found not
/// finite, stays at its pose (the last finite one: the stages before the
/// positions' change only velocities) at rest and awake, or goes to the
/// origin when the pose itself is not finite, and is listed in ws.diverged
/// (thread-safe: stages split over the cores call it). The slow path only.
void putBack(int i, BodyState& s, Workspace& ws);

/// After the stages, when the guard put bodies back: orders ws.diverged by
/// body and drops their contact impulses and contacts.
void finishGuard(State& state, Workspace& ws);

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
