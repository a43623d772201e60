// The fixed-point cache of the step (docs/physics.md §6).
#include "fixed_point.h"

#include <cstring>

#include "scratch.h"
#include "sleep.h"

namespace rigid_body_sim::core {
namespace {

// A step that returns its input unchanged (detail::FixedPoint). Compared bit
// for bit, not with ==, which would take −0.0 for +0.0: the bits are the point
// (T holds only doubles, no padding), hence the NOLINT.
template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;  // NOLINT(bugprone-suspicious-memory-comparison)
}

/// Everything a body brings into the step but its still time.
bool sameMotion(const BodyState& a, const BodyState& b) {
  return sameBits(a.p_WB, b.p_WB) && sameBits(a.v_WB, b.v_WB) && sameBits(a.q_WB.coeffs(), b.q_WB.coeffs()) &&
         sameBits(a.w_B, b.w_B) && a.asleep == b.asleep;
}

bool sameImpulse(const ContactImpulse& a, const ContactImpulse& b) {
  return a.key() == b.key() && sameBits(a.normal, b.normal) && sameBits(a.tangent_W, b.tangent_W);
}

/// The step's whole input but the time and the still times (which only
/// decide sleep, and which the repeated step updates as a computed one would).
bool sameInput(const detail::FixedPoint& f, const Model& model, const State& state, const Loads& loads) {
  if (f.model != &model || f.bodies.size() != state.bodies.size() ||
      f.impulses.size() != state.contact_impulses.size() || f.loads.size() != loads.size()) {
    return false;
  }
  for (std::size_t i = 0; i < f.bodies.size(); ++i) {
    if (!sameMotion(f.bodies[i], state.bodies[i])) return false;
  }
  for (std::size_t i = 0; i < f.impulses.size(); ++i) {
    if (!sameImpulse(f.impulses[i], state.contact_impulses[i])) return false;
  }
  for (std::size_t i = 0; i < f.loads.size(); ++i) {
    if (!sameBits(f.loads[i], loads[i])) return false;
  }
  return true;
}

/// Below the sleep speeds after the last step: the only worlds that can be
/// at a fixed point, and the only ones worth keeping the input for.
bool everyAwakeBodyStill(const State& state) {
  for (const BodyState& s : state.bodies) {
    if (!s.asleep && !(s.still_time > 0.0)) return false;
  }
  return true;
}

}  // namespace

bool repeatFixedPoint(const Model& model, State& state, const Loads& loads, double h, Workspace& ws) {
  detail::FixedPoint& f = ws.scratch->fixed_point;
  if (ws.skip_fixed_points && f.holds && sameInput(f, model, state, loads)) {
    for (BodyState& s : state.bodies) {
      if (!s.asleep) updateStillTime(model, h, s);
    }
    sleepIslands(model, state, ws, f.islands_known);
    ++ws.skipped_steps;
    return true;
  }
  f.kept = ws.skip_fixed_points && everyAwakeBodyStill(state);
  f.holds = false;
  if (f.kept) {
    f.model = &model;
    f.bodies = state.bodies;
    f.impulses = state.contact_impulses;
    f.loads = loads;
  }
  return false;
}

void recordFixedPoint(const Model& model, const State& state, const Loads& loads, bool islands_known, Workspace& ws) {
  detail::FixedPoint& f = ws.scratch->fixed_point;
  f.islands_known = islands_known;
  f.holds = f.kept && sameInput(f, model, state, loads);
}

void forgetFixedPoint(Workspace& ws) { ws.scratch->fixed_point.holds = false; }

}  // namespace rigid_body_sim::core
