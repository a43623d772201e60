// The simulator loop of the notes (rigid_body_notes.md, "Simulator loop"),
// one named stage per line of step(), plus the gyroscopic term the notes
// leave out (ERRATA.md).
#include "rigid_body_sim/core/step.h"

#include <cmath>

namespace rigid_body_sim::core {
namespace {

/// External and drag loads on one body for this step (gravity is applied as
/// an acceleration, so free fall is exactly v += Δt g).
struct NetLoad {
  Vec3 force_W;   ///< N, world frame
  Vec3 torque_B;  ///< N·m, body frame
};

// F = −σ v + F_ext,  τ = −σ_ω ω + τ_ext; the notes' τᵢ = (R rᵢ) × Fᵢ has
// been reduced to the centre of mass by addWrench().
NetLoad accumulateForces(const Damping& damping, const BodyState& s, const BodyLoad* load) {
  NetLoad net{Vec3::Zero(), Vec3::Zero()};
  if (damping.linear_drag != 0.0) net.force_W = -damping.linear_drag * s.v_WB;
  if (damping.angular_drag != 0.0) net.torque_B = -damping.angular_drag * s.w_B;
  if (load != nullptr) {
    net.force_W += load->force_W + s.q_WB * load->force_B;
    net.torque_B += load->torque_B + s.q_WB.conjugate() * load->torque_W;
  }
  return net;
}

// v_{n+1} = v_n + Δt (g + F/M);  ω_{n+1} = ω_n + Δt I⁻¹ τ.
// In the body frame I is constant and diagonal: the notes' I_n = R I_ref Rᵀ
// and its inverse are never formed.
void integrateVelocities(const Model& model, const BodyModel& b, const NetLoad& net, BodyState& s) {
  const double dt = model.dt();
  s.v_WB += dt * (model.gravity() + b.inv_mass * net.force_W);
  s.w_B += dt * b.inv_inertia_B.cwiseProduct(net.torque_B);
}

// v ← α v with α = e^(−k Δt): the notes' decay coefficient, made independent of Δt.
void applyDamping(const Model& model, BodyState& s) {
  if (model.linearDecay() != 1.0) s.v_WB *= model.linearDecay();
  if (model.angularDecay() != 1.0) s.w_B *= model.angularDecay();
}

/// Solves one implicit-midpoint step of the torque-free Euler equation
/// Π̇ = Π × I⁻¹Π (Π = I Ω, body frame) over h, for u = Π + Π_{n+1}:
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

// The gyroscopic term −ω × (I ω) of Euler's equation, which the notes leave
// out. Returns the body-frame rotation of this step as the (unnormalized)
// quaternion increment [1, Δt/2 Ω] and updates w_B.
//
// Why implicit midpoint: it conserves both quadratic invariants of the free
// rigid body, |Π| and the energy ½ ΠᵀI⁻¹Π, and its update is exactly
// Π_{n+1} = cay(−Δt Ω̂_m) Π_n with Ω_m = I⁻¹(Π_n + Π_{n+1})/2. Rotating the
// body by cay(Δt Ω̂_m), which is the notes' quaternion update evaluated with
// Ω_m, therefore leaves the world angular momentum R Π unchanged. First-order
// variants drift about 1% in energy over 20 s (bench/README.md).
// Gyroscopic off: Ω = ω_{n+1}, the notes exactly.
Quat gyroscopicRotation(const Model& model, const BodyModel& b, BodyState& s) {
  const double dt = model.dt();
  if (!model.gyroscopic()) {
    const Vec3 h = 0.5 * dt * s.w_B;
    return Quat(1.0, h.x(), h.y(), h.z());
  }
  // Sub-step only when one step is too large for the iteration to contract;
  // every sub-step conserves the invariants, so the result stays exact.
  for (int substeps = 1;; substeps *= 2) {
    const Vec3 c = (0.25 * dt / substeps) * b.inv_inertia_B;
    Vec3 w = s.w_B;
    Quat increment = Quat::Identity();
    bool converged = true;
    for (int k = 0; k < substeps && converged; ++k) {
      const Vec3 Pi = b.inertia_B.cwiseProduct(w);
      Vec3 u;
      converged = solveMidpoint(Pi, c, u);
      w = b.inv_inertia_B.cwiseProduct(u - Pi);  // Ω_{n+1} = I⁻¹ Π_{n+1}
      const Vec3 h = c.cwiseProduct(u);          // Δt/2 Ω_m = (Δt/4) I⁻¹ u
      increment = increment * Quat(1.0, h.x(), h.y(), h.z());
    }
    if (converged || substeps >= (1 << 16)) {
      if (w.allFinite()) s.w_B = w;
      return increment;
    }
  }
}

// x_{n+1} = x_n + Δt v_{n+1}.
void integratePosition(double dt, BodyState& s) { s.p_WB += dt * s.v_WB; }

// q_{n+1} = q_n + [0, Δt/2 ω] × q_n, then normalize (ERRATA: it drifts off
// the unit sphere otherwise).
void integrateOrientation(const Quat& increment, BodyState& s) {
  s.q_WB = s.q_WB * increment;
  s.q_WB.coeffs() *= 1.0 / std::sqrt(s.q_WB.squaredNorm());
}

}  // namespace

void step(const Model& model, State& state, const Loads& loads) {
  const Damping& damping = model.damping();
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    const BodyModel& body = model.bodies()[i];
    BodyState& s = state.bodies[i];
    const NetLoad net = accumulateForces(damping, s, loads.empty() ? nullptr : &loads[i]);
    integrateVelocities(model, body, net, s);
    applyDamping(model, s);
    const Quat rotation = gyroscopicRotation(model, body, s);
    integratePosition(model.dt(), s);
    integrateOrientation(rotation, s);
  }
  state.time += model.dt();
}

}  // namespace rigid_body_sim::core
