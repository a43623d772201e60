// The simulator loop, one named stage per line of advance(), in the order of
// docs/physics.md §4: Euler-Cromer integration with the gyroscopic term,
// contacts and sleep.
#include "rigid_body_sim/core/step.h"

#include <cmath>
#include <cstring>
#include <memory>

#include "rigid_body_sim/core/contact.h"
#include "rigid_body_sim/core/shape_matching.h"

namespace rigid_body_sim::core {
namespace {

/// External, drag and penalty loads on one body for this step (gravity is
/// applied as an acceleration, so free fall is exactly v += h g).
struct NetLoad {
  Vec3 force_W = Vec3::Zero();   ///< N, world frame
  Vec3 torque_B = Vec3::Zero();  ///< N·m, body frame
};

// A load, an impulse or a new state wakes a sleeping body (impulses and
// states do it themselves; loads here).
void wakeLoadedBodies(State& state, const Loads& loads) {
  for (std::size_t i = 0; i < loads.size() && i < state.bodies.size(); ++i) {
    BodyState& s = state.bodies[i];
    if (s.asleep && !loads[i].isZero()) {
      s.asleep = false;
      s.still_time = 0.0;
    }
  }
}

// F = −σ v + F_ext (+ penalty),  τ = −σ_ω ω + τ_ext (+ penalty) (docs/physics.md
// §5.2); a force's r × F has been reduced to the centre of mass by addWrench().
NetLoad accumulateForces(const Model& model, const State& state, const BodyLoad* load, const Workspace& ws, int body) {
  const Damping& damping = model.damping();
  const BodyState& s = state.bodies[body];
  NetLoad net;
  if (damping.linear_drag != 0.0) net.force_W = -damping.linear_drag * s.v_WB;
  if (damping.angular_drag != 0.0) net.torque_B = -damping.angular_drag * s.w_B;
  Vec3 torque_W = Vec3::Zero();
  if (load != nullptr) {
    net.force_W += load->force_W + s.q_WB * load->force_B;
    net.torque_B += load->torque_B;
    torque_W += load->torque_W;
  }
  const ContactMethod method = model.contact().method;
  const bool penalty = method == ContactMethod::kPenaltyQuadratic || method == ContactMethod::kPenaltyLogBarrier;
  if (penalty && !ws.contacts.empty()) accumulatePenaltyForces(model, state, ws, body, net.force_W, torque_W);
  if (load != nullptr || penalty) net.torque_B += s.q_WB.conjugate() * torque_W;
  return net;
}

// v_{n+1} = v_n + h (g + F/M);  ω_{n+1} = ω_n + h I⁻¹ τ (docs/physics.md §5.3).
// In the body frame I is constant and diagonal: the world tensor R I Rᵀ and
// its inverse are never formed.
void integrateVelocities(const Model& model, const BodyModel& b, const NetLoad& net, double h, BodyState& s) {
  s.v_WB += h * (model.gravity() + b.inv_mass * net.force_W);
  s.w_B += h * b.inv_inertia_B.cwiseProduct(net.torque_B);
}

// v ← e^(−k h) v: a decay rate, independent of h (docs/physics.md §5.4).
void applyDamping(const Model& model, double h, BodyState& s) {
  const Damping& d = model.damping();
  if (d.linear_rate != 0.0) s.v_WB *= h == model.dt() ? model.linearDecay() : std::exp(-d.linear_rate * h);
  if (d.angular_rate != 0.0) s.w_B *= h == model.dt() ? model.angularDecay() : std::exp(-d.angular_rate * h);
}

/// Solves one implicit-midpoint step of the torque-free Euler equation
/// Π̇ = Π × I⁻¹Π (Π = I Ω, body frame) for u = Π + Π_{n+1}:
///   u = 2Π + u × (c ∘ u),  c = (h/4) I⁻¹   (fixed-point iteration)
/// The iteration contracts by about h|Ω| per pass: 4 passes at 1 ms and
/// 3 rad/s. Returns false if it does not converge (h|Ω| too large).
bool solveMidpoint(const Vec3& Pi, const Vec3& c, Vec3& u) {
  constexpr int kMaxIterations = 40;
  constexpr double kRelTol2 = 1e-24;  // |Δu| ≤ 1e-12 |u|
  const Vec3 two_pi = 2.0 * Pi;
  const double tol2 = kRelTol2 * two_pi.squaredNorm();
  u = two_pi;
  for (int i = 0; i < kMaxIterations; ++i) {
    const Vec3 next = two_pi + u.cross(c.cwiseProduct(u));
    const double d2 = (next - u).squaredNorm();
    u = next;
    if (d2 <= tol2) return true;
    if (!std::isfinite(d2)) return false;
  }
  return false;
}

// The gyroscopic term −ω × (I ω) of Euler's equation (docs/physics.md §5.6).
// Returns the body-frame rotation of this step as the (unnormalized)
// quaternion increment [1, h/2 Ω] and updates w_B.
//
// Why implicit midpoint: it conserves both quadratic invariants of the free
// rigid body, |Π| and the energy ½ ΠᵀI⁻¹Π, and its update is exactly
// Π_{n+1} = cay(−h Ω̂_m) Π_n with Ω_m = I⁻¹(Π_n + Π_{n+1})/2. Rotating the
// body by cay(h Ω̂_m), which is the quaternion update of §5.7 evaluated with
// Ω_m, therefore leaves the world angular momentum R Π unchanged. First-order
// variants drift about 1% in energy over 20 s (bench/README.md).
// Gyroscopic off: Ω = ω_{n+1}, exact only for isotropic inertia.
Quat gyroscopicRotation(const Model& model, const BodyModel& b, double h, BodyState& s) {
  if (!model.gyroscopic()) {
    const Vec3 half = 0.5 * h * s.w_B;
    return Quat(1.0, half.x(), half.y(), half.z());
  }
  // Sub-step only when one step is too large for the iteration to contract;
  // every sub-step conserves the invariants, so the result stays exact.
  for (int substeps = 1;; substeps *= 2) {
    const Vec3 c = (0.25 * h / substeps) * b.inv_inertia_B;
    Vec3 w = s.w_B;
    Quat increment = Quat::Identity();
    bool converged = true;
    for (int k = 0; k < substeps && converged; ++k) {
      const Vec3 Pi = b.inertia_B.cwiseProduct(w);
      Vec3 u;
      converged = solveMidpoint(Pi, c, u);
      w = b.inv_inertia_B.cwiseProduct(u - Pi);  // Ω_{n+1} = I⁻¹ Π_{n+1}
      const Vec3 half = c.cwiseProduct(u);       // h/2 Ω_m = (h/4) I⁻¹ u
      increment = increment * Quat(1.0, half.x(), half.y(), half.z());
    }
    if (converged || substeps >= (1 << 16)) {
      if (w.allFinite()) s.w_B = w;
      return increment;
    }
  }
}

// x_{n+1} = x_n + h v_{n+1}.
void integratePosition(double h, BodyState& s) { s.p_WB += h * s.v_WB; }

// q_{n+1} = q_n ⊗ [1, h/2 Ω], then normalize: the update drifts off the unit
// sphere otherwise (docs/physics.md §5.7).
void integrateOrientation(const Quat& increment, BodyState& s) {
  s.q_WB = s.q_WB * increment;
  s.q_WB.coeffs() *= 1.0 / std::sqrt(s.q_WB.squaredNorm());
}

/// The awake bodies in [begin, end): rotation (with the gyroscopic term),
/// position, orientation, and the time they have been still.
void integrateBodies(const Model& model, State& state, double h, std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) {
    BodyState& s = state.bodies[i];
    if (s.asleep) continue;
    if (s.w_B.isZero(0.0)) {  // no rotation: q stays as it is (normalizing it again would move its last bits)
      integratePosition(h, s);
    } else {
      const Quat rotation = gyroscopicRotation(model, model.body(i), h, s);
      integratePosition(h, s);
      integrateOrientation(rotation, s);
    }
    updateStillTime(model, h, s);
  }
}

/// Sleep by islands, as Box2D does: bodies joined by contacts fall asleep
/// together, once every one of them has been still for the sleep time while
/// touching something, or is held exactly still (Workspace::held_still: the
/// sleep time only guards the loose sleep speeds, and exactly zero is
/// equilibrium, not the turning point of a bounce). A body alone would
/// otherwise fall asleep under a neighbour still settling on it, and the
/// neighbour's next jolt would wake it again, over and over. The islands are
/// those of the impulse solve when it ran (no body has changed sleep state
/// since).
void sleepIslands(const Model& model, State& state, Workspace& ws, bool islands_known) {
  if (!model.sleep().enabled || ws.contacts.empty()) return;  // nothing touches: nothing sleeps
  if (!islands_known) findIslands(model, state, ws);
  std::vector<char>& ready = ws.island_flags;  // per root: every body of the island may sleep
  ready.assign(model.bodyCount(), 1);
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    const BodyState& s = state.bodies[i];
    const bool held = islands_known && ws.held_still[i];
    if (!s.asleep && !held && !readyToSleep(model, ws.in_contact[i] != 0, s)) ready[ws.island_root[i]] = 0;
  }
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    BodyState& s = state.bodies[i];
    if (!s.asleep && ready[ws.island_root[i]]) fallAsleep(s);
  }
}

