// Contacts with the static scene and between bodies, and the declarations of
// the contact stages of a step (docs/physics.md §5): detection by signed
// distance (detection.cpp), the impulse response and the position correction
// (contact_solver.cpp), penalty forces (penalty.cpp). Shape matching is in
// shape_matching.h; the scratch memory the stages share is the Workspace
// (workspace.h).
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

struct Workspace;

/// One contact point of a body against a scene item or another body: the
/// point is one of `body`'s contact points, tested against the signed
/// distance of the item or of the other body's solid. The key (ContactKey:
/// body, other, item, point) names it from step to step.
struct Contact : ContactKey {
  Vec3 normal_W = Vec3::UnitZ();  ///< unit, out of the item (or other body) toward `body` (∇φ)
  Vec3 r_W = Vec3::Zero();        ///< contact point relative to `body`'s centre of mass, world axes (m)
  Vec3 r_other_W = Vec3::Zero();  ///< the same point relative to the other body's centre of mass (m)
  double separation = 0.0;        ///< φ − radius (m): < 0 penetrating, > 0 not yet touching

  // Results of the impulse solve.
  int last_impulse = -1;                  ///< index in the last step's state.contact_impulses, or -1 (new)
  double normal_impulse = 0.0;            ///< accumulated λ_N ≥ 0, N·s
  Vec3 tangent_impulse_W = Vec3::Zero();  ///< accumulated λ_T, |λ_T| ≤ μ λ_N, world axes, N·s
  double predicted_separation = 0.0;      ///< m after the step, from the solved velocity (linear)
};

// The stages are the library's own (step() runs them; the core's tests,
// which link its objects, call them directly): not exported, so link-time
// optimisation may inline them into the step.
#pragma GCC visibility push(hidden)

/// Stage 1 (§5.1). Contacts of the awake bodies, at the current state,
/// against the scene and against each other, into ws.contacts sorted by key:
/// every contact point with φ − radius < margin, where the margin is the
/// distance the bodies can travel in h (speculative contacts: a fast body is
/// caught before it passes through a thin shape) or the penalty buffer.
/// Between two bodies both ways are tested: the points of each against the
/// other's solid (analytic for boxes, spheres and cylinders, a sampled grid
/// for meshes); only pairs whose bounding boxes overlap are tested (sweep and
/// prune). For the impulse method the points of one region (one item or
/// body, one normal direction) are reduced to at most four that span it;
/// separate regions (the three walls of a room's corner) stay separate. A
/// sleeping body an awake one comes at is woken (wakeTouchedSleepers) and
/// the detection runs again with it awake.
void detectContacts(const Model& model, State& state, double h, Workspace& ws);

/// Stage 5 (§5.5), the impulse response, for all contacts together: per
/// contact the 3×3 K = M⁻¹𝟙 − [r]× I⁻¹ [r]× (with the other body's terms
/// added); normal and friction impulses solved by projected Gauss-Seidel with
/// accumulated clamping, λ_N ≥ 0 and |λ_T| ≤ μ λ_N. Restitution first, in
/// impact passes: the contacts arriving faster than the threshold separate
/// at e × the approach speed they had before the solve; contacts set
/// approaching by that collide in the next pass (a row of touching balls
/// passes the impulse along). Warm-started from the last step's impulses.
/// Islands (island.h) are solved on their own, split over the cores.
/// Updates v_WB and w_B of the bodies in contact and state.contact_impulses.
/// Returns whether it ran (the impulse method, with contacts).
bool solveContactImpulses(const Model& model, State& state, double h, Workspace& ws);

/// Stage 8 (§5.8): moves penetrating bodies out along the contact normals
/// (nonlinear Gauss-Seidel on positions, as Box2D does), leaving at most the
/// slop. Velocities are not touched, so no kinetic energy is added. Runs
/// after solveContactImpulses, on its islands.
void correctPositions(const Model& model, State& state, Workspace& ws);

/// Penalty forces (§7.1, §7.2) of the contacts on one body, reduced to the
/// centre of mass: quadratic f = k (ε − φ) or log-barrier f = ρ (1/φ − 1/ε),
/// both minus damping c v_N and never pulling, with Coulomb friction μ |f_N|.
void accumulatePenaltyForces(const Model& model, const State& state, const Workspace& ws, int body, Vec3& force_W,
                             Vec3& torque_W);

#pragma GCC visibility pop

/// The smallest φ − radius of any contact point of `body` within `margin`
/// of the scene (+infinity if none is that close; other bodies not counted).
double minSeparation(const Model& model, const BodyState& s, int body, double margin);

}  // namespace rigid_body_sim::core
