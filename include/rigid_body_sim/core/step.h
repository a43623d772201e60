// One time step of the simulation.
#pragma once

#include "rigid_body_sim/core/loads.h"
#include "rigid_body_sim/core/model.h"
#include "rigid_body_sim/core/state.h"

namespace rigid_body_sim::core {

/// Advances `state` by model.dt(). `loads` is one BodyLoad per body, held
/// constant over the step, or empty. The step is the notes' Euler-Cromer
/// loop, one named stage per line (see step.cpp):
///   accumulate forces and torques  F = M g − σ v + F_ext,  τ = −σ_ω ω + τ_ext
///   integrate velocities           v += Δt F / M,  ω += Δt I⁻¹ τ
///   apply damping                  v *= e^(−k Δt),  ω *= e^(−k_ω Δt)
///   gyroscopic rotation            Euler's −ω × Iω term (implicit midpoint)
///   integrate positions            x += Δt v
///   integrate orientations         q += [0, Δt/2 ω] × q, then normalize
void step(const Model& model, State& state, const Loads& loads = {});

}  // namespace rigid_body_sim::core
