// The fixed-point cache of the step (private to the core). A step that
// returns its input unchanged bit for bit (bodies resting exactly: the
// contact impulses cancel gravity and leave v so small that x + Δt v = x)
// will do so again from the same input under the same loads, since the step
// is a function of its input: the next such step only counts the time and
// the still times (docs/physics.md §6). The input is kept only while every
// awake body is below the sleep speeds, so moving worlds do not pay for the
// copy. A repeated step takes the contacts and islands the last step left in
// the workspace: nothing else may run on it between steps, or the cache is
// dropped (forgetFixedPoint).
#pragma once

#include "rigid_body_sim/core/loads.h"
#include "rigid_body_sim/core/model.h"
#include "rigid_body_sim/core/state.h"
#include "rigid_body_sim/core/workspace.h"

// Not exported from the library (only its own files and the core tests,
// which link its objects, call these), so link-time optimisation may inline them.
#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// A full step of length h; returns whether the impulse solve ran (its islands are then in the workspace).
using AdvanceFunction = bool (*)(const Model&, State&, const Loads&, double, Workspace&);

/// advance(), or, when the last step returned this same input unchanged,
/// what advance() would do again: nothing but the still times and sleep
/// (counted in ws.skipped_steps). Only when ws.skip_fixed_points is set.
void advanceOrRepeat(const Model& model, State& state, const Loads& loads, double h, Workspace& ws,
                     AdvanceFunction advance);

/// Drops the cache: the next step is computed in full (for steps that leave
/// other contents in the workspace).
void forgetFixedPoint(Workspace& ws);

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
