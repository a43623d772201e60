// Shape matching (docs/physics.md §7.3): let every vertex move on its own
// with collision and friction, then find the rigid motion closest to where
// the vertices went. No physics in the second half: an optimization.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/loads.h"
#include "rigid_body_sim/core/step/workspace.h"

namespace rigid_body_sim::core {

/// R = Polar(A): the rotation of A = R S (S symmetric), by SVD A = U D Vᵀ,
/// R = U Vᵀ, with the sign of U's last column flipped if that makes det R
/// negative, so R is always a proper rotation (also for a reflected or
/// rank-deficient A).
Mat3 polarRotation(const Mat3& A);

/// One shape-matching step of length h for every awake body, in place of
/// every stage of step(): first the rigid velocities with the integration
/// stage's own functions (external loads, drag, damping, and the rotation
/// with the gyroscopic term), which is the whole step for a body away from
/// the scene; near it, each vertex moves on its own,
///   yᵢ = xᵢ + h (v + ω × rᵢ), with a particle response
///   where φ(yᵢ) < 0 (restitution, friction a = max(1 − μ_T(1+μ_N)|v_N|/|v_T|, 0)),
///   c = mean yᵢ,  A = (Σ (yᵢ − c) r̄ᵢᵀ)(Σ r̄ᵢ r̄ᵢᵀ)⁻¹,  R = Polar(A),
/// and the body's velocity is the rigid motion from the old pose to the new.
void stepShapeMatching(const Model& model, State& state, const Loads& loads, double h, Workspace& ws);

}  // namespace rigid_body_sim::core
