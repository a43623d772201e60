// The integration stages (docs/physics.md §5.2–§5.4 and §5.6–§5.7).
#include "integration.h"

#include <cmath>

#include "guard.h"
#include "scratch.h"
#include "sleep.h"

namespace rigid_body_sim::core {
namespace {

/// Solves one implicit-midpoint step of the torque-free Euler equation
/// Π̇ = Π × I⁻¹Π (Π = I Ω, body frame) for u = Π + Π_{n+1}:
///   u = 2Π + u × (c ∘ u),  c = (h/4) I⁻¹   (fixed-point iteration)
/// The iteration contracts by about h|Ω| per pass: 4 passes at 1 ms and
/// 3 rad/s. Returns false if it does not converge (h|Ω| too large).
bool solveMidpoint(const Vec3& Pi, const Vec3& c, Vec3& u) {
  const Vec3 two_pi = 2.0 * Pi;
  const double tol2 = SolverSettings::kGyroscopicTolerance2 * two_pi.squaredNorm();  // |Δu| ≤ 1e-12 |u| by default
  u = two_pi;
  for (int i = 0; i < SolverSettings::kGyroscopicIterations; ++i) {
    const Vec3 next = two_pi + u.cross(c.cwiseProduct(u));
    const double d2 = (next - u).squaredNorm();
    u = next;
    if (d2 <= tol2) return true;
    if (!std::isfinite(d2)) return false;
  }
  return false;
}

}  // namespace

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
void integrateVelocity(const Model& model, const BodyModel& b, const NetLoad& net, double h, BodyState& s) {
  s.v_WB += h * (model.gravity() + b.inv_mass * net.force_W);
  s.w_B += h * b.inv_inertia_B.cwiseProduct(net.torque_B);
}

// v ← e^(−k h) v: a decay rate, independent of h (docs/physics.md §5.4).
void applyDamping(const Model& model, double h, BodyState& s) {
  const Damping& d = model.damping();
  if (d.linear != 0.0) s.v_WB *= h == model.dt() ? model.linearDecay() : std::exp(-d.linear * h);
  if (d.angular != 0.0) s.w_B *= h == model.dt() ? model.angularDecay() : std::exp(-d.angular * h);
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
// variants drift about 1% in energy over 20 s (bench/HISTORY.md).
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
    if (converged || substeps >= SolverSettings::kGyroscopicMaxSubsteps) {
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

namespace {

/// The awake bodies in [begin, end): first the guard (§5.9), then rotation
/// (with the gyroscopic term), position, orientation, and the time they
/// have been still.
void integrateBodies(const Model& model, State& state, double h, std::size_t begin, std::size_t end, Workspace& ws) {
  for (std::size_t i = begin; i < end; ++i) {
    BodyState& s = state.bodies[i];
    if (s.asleep) continue;
    // The guard (§5.9): only the velocity stages ran since the step began,
    // so a body not finite here still has its last finite pose, and keeps it.
    if (!finiteState(s)) {
      putBack(static_cast<int>(i), s, ws);
      continue;
    }
    integrateBody(model, model.body(i), h, s);
    updateStillTime(model, h, s);
  }
}

/// integrateVelocities with loads, drag or penalty forces. Flattened as
/// integrateBodies is: the per-body functions inlined into the loop.
[[gnu::flatten]] void integrateForces(const Model& model, State& state, const Loads& loads, double h, Workspace& ws) {
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    BodyState& s = state.bodies[i];
    if (s.asleep) continue;
    const NetLoad net = accumulateForces(model, state, loads.empty() ? nullptr : &loads[i], ws, static_cast<int>(i));
    integrateVelocity(model, model.body(i), net, h, s);
    applyDamping(model, h, s);
    limitSpeeds(model, static_cast<int>(i), s, ws);
  }
}

}  // namespace

void integrateBody(const Model& model, const BodyModel& b, double h, BodyState& s) {
  if (s.w_B.isZero(0.0)) {  // no rotation: q stays as it is (normalizing it again would move its last bits)
    integratePosition(h, s);
  } else {
    const Quat rotation = gyroscopicRotation(model, b, h, s);
    integratePosition(h, s);
    integrateOrientation(rotation, s);
  }
}

void integrateVelocities(const Model& model, State& state, const Loads& loads, double h, Workspace& ws) {
  const Damping& d = model.damping();
  // Without loads, drag or penalty contacts the only force is gravity.
  const bool penalty = !ws.contacts.empty() && model.contact().method != ContactMethod::kImpulse;
  if (!loads.empty() || d.linear_drag != 0.0 || d.angular_drag != 0.0 || penalty) {
    integrateForces(model, state, loads, h, ws);
    return;
  }
  // Gravity alone changes only v: ω needs no look (it was limited when it changed).
  const double linear2 = model.limits().max_linear_speed * model.limits().max_linear_speed;
  for (std::size_t i = 0; i < state.bodies.size(); ++i) {
    BodyState& s = state.bodies[i];
    if (s.asleep) continue;
    s.v_WB += h * model.gravity();
    applyDamping(model, h, s);
    if (!(s.v_WB.squaredNorm() <= linear2)) limitSpeeds(model, static_cast<int>(i), s, ws);
  }
}

void integratePositions(const Model& model, State& state, double h, Workspace& ws) {
  // Body by body, each on its own: split over the cores when enough are awake.
  const std::size_t n = model.bodyCount();
  std::size_t awake = n;
  if (n > 1) {
    for (const BodyState& s : state.bodies) awake -= s.asleep;
  }
  const int parts = n > 1 ? detail::partsFor(ws, awake) : 1;
  if (parts == 1) {
    integrateBodies(model, state, h, 0, n, ws);
    return;
  }
  detail::runParts(ws, parts, [&](int part) {
    const Range r = partRange(n, part, parts);
    integrateBodies(model, state, h, r.begin, r.end, ws);
  });
}

}  // namespace rigid_body_sim::core
