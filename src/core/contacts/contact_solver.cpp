// The impulse response (K J = Δv for every contact together, by projected
// Gauss-Seidel over islands; docs/physics.md §5.5). The position correction
// after it is position_correction.cpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "island.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "solver_contact.h"
#include "step/guard.h"
#include "step/scratch.h"
#include "stiff_body.h"

namespace rigid_body_sim::core {
namespace {

using detail::BodyVelocity;
using detail::PartScratch;
using detail::SolverContact;
using detail::StepScratch;
using Velocities = std::vector<BodyVelocity>;

/// The velocity of `body`'s point relative to the other's along n, t₁ and
/// t₂ (Jacobian rows (d, r × d) per body: d·(v + ω × r) = d·v + ω·(r × d)).
inline Vec3 contactVelocity(const SolverContact& c, const Velocities& vel) {
  const BodyVelocity& a = vel[c.body];
  Vec3 u(c.normal_W.dot(a.v_W) + c.a.rn.dot(a.w_W), c.tangent1_W.dot(a.v_W) + c.a.rt1.dot(a.w_W),
         c.tangent2_W.dot(a.v_W) + c.a.rt2.dot(a.w_W));
  if (c.other >= 0) {
    const BodyVelocity& o = vel[c.other];
    u -= Vec3(c.normal_W.dot(o.v_W) + c.o.rn.dot(o.w_W), c.tangent1_W.dot(o.v_W) + c.o.rt1.dot(o.w_W),
              c.tangent2_W.dot(o.v_W) + c.o.rt2.dot(o.w_W));
  }
  return u;
}

inline double normalVelocity(const SolverContact& c, const Velocities& vel) {
  double u = c.normal_W.dot(vel[c.body].v_W) + c.a.rn.dot(vel[c.body].w_W);
  if (c.other >= 0) u -= c.normal_W.dot(vel[c.other].v_W) + c.o.rn.dot(vel[c.other].w_W);
  return u;
}

/// Applies the impulse λ_N n + λ₁ t₁ + λ₂ t₂ at a contact: + to `body`, − to the other.
/// A sleeper (zero terms) is not written: it may sit in several islands
/// solved at once.
inline void applyImpulse(const SolverContact& c, double ln, double l1, double l2, Velocities& vel) {
  const Vec3 P = ln * c.normal_W + l1 * c.tangent1_W + l2 * c.tangent2_W;
  if (c.a.inv_mass > 0.0) {
    vel[c.body].v_W += c.a.inv_mass * P;
    vel[c.body].w_W += ln * c.a.turn_n + l1 * c.a.turn_t1 + l2 * c.a.turn_t2;
  }
  if (c.other >= 0 && c.o.inv_mass > 0.0) {
    vel[c.other].v_W -= c.o.inv_mass * P;
    vel[c.other].w_W -= ln * c.o.turn_n + l1 * c.o.turn_t1 + l2 * c.o.turn_t2;
  }
}

/// Starts a contact from the impulse it carried last step (if it existed,
/// see matchLastImpulses), applied to the bodies before the first sweep.
void warmStart(const Contact& contact, const State& state, Velocities& vel, SolverContact& c) {
  if (contact.last_impulse < 0) return;
  const ContactImpulse last = state.contact_impulses[contact.last_impulse];
  c.normal_impulse = last.normal;
  c.tangent_impulse = Eigen::Vector2d(c.tangent1_W.dot(last.tangent_W), c.tangent2_W.dot(last.tangent_W));
  const double limit = c.friction * c.normal_impulse;
  if (c.tangent_impulse.norm() > limit) c.tangent_impulse *= limit / c.tangent_impulse.norm();
  applyImpulse(c, c.normal_impulse, c.tangent_impulse.x(), c.tangent_impulse.y(), vel);
}

/// Finds each contact's impulse of the last step: both lists are sorted by
/// key, so one merge walk does it.
void matchLastImpulses(const State& state, std::vector<Contact>& contacts) {
  const std::vector<ContactImpulse>& last = state.contact_impulses;
  std::size_t k = 0;
  for (Contact& c : contacts) {
    while (k < last.size() && last[k].key() < c.key()) ++k;
    const bool same = k < last.size() && last[k].key() == c.key();
    c.last_impulse = same ? static_cast<int>(k) : -1;
  }
}

/// One Gauss-Seidel update of one contact, on the accumulated impulses given:
/// friction first (it matters less than not sinking), then the normal to
/// reach `target` (m/s). Returns the velocity change it made (m/s). The
/// normal velocity after the friction update is u_N + nᵀKT Δλ_T, so the
/// bodies are read once and written once.
double sweepContact(const SolverSettings& settings, SolverContact& c, double& normal, Eigen::Vector2d& tangent,
                    double target, double friction, Velocities& vel) {
  const Vec3 u = contactVelocity(c, vel);
  const double rounding = settings.rounding_speed;
  if (std::abs(u.x() - target) < rounding && u.tail<2>().squaredNorm() < rounding * rounding) {
    return 0.0;  // the contact holds to rounding: an impulse now would only move λ's last bits
  }
  // Friction: stop the sliding if the cone |λ_T| ≤ μ λ_N allows; otherwise
  // slide with maximal dissipation (frictionOnDisk).
  const Eigen::Vector2d lt = detail::frictionOnDisk(
      settings, c.tangent_k, c.tangent_eigen, tangent - c.tangent_mass * u.tail<2>(), friction * normal, c.friction_nu);
  const Eigen::Vector2d dlt = lt - tangent;
  tangent = lt;
  // Normal: reach the target velocity, never pull (λ_N ≥ 0).
  const double vn = u.x() + c.normal_tangent_k.dot(dlt);
  const double ln = std::max(normal - c.normal_mass * (vn - target), 0.0);
  const double dln = ln - normal;
  normal = ln;
  applyImpulse(c, dln, dlt.x(), dlt.y(), vel);
  return (std::abs(dln) + dlt.norm()) / c.normal_mass;
}

/// For the solver contacts [first, last) of one island: prepare, warm
/// start, restitution (impact passes), projected Gauss-Seidel; then the
/// results go back to the contacts.
void solveIsland(const Model& model, int first, int last, double h, const State& state, Velocities& vel, Workspace& ws,
                 PartScratch& scratch) {
  const ContactSettings& cs = model.contact();
  const SolverSettings& settings = model.solver();
  StepScratch& sc = *ws.scratch;
  const double threshold = model.restitutionThreshold();
  SolverContact* const begin = sc.solver_contacts.data() + first;
  SolverContact* const end = sc.solver_contacts.data() + last;
  double fastest = 0.0;  // (m/s)²: the largest contact speed, each taken before its warm start
  for (int k = first; k < last; ++k) {
    const Contact& contact = ws.contacts[sc.island_contacts[k]];
    SolverContact& c = sc.solver_contacts[k];
    c.contact = sc.island_contacts[k];
    detail::prepareContact(model, state, sc, h, contact, k > first ? &c - 1 : nullptr, c);
    fastest = std::max(fastest, contactVelocity(c, vel).squaredNorm());
    warmStart(contact, state, vel, c);
  }
  // Sweeps stop once none changes a velocity by more than the velocity
  // tolerance (1e-7 m/s: 1e-10 m of drift a step, what a resting stack
  // needs), or by more than the relative tolerance (1e-6) of the fastest
  // contact's speed when the island moves (a relative residual).
  const double tolerance = std::max(settings.velocity_tolerance, settings.relative_tolerance * std::sqrt(fastest));
  // Impacts first, as a sequence of simultaneous collisions: the contacts
  // arriving faster than the threshold are solved together to separate at
  // e × their approach speed (the pre-solve speed, for the first pass).
  // If that sets other contacts approaching (an impulse passed along a row
  // of touching bodies), they collide in the next pass: Newton's cradle.
  // Each pass has its own impulses, so a collision, once resolved, does not
  // keep pushing.
  if (model.bounces()) {
    const int max_passes = 2 * (last - first) + 2;
    std::vector<int>& hit = scratch.impact_contacts;
    for (int pass = 0; pass < max_passes; ++pass) {
      hit.clear();
      for (SolverContact* c = begin; c != end; ++c) {
        const double vn = normalVelocity(*c, vel);
        const bool arrives = c->separation <= 0.0 || vn * h < -c->separation;
        if (arrives && vn < -threshold && c->restitution > 0.0) {
          c->impact_target = -c->restitution * vn;
          c->impact_normal = 0.0;
          c->impact_tangent.setZero();
          hit.push_back(static_cast<int>(c - begin));
        }
      }
      if (hit.empty()) break;
      for (int sweep = 0; sweep < cs.iterations; ++sweep) {
        double largest = 0.0;
        for (int k : hit) {
          SolverContact& c = begin[k];
          largest = std::max(
              largest, sweepContact(settings, c, c.impact_normal, c.impact_tangent, c.impact_target, c.friction, vel));
        }
        if (largest < tolerance) break;
      }
    }
  }
  // Then projected Gauss-Seidel over every contact: no penetration, Coulomb
  // friction; a speculative contact may close its gap, no more. A stiff
  // body alone against the ground (a heavy body with a small inertia) has
  // its normal impulses solved together before each sweep (stiff_body.h).
  const int stiff = detail::stiffBody(settings, sc.inverse_inertias, begin, end);
  if (stiff >= 0) sc.stiff[stiff] = 1;      // the island's own body: no other part writes it
  double recent[4] = {0.0, 0.0, 0.0, 0.0};  // the last four sweeps' largest changes
  for (int sweep = 0; sweep < cs.iterations; ++sweep) {
    if (stiff >= 0) detail::solveStiffBodyNormals(settings, sc.inverse_inertias[stiff], stiff, begin, end, vel);
    double largest = 0.0;
    for (SolverContact* c = begin; c != end; ++c) {
      largest = std::max(largest, sweepContact(settings, *c, c->normal_impulse, c->tangent_impulse,
                                               c->target_normal_velocity, c->friction, vel));
    }
    if (largest < tolerance) break;
    // Stalled: four sweeps took off less than a tenth (by default). Gauss-Seidel on
    // friction whose limit moves with the normal impulse can settle into a
    // small cycle instead of converging; more sweeps would not change it.
    if (sweep >= settings.stall_min_sweeps && largest > settings.stall_ratio * recent[sweep % 4]) break;
    recent[sweep % 4] = largest;
  }
  for (const SolverContact* c = begin; c != end; ++c) {
    Contact& contact = ws.contacts[c->contact];
    contact.normal_impulse = c->normal_impulse;
    contact.tangent_impulse_W = c->tangent_impulse.x() * c->tangent1_W + c->tangent_impulse.y() * c->tangent2_W;
    contact.predicted_separation = c->separation + h * normalVelocity(*c, vel);
  }
}

/// solveContactImpulses with contacts to solve (kept apart so that a step
/// with none does not pay for this function's set-up).
[[gnu::noinline]] void solveAll(const Model& model, State& state, double h, Workspace& ws) {
  StepScratch& sc = *ws.scratch;
  // The bodies in contact, in world axes: v, ω_W = R w_B and I⁻¹_W = R I⁻¹ Rᵀ
  // (a sleeper's velocities are zero and it has no inertia terms: it is ground).
  Velocities& vel = sc.velocities;
  vel.resize(model.bodyCount());
  sc.inverse_inertias.resize(model.bodyCount());
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    if (!sc.in_contact[i]) continue;
    const BodyState& b = state.bodies[i];
    vel[i].v_W = b.v_WB;
    vel[i].w_W = b.q_WB * b.w_B;
    if (!b.asleep) sc.inverse_inertias[i] = detail::worldInverseInertia(model.body(i), b.q_WB);
  }
  // Islands: contacts only couple bodies they join (the scene and sleepers
  // join nothing), so each island is solved on its own, to its own
  // convergence: a box still bouncing does not keep the others sweeping.
  // Islands share no body, so they split over the cores with the same result.
  matchLastImpulses(state, ws.contacts);
  if (model.bounces()) {
    detail::findPressedPairs(state, sc.pressed_pairs);
  } else {
    sc.pressed_pairs.clear();
  }
  groupContactsByIsland(model, state, ws);
  sc.stiff.assign(model.bodyCount(), 0);
  const int islands = static_cast<int>(sc.island_starts.size()) - 1;
  const int parts = islands > 1 ? detail::partsFor(ws, ws.contacts.size()) : 1;
  sc.solver_contacts.resize(ws.contacts.size());
  detail::runParts(ws, parts, [&](int part) {
    // Contiguous runs of islands holding about equal numbers of contacts:
    // each part takes the islands that start in its range of contacts.
    const Range range = partRange(ws.contacts.size(), part, parts);
    for (int k = 0; k < islands; ++k) {
      const std::size_t at = static_cast<std::size_t>(sc.island_starts[k]);
      if (at < range.begin || at >= range.end) continue;
      solveIsland(model, sc.island_starts[k], sc.island_starts[k + 1], h, state, vel, ws, sc.parts[part]);
    }
  });
  // The contacts come sorted by key (see detectContacts), and so do these.
  // A body a contact pushes (λ_N > 0) is held up, not merely touching.
  std::vector<char>& held = sc.held_still;
  held.assign(model.bodyCount(), 0);
  state.contact_impulses.clear();
  for (const Contact& c : ws.contacts) {
    state.contact_impulses.push_back({c.key(), c.normal_impulse, c.tangent_impulse_W});
    if (c.normal_impulse > 0.0) {
      held[c.body] = 1;
      if (c.other >= 0) held[c.other] = 1;
    }
  }
  // Velocities below the resting speed are rounding: zero, so that the body
  // rests exactly. A body held up and left exactly still is in equilibrium,
  // if it also came into the step still (its still time runs): a landing
  // that stops a body dead is an impact, and a body that fell asleep on it
  // kept the impact's impulse as the force that holds it up (13 N for a
  // 1 kg ball). It sleeps a step later, on a step that only holds it.
  const double resting = model.solver().resting_speed;
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    BodyState& b = state.bodies[i];
    if (!sc.in_contact[i] || b.asleep) continue;
    if (vel[i].v_W.squaredNorm() < resting * resting && vel[i].w_W.squaredNorm() < resting * resting) {
      b.v_WB.setZero();
      b.w_B.setZero();
      if (!(b.still_time > 0.0)) held[i] = 0;
      continue;
    }
    held[i] = 0;
    b.v_WB = vel[i].v_W;
    b.w_B = b.q_WB.conjugate() * vel[i].w_W;
    limitSpeeds(model, static_cast<int>(i), b, ws);
  }
}

}  // namespace

bool solveContactImpulses(const Model& model, State& state, double h, Workspace& ws) {
  if (model.contact().method != ContactMethod::kImpulse || ws.contacts.empty()) {
    state.contact_impulses.clear();  // nothing to warm-start from next time
    return false;
  }
  solveAll(model, state, h, ws);
  return true;
}

}  // namespace rigid_body_sim::core
