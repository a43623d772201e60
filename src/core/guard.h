// The speed limits and the finite-state guard (docs/physics.md §5.9): what
// keeps every state a step returns finite. Private to the core.
#pragma once

#include "rigid_body_sim/core/model.h"
#include "rigid_body_sim/core/state.h"
#include "rigid_body_sim/core/workspace.h"

// Not exported from the library (only its own files and the core tests,
// which link its objects, call these), so link-time optimisation may inline them.
#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// Scales body `i`'s v and ω back to the model's speed limits, keeping their
/// directions, and lists the body in ws.speed_limited when it does. A
/// velocity with a non-finite component is left to the guard.
void limitSpeeds(const Model& model, int i, BodyState& s, Workspace& ws);

/// Keeps every body's pose before the stages change it: the last finite
/// state the guard puts a body back to.
void keepPoses(const State& state, Workspace& ws);

/// The guard, as MuJoCo's mj_checkPos and mj_checkVel: every body whose
/// state is no longer finite goes back to the pose keepPoses() kept, at rest
/// and awake, its contact impulses dropped, and is listed in ws.diverged.
void guardFinite(State& state, Workspace& ws);

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
