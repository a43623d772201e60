// A stiff body's normal impulses in one exact solve (private to the core;
// docs/physics.md §5.5, "A heavy body with a small inertia").
#pragma once

#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/settings.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "solver_contact.h"

#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core::detail {

/// Islands with more contacts are left to the sweeps alone.
constexpr int kMaxStiffBodyContacts = 16;

/// The awake body of an island of one body against the scene and sleepers
/// whose contacts are stiffer in rotation than along their normals by more
/// than `settings.stiff_body_ratio` (λ_max(I⁻¹) |r|² against 1/m), or −1:
/// Gauss-Seidel, one contact at a time, moves such a body's centre by a
/// fraction of a per cent a sweep.
int stiffBody(const SolverSettings& settings, const std::vector<Mat3>& inverse_inertias_W, const SolverContact* begin,
              const SolverContact* end);

/// The island's normal impulses, friction impulses held, solved together
/// exactly: every contact pushes (λ_N ≥ 0) and ends at or above its target
/// normal velocity, and the pushing ones at it (an active set over the
/// least-norm solves of their K). Sets the contacts' λ_N and `vel[body]`;
/// returns false, changing nothing, if the active set does not settle.
bool solveStiffBodyNormals(const SolverSettings& settings, const Mat3& inverse_inertia_W, int body,
                           SolverContact* begin, SolverContact* end, std::vector<BodyVelocity>& vel);

/// Position correction (§5.8) of a body solved as stiff: its contacts
/// `indices` (into `contacts`; every one against the scene or a sleeper)
/// pushed out to −slop together from their predicted separations, by the
/// least-norm pseudo-impulses λ ≥ 0 with d + J M⁻¹ Jᵀ λ ≥ −slop, applied to
/// the pose to first order. The nonlinear sweeps then finish what is left.
void correctStiffBody(const BodyModel& model, BodyState& state, int body, const std::vector<Contact>& contacts,
                      const std::vector<int>& indices, double slop, double tolerance);

}  // namespace rigid_body_sim::core::detail
#pragma GCC visibility pop
