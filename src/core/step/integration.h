// The integration stages of a step (docs/physics.md §5.2–§5.4, §5.6–§5.7):
// forces to velocities, then velocities to poses, Euler-Cromer. Private to
// the core; each function is one body's part of a stage, and the two stages
// run them over the awake bodies.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/loads.h"
#include "rigid_body_sim/core/step/workspace.h"

// Not exported from the library (only its own files and the core tests,
// which link its objects, call these), so link-time optimisation may inline them.
#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// External, drag and penalty loads on one body for this step (gravity is
/// applied as an acceleration, so free fall is exactly v += h g).
struct NetLoad {
  Vec3 force_W = Vec3::Zero();   ///< N, world frame
  Vec3 torque_B = Vec3::Zero();  ///< N·m, body frame
};

/// F = −σ v + F_ext (+ penalty), τ = −σ_ω ω + τ_ext (+ penalty) (§5.2);
/// `load` may be null (none).
NetLoad accumulateForces(const Model& model, const State& state, const BodyLoad* load, const Workspace& ws, int body);

/// v += h (g + F/M), ω += h I⁻¹ τ in the body frame (§5.3).
void integrateVelocity(const Model& model, const BodyModel& b, const NetLoad& net, double h, BodyState& s);

/// v ← e^(−k h) v, ω ← e^(−k_ω h) ω (§5.4).
void applyDamping(const Model& model, double h, BodyState& s);

/// Euler's −ω × Iω term by the implicit midpoint rule (§5.6): updates w_B
/// and returns the body-frame rotation of the step as the unnormalized
/// quaternion increment [1, h/2 Ω_mid] (Ω = ω with the term off).
Quat gyroscopicRotation(const Model& model, const BodyModel& b, double h, BodyState& s);

/// x += h v (§5.7).
void integratePosition(double h, BodyState& s);

/// q ← q ⊗ increment, normalized (§5.7).
void integrateOrientation(const Quat& increment, BodyState& s);

/// One awake body's rotation, position and orientation over h (§5.6–5.7;
/// not its still time): what stage 6–7 does to each body.
void integrateBody(const Model& model, const BodyModel& b, double h, BodyState& s);

/// Stage 2–4: forces, velocities and damping of every awake body, then its
/// speed limits (guard.h).
void integrateVelocities(const Model& model, State& state, const Loads& loads, double h, Workspace& ws);

/// Stage 6–7: rotation (with the gyroscopic term), position and orientation
/// of every awake body, and the time it has been still (§6), then the guard
/// (§5.9, guard.h); split over the cores when enough bodies are awake.
void integratePositions(const Model& model, State& state, double h, Workspace& ws);

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