/// One step of length h of every awake body: the stages in order. Returns
/// whether the impulse solve ran (its islands are then in the workspace).
bool advance(const Model& model, State& state, const Loads& loads, double h, Workspace& ws) {
  const std::size_t n = model.bodyCount();
  if (!model.scene().empty() || n > 1) {
    detectContacts(model, state, h, ws);
    // A woken body takes part from this step on: detect again with it awake.
    if (n > 1 && wakeTouchedSleepers(model, state, ws, h)) detectContacts(model, state, h, ws);
  } else {
    ws.contacts.clear();
    ws.in_contact.clear();
    ws.deepest_penetration = 0.0;
  }
  const bool impulse = model.contact().method == ContactMethod::kImpulse && !ws.contacts.empty();
  const Damping& d = model.damping();
  // Without loads, drag or penalty contacts the only force is gravity.
  const bool forces =
      !loads.empty() || d.linear_drag != 0.0 || d.angular_drag != 0.0 || (!ws.contacts.empty() && !impulse);
  for (std::size_t i = 0; i < n; ++i) {
    BodyState& s = state.bodies[i];
    if (s.asleep) continue;
    if (forces) {
      const NetLoad net = accumulateForces(model, state, loads.empty() ? nullptr : &loads[i], ws, static_cast<int>(i));
      integrateVelocities(model, model.body(i), net, h, s);
    } else {
      s.v_WB += h * model.gravity();
    }
    applyDamping(model, h, s);
  }
  if (impulse) {
    solveContactImpulses(model, state, h, ws);
  } else if (!state.contact_impulses.empty()) {
    state.contact_impulses.clear();  // nothing to warm-start from next time
  }
  // Body by body, each on its own: split over the cores when enough are awake.
  std::size_t awake = n;
  if (n > 1) {
    for (const BodyState& s : state.bodies) awake -= s.asleep;
  }
  const int parts = n > 1 ? partsFor(ws, awake) : 1;
  if (parts == 1) {
    integrateBodies(model, state, h, 0, n);
  } else {
    runParts(ws, parts, [&](int part) { integrateBodies(model, state, h, n * part / parts, n * (part + 1) / parts); });
  }
  if (impulse) correctPositions(model, state, ws);
  sleepIslands(model, state, ws, impulse);
  return impulse;
}

