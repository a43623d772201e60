// The measurement behind the gyroscopic integrator (issue 2: "measure and
// choose"). Runs the issue's flipping spin, the box of half extents
// 0.2 × 0.1 × 0.05 m, 1 kg, from ω₀ = (0.01, 3, 0) for 20 s, with:
//   notes          no gyroscopic term, as the original notes (core, gyroscopic: false)
//   world-L Euler  L carried in the world, ω = R I⁻¹ Rᵀ L at the new orientation
//   world-L mid    L in the world, ω evaluated at the mid-step orientation
//   Bullet         implicit Euler in the body frame, one Newton step (Bullet's default)
//   implicit mid   the core's integrator (gyroscopic: true)
// and prints, per Δt, the relative change of energy and |L| over the run, the
// number of flips (sign changes of ω_y in the body frame) and the first flip
// time against the closed form (Landau & Lifshitz §37).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

#include "rigid_body_sim/core/step/diagnostics.h"
#include "rigid_body_sim/core/step/step.h"

namespace {

using namespace rigid_body_sim::core;

const Vec3 kI(0.0125 / 3.0, 0.0425 / 3.0, 0.05 / 3.0);  // principal moments, kg·m²
const Vec3 kW0(0.01, 3.0, 0.0);
constexpr double kDuration = 20.0;

/// Orientation and body-frame angular velocity; the variants below advance it.
struct Spin {
  Quat q = Quat::Identity();
  Vec3 w_B = kW0;
};

Quat cayley(const Quat& q, const Vec3& h_B) { return (q * Quat(1.0, h_B.x(), h_B.y(), h_B.z())).normalized(); }

void worldLEuler(Spin& s, double dt) {
  const Vec3 L_W = s.q * kI.cwiseProduct(s.w_B);
  s.q = cayley(s.q, 0.5 * dt * s.w_B);
  s.w_B = kI.cwiseInverse().cwiseProduct(s.q.conjugate() * L_W);
}

void worldLMidpoint(Spin& s, double dt) {
  const Vec3 L_W = s.q * kI.cwiseProduct(s.w_B);
  const Quat q_mid = cayley(s.q, 0.25 * dt * s.w_B);
  const Vec3 w_mid = kI.cwiseInverse().cwiseProduct(q_mid.conjugate() * L_W);
  s.q = cayley(s.q, 0.5 * dt * w_mid);
  s.w_B = kI.cwiseInverse().cwiseProduct(s.q.conjugate() * L_W);
}

void bulletImplicitEuler(Spin& s, double dt) {
  // Solve I (ω' − ω)/Δt + ω' × I ω' = 0 with one Newton step from ω.
  const Vec3 w = s.w_B;
  const Vec3 f = dt * w.cross(kI.cwiseProduct(w));
  const Mat3 J = Mat3(kI.asDiagonal()) + dt * (skew(w) * kI.asDiagonal() - skew(kI.cwiseProduct(w)));
  s.w_B = w - J.inverse() * f;
  s.q = cayley(s.q, 0.5 * dt * s.w_B);
}

struct Result {
  double energy_change, momentum_change, first_flip, ns_per_step;
  int flips;
};

Result run(const std::function<void(Spin&)>& advance, double dt) {
  Spin s;
  const auto energy = [](const Spin& x) { return 0.5 * x.w_B.dot(kI.cwiseProduct(x.w_B)); };
  const auto momentum = [](const Spin& x) { return kI.cwiseProduct(x.w_B).norm(); };
  const double e0 = energy(s), l0 = momentum(s);
  Result r{0, 0, -1, 0, 0};
  const long steps = std::lround(kDuration / dt);
  double prev = s.w_B.y();
  const auto t0 = std::chrono::steady_clock::now();
  for (long n = 0; n < steps; ++n) {
    advance(s);
    if ((prev > 0) != (s.w_B.y() > 0)) {
      if (r.flips++ == 0) r.first_flip = n * dt + dt * prev / (prev - s.w_B.y());
    }
    prev = s.w_B.y();
  }
  r.ns_per_step = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / steps;
  r.energy_change = energy(s) / e0 - 1.0;
  r.momentum_change = momentum(s) / l0 - 1.0;
  return r;
}

std::function<void(Spin&)> core(bool gyroscopic, double dt) {
  ModelSpec spec;
  BodySpec b;
  b.I_C_L = kI.asDiagonal();
  spec.bodies = {b};
  spec.dt = dt;
  spec.gravity_W = Vec3::Zero();
  spec.gyroscopic = gyroscopic;
  auto model = std::make_shared<Model>(spec);
  auto state = std::make_shared<State>(restState(*model));
  return [model, state](Spin& s) {
    BodyState& b = state->bodies[0];
    b.q_WB = s.q;
    b.w_B = s.w_B;
    step(*model, *state);
    s.q = b.q_WB;
    s.w_B = b.w_B;
  };
}

double closedFormFirstFlip() {
  const double I1 = kI.x(), I2 = kI.y(), I3 = kI.z();
  const double L2 = kI.cwiseProduct(kW0).squaredNorm(), E2 = kW0.dot(kI.cwiseProduct(kW0));
  // L² < 2EI₂ here: the axes-1-and-3-exchanged form.
  const double nu = std::sqrt((I2 - I1) * (E2 * I3 - L2) / (I1 * I2 * I3));
  const double k2 = (I3 - I2) * (L2 - E2 * I1) / ((I2 - I1) * (E2 * I3 - L2));
  return std::comp_ellint_1(std::sqrt(k2)) / nu;
}

}  // namespace

int main() {
  const double first = closedFormFirstFlip();
  std::printf("closed form: first flip at %.4f s, then every %.4f s (3 flips in 20 s)\n", first, 2 * first);
  std::printf("%-14s %6s %12s %12s %6s %11s %8s\n", "variant", "dt", "dE/E", "d|L|/|L|", "flips", "first flip",
              "ns/step");
  for (double dt : {1e-3, 1e-2}) {
    const struct {
      const char* name;
      std::function<void(Spin&)> advance;
    } variants[] = {
        {"notes", core(false, dt)},
        {"world-L Euler", [dt](Spin& s) { worldLEuler(s, dt); }},
        {"world-L mid", [dt](Spin& s) { worldLMidpoint(s, dt); }},
        {"Bullet", [dt](Spin& s) { bulletImplicitEuler(s, dt); }},
        {"implicit mid", core(true, dt)},
    };
    for (const auto& v : variants) {
      const Result r = run(v.advance, dt);
      std::printf("%-14s %6g %12.2e %12.2e %6d %11.4f %8.1f\n", v.name, dt, r.energy_change, r.momentum_change, r.flips,
                  r.first_flip, r.ns_per_step);
    }
  }
}
