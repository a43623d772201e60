// Still time and sleep (docs/physics.md §6), private to the core: a body
// that stays below the sleep speeds for the sleep time while touching
// something falls asleep with its island; loads, impulses, new states and
// awake bodies coming at it wake it.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/loads.h"
#include "rigid_body_sim/core/step/workspace.h"
#include "world.h"

// Not exported from the library (only its own files and the core tests,
// which link its objects, call these), so link-time optimisation may inline them.
#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// After a step of h: counts the time a body stays below the sleep speeds.
inline void updateStillTime(const Model& model, double h, BodyState& s) {
  const SleepSettings& sleep = model.sleep();
  const bool still = s.v_WB.squaredNorm() < sleep.linear_velocity * sleep.linear_velocity &&
                     s.w_B.squaredNorm() < sleep.angular_velocity * sleep.angular_velocity;
  s.still_time = still ? s.still_time + h : 0.0;
}

/// Whether a body may fall asleep now: sleeping is on, the body has been
/// still for the sleep time, and it is `touching` something (a body in free
/// flight never sleeps).
inline bool readyToSleep(const Model& model, bool touching, const BodyState& s) {
  return model.sleep().enabled && touching && s.still_time > 0.0 && s.still_time >= model.sleep().time;
}

/// Puts a body to sleep: velocities zeroed, no longer integrated, so it
/// stays exactly put until something wakes it.
inline void fallAsleep(BodyState& s) {
  s.asleep = true;
  s.v_WB.setZero();
  s.w_B.setZero();
}

/// updateStillTime, then sleep for a body on its own (no islands: shape matching).
inline void updateSleep(const Model& model, bool touching, double h, BodyState& s) {
  updateStillTime(model, h, s);
  if (readyToSleep(model, touching, s)) fallAsleep(s);
}

/// Wakes every sleeping body with a non-zero load (impulses and new states
/// wake a body themselves).
void wakeLoadedBodies(State& state, const Loads& loads);

/// Wakes the sleeping bodies an awake body comes at (faster than a resting
/// contact) or presses into (deeper than the slop), from this step's
/// contacts. Returns whether any woke.
bool wakeTouchedSleepers(const Model& model, State& state, const Workspace& ws, double h);

/// sleepIslands (below) for free bodies alone. `islands_known`: the impulse
/// solve ran and left its islands in the workspace.
void sleepIslands(const Model& model, State& state, Workspace& ws, bool islands_known);

namespace detail {

/// The sleep stage (§6, §11.9), for bodies and robots alike: islands whose
/// bodies and robots are all ready to sleep (a body also when held exactly
/// still by the impulse solve) fall asleep together; a robot's still time
/// is counted here. `islands_known`: the free bodies' impulse solve ran.
void sleepIslands(const World& world, double h, WorldState& state, WorldWorkspace& ws, bool islands_known);

}  // namespace detail

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