/// The log-barrier method needs φ > 0 at every contact point at all times,
/// and its force ρ/φ is stiff: taken explicitly over a step in which φ
/// changes a lot, it pumps energy in. So a step is taken again as two half
/// steps (step control) if any body's smallest φ inside the buffer would
/// reach 0, or shrink or grow by more than a factor of two.
void advanceKeepingBarrier(const Model& model, State& state, const Loads& loads, double h, Workspace& ws, int depth) {
  constexpr int kMaxHalvings = 20;
  const double buffer = model.contact().barrier_buffer;
  const State before = state;
  advance(model, state, loads, h, ws);
  bool redo = false;
  for (std::size_t i = 0; i < model.bodyCount() && !redo; ++i) {
    const int body = static_cast<int>(i);
    const double was = minSeparation(model, before.bodies[i], body, buffer);
    const double now = minSeparation(model, state.bodies[i], body, buffer);
    if (std::isinf(was) && std::isinf(now)) continue;  // outside the buffer throughout
    redo = !(now > 0.0) || (!std::isinf(was) && !std::isinf(now) && (now < 0.5 * was || now > 2.0 * was)) ||
           (std::isinf(was) && now < 0.5 * buffer);
  }
  if (!redo || depth >= kMaxHalvings) return;
  state = before;
  advanceKeepingBarrier(model, state, loads, 0.5 * h, ws, depth + 1);
  advanceKeepingBarrier(model, state, loads, 0.5 * h, ws, depth + 1);
}

