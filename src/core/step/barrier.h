// The log barrier (docs/physics.md §7.2), private to the core: its force
// law, taken as the exact work of its potential over each step, and the step
// control that keeps φ > 0 and the step within what explicit integration of
// so stiff a spring can follow.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/loads.h"
#include "rigid_body_sim/core/step/workspace.h"

// Not exported from the library (only its own files and the core tests,
// which link its objects, call these), so link-time optimisation may inline them.
#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// U(φ) = ρ (ln(ε/φ) − 1 + φ/ε) inside the buffer ε, 0 beyond (J): the
/// potential whose force is ρ (1/φ − 1/ε).
double barrierPotential(const ContactSettings& cs, double phi);

/// N: the constant force that does the potential's exact work from φ₀ to φ₁,
/// (U(φ₀) − U(φ₁)) / (φ₁ − φ₀) (a discrete gradient), or the force at the
/// midpoint when the two are too close to divide.
double barrierForce(const ContactSettings& cs, double phi0, double phi1);

/// One step of length h under the barrier: `advance` (the stages) run with
/// each contact's force the discrete gradient between its separations at
/// the start and at the end of the step, repeated as two halves where the
/// step is too long (§7.2).
using Advance = bool (*)(const Model&, State&, const Loads&, double, Workspace&);
void advanceKeepingBarrier(const Model& model, State& state, const Loads& loads, double h, Workspace& ws,
                           const Advance& advance, int depth = 0);

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
