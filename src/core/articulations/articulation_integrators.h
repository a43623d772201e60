// The integrators of an articulation's step (private to the core): the
// passes that take its prediction to the velocity of the step, by velocity
// Verlet or by symplectic Euler, and Verlet's floating base.
// docs/physics.md §11.5.
#pragma once

#include "rigid_body_sim/core/articulations/articulation_step.h"

#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core::detail {

/// Symplectic Euler's corrector (§11.5): p⁺ = p + h (τ + ∂T/∂q(q, u⁺)),
/// implicit in u⁺ through ∂T/∂q, by fixed-point passes from the prediction
/// (ws.predicted); where they do not contract (a fast or long, light
/// chain), false: the prediction stands. The result in ws.next, the
/// joints' momenta in ws.rhs.
bool symplecticPasses(const ArticulationModel& model, double h, ArticulationWorkspace& ws);

/// Velocity Verlet with the step's velocity ū (§11.5): A (ū⁺ − ū) =
/// h (τ − c(q, ½ (ū + ū⁺)) − D ū), c with gravity g_W and the wrenches
/// `wrench_L` (ws.force holds the efforts alone), the Coriolis terms at the velocity of
/// the step's start, implicit in ū⁺; kVerletPasses fixed-point passes from
/// the prediction (ws.predicted), stopped early when they grow. A state not
/// carried from the last step has its velocity at this instant: its ū is
/// half a step back, and the step is explicit. ws.gain is what the step
/// changed ū by, for the next step's prediction.
bool verletPasses(const ArticulationModel& model, const ArticulationLoads& loads, const Vec3& g_W,
                  const std::vector<Vec6>& wrench_L, double h, bool fresh, ArticulationWorkspace& ws);

/// Verlet's floating base (§11.5): its twist such that the step's velocity
/// carries the whole momentum H_W (the step's, at its middle) where it
/// acts, at the middle of the step's move: the joints half way, the base
/// turned and moved by half the step at that twist. The middle depends on
/// the twist a little: rounds until the twist stays put (to 1e-15, or
/// where it stops shrinking at rounding; at most kMiddleRounds).
void middleMomentum(const ArticulationModel& model, const ArticulationState& state, double h,
                    ArticulationWorkspace& ws);

}  // namespace rigid_body_sim::core::detail
#pragma GCC visibility pop