// A step that returns its input unchanged (Workspace::FixedPoint). Compared
// bit for bit, not with ==, which would take −0.0 for +0.0.
template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// Everything a body brings into the step but its still time.
bool sameMotion(const BodyState& a, const BodyState& b) {
  return sameBits(a.p_WB, b.p_WB) && sameBits(a.v_WB, b.v_WB) && sameBits(a.q_WB.coeffs(), b.q_WB.coeffs()) &&
         sameBits(a.w_B, b.w_B) && a.asleep == b.asleep;
}

bool sameImpulse(const ContactImpulse& a, const ContactImpulse& b) {
  return a.body == b.body && a.other == b.other && a.item == b.item && a.point == b.point &&
         sameBits(a.normal, b.normal) && sameBits(a.tangent_W, b.tangent_W);
}

/// The step's whole input but the time and the still times (which only
/// decide sleep, and which the repeated step updates as a computed one would).
bool sameInput(const Workspace::FixedPoint& f, const Model& model, const State& state, const Loads& loads) {
  if (f.model != &model || f.bodies.size() != state.bodies.size() ||
      f.impulses.size() != state.contact_impulses.size() || f.loads.size() != loads.size()) {
    return false;
  }
  for (std::size_t i = 0; i < f.bodies.size(); ++i) {
    if (!sameMotion(f.bodies[i], state.bodies[i])) return false;
  }
  for (std::size_t i = 0; i < f.impulses.size(); ++i) {
    if (!sameImpulse(f.impulses[i], state.contact_impulses[i])) return false;
  }
  for (std::size_t i = 0; i < f.loads.size(); ++i) {
    if (!sameBits(f.loads[i], loads[i])) return false;
  }
  return true;
}

/// Below the sleep speeds after the last step: the only worlds that can be
/// at a fixed point, and the only ones worth keeping the input for.
bool everyAwakeBodyStill(const State& state) {
  for (const BodyState& s : state.bodies) {
    if (!s.asleep && !(s.still_time > 0.0)) return false;
  }
  return true;
}

/// advance(), or, when the last step returned this same input unchanged,
/// what advance() would do again: nothing but the still times and sleep.
void advanceOrRepeat(const Model& model, State& state, const Loads& loads, double h, Workspace& ws) {
  Workspace::FixedPoint& f = ws.fixed_point;
  if (ws.skip_fixed_points && f.holds && sameInput(f, model, state, loads)) {
    for (BodyState& s : state.bodies) {
      if (!s.asleep) updateStillTime(model, h, s);
    }
    sleepIslands(model, state, ws, f.islands_known);
    ++ws.skipped_steps;
    return;
  }
  const bool keep = ws.skip_fixed_points && everyAwakeBodyStill(state);
  f.holds = false;
  if (keep) {
    f.model = &model;
    f.bodies = state.bodies;
    f.impulses = state.contact_impulses;
    f.loads = loads;
  }
  f.islands_known = advance(model, state, loads, h, ws);
  f.holds = keep && sameInput(f, model, state, loads);
}

}  // namespace

void step(const Model& model, State& state, const Loads& loads, Workspace* workspace) {
  std::unique_ptr<Workspace> local;  // only built when the caller brings none (not on the stack: it is large)
  if (workspace == nullptr) local = std::make_unique<Workspace>();
  Workspace& ws = workspace != nullptr ? *workspace : *local;
  const double h = model.dt();
  wakeLoadedBodies(state, loads);
  switch (model.contact().method) {
    case ContactMethod::kShapeMatching:
      ws.fixed_point.holds = false;  // these leave other contents in the workspace
      stepShapeMatching(model, state, loads, h, ws);
      break;
    case ContactMethod::kPenaltyLogBarrier:
      ws.fixed_point.holds = false;
      advanceKeepingBarrier(model, state, loads, h, ws, 0);
      break;
    default:
      advanceOrRepeat(model, state, loads, h, ws);
      break;
  }
  state.time += h;
}

}  // namespace rigid_body_sim::core
