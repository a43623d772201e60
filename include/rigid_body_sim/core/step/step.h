// One time step of the simulation.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/loads.h"
#include "rigid_body_sim/core/step/workspace.h"

namespace rigid_body_sim::core {

/// Advances `state` by model.dt(). `loads` is one BodyLoad per body, held
/// constant over the step, or empty. `workspace` is scratch memory reused
/// across steps (optional; it also reports the step's contacts and deepest
/// penetration). The step is the Euler-Cromer loop of docs/physics.md §4, one named stage
/// per line (see step.cpp):
///   detect contacts                φ(x + R rᵢ) < margin against the scene
///   accumulate forces and torques  F = M g − σ v + F_ext (+ penalty),  τ likewise
///   integrate velocities           v += Δt F / M,  ω += Δt I⁻¹ τ
///   apply damping                  v *= e^(−k Δt),  ω *= e^(−k_ω Δt)
///   solve contact impulses         J = K⁻¹ Δv per contact, together (impulse method)
///   gyroscopic rotation            Euler's −ω × Iω term (implicit midpoint)
///   integrate positions            x += Δt v
///   integrate orientations         q += [0, Δt/2 ω] × q, then normalize
///   correct positions              push penetrating bodies out (impulse method)
///   update sleep                   bodies at rest stop being integrated
/// Velocities are held to the speed limits where loads and contacts change
/// them, and a body whose state stops being finite goes back to its pose
/// before the step, at rest (the guard; both reported in the workspace).
/// Shape matching replaces every stage (shape_matching.h);
/// the log-barrier method repeats a step as two halves when φ would cross 0.
void step(const Model& model, State& state, const Loads& loads = {}, Workspace* workspace = nullptr);

}  // namespace rigid_body_sim::core
