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

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/loads.h"
#include "rigid_body_sim/core/step/workspace.h"

// Not exported from the library (only its own files and the core tests,
// which link its objects, call these), so link-time optimisation may inline them.
#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// When the last step returned this same input unchanged: does what the
/// step would do again, nothing but the still times and sleep (counted in
/// ws.skipped_steps), and returns true. Otherwise keeps the input if the
/// bodies are still (to compare the result with) and returns false: the
/// caller computes the step, then calls recordFixedPoint. Only when
/// ws.skip_fixed_points is set.
bool repeatFixedPoint(const Model& model, State& state, const Loads& loads, double h, Workspace& ws);

/// After a computed step: whether it returned its input unchanged (then the
/// next step from it is repeated). `islands_known`: the impulse solve ran.
void recordFixedPoint(const Model& model, const State& state, const Loads& loads, bool islands_known, Workspace& ws);

/// Drops the cache: the next step is computed in full (for steps that leave
/// other contents in the workspace).
void forgetFixedPoint(Workspace& ws);

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
