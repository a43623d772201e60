// Still time and sleep (docs/physics.md §6).
#include "sleep.h"

#include <cmath>

#include "contacts/island.h"
#include "scratch.h"

namespace rigid_body_sim::core {

void wakeLoadedBodies(State& state, const Loads& loads) {
  for (std::size_t i = 0; i < loads.size() && i < state.bodies.size(); ++i) {
    BodyState& s = state.bodies[i];
    if (s.asleep && !loads[i].isZero()) {
      s.asleep = false;
      s.still_time = 0.0;
    }
  }
}

bool wakeTouchedSleepers(const Model& model, State& state, const Workspace& ws, double h) {
  // Wake a sleeper when an awake body comes at it faster than a resting
  // contact would (gravity's one step), or presses in deeper than the slop.
  const double still = model.sleep().linear_velocity + model.gravity().norm() * h;
  bool woke = false;
  for (const Contact& c : ws.contacts) {
    if (c.other < 0) continue;
    BodyState &a = state.bodies[c.body], &o = state.bodies[c.other];
    if (a.asleep == o.asleep) continue;
    const BodyState& awake = a.asleep ? o : a;
    BodyState& sleeper = a.asleep ? a : o;
    const Vec3 w = awake.q_WB * awake.w_B;
    const Vec3 arm = a.asleep ? c.r_other_W : c.r_W;
    const double approach = std::abs(c.normal_W.dot(awake.v_WB + w.cross(arm)));
    if (approach > still || c.separation < -model.contact().position_slop) {
      sleeper.asleep = false;
      sleeper.still_time = 0.0;
      woke = true;
    }
  }
  return woke;
}

/// Sleep by islands, as Box2D does: bodies joined by contacts fall asleep
/// together, once every one of them has been still for the sleep time while
/// touching something, or is held exactly still (the scratch's held_still: the
/// sleep time only guards the loose sleep speeds, and exactly zero is
/// equilibrium, not the turning point of a bounce). A body alone would
/// otherwise fall asleep under a neighbour still settling on it, and the
/// neighbour's next jolt would wake it again, over and over. The islands are
/// those of the impulse solve when it ran (no body has changed sleep state
/// since).
void sleepIslands(const Model& model, State& state, Workspace& ws, bool islands_known) {
  if (!model.sleep().enabled || ws.contacts.empty()) return;  // nothing touches: nothing sleeps
  detail::StepScratch& sc = *ws.scratch;
  if (!islands_known) findIslands(model, state, ws);
  std::vector<char>& ready = sc.island_flags;  // per root: every body of the island may sleep
  ready.assign(model.bodyCount(), 1);
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    const BodyState& s = state.bodies[i];
    const bool held = islands_known && sc.held_still[i];
    if (!s.asleep && !held && !readyToSleep(model, sc.in_contact[i] != 0, s)) ready[sc.island_root[i]] = 0;
  }
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    BodyState& s = state.bodies[i];
    if (!s.asleep && ready[sc.island_root[i]]) fallAsleep(s);
  }
}

}  // namespace rigid_body_sim::core
