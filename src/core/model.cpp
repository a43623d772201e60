#include "rigid_body_sim/core/model.h"

#include <cmath>

#include "rigid_body_sim/core/inertia.h"
#include "validate.h"

namespace rigid_body_sim::core {
namespace {

BodyModel buildBody(const BodySpec& spec) {
  const std::string where = "body '" + spec.name + "': ";
  detail::requirePositive(spec.mass, where + "mass", "kg");
  detail::requireFinite(spec.p_LC, where + "centre of mass");
  validateInertia(spec.I_C_L, where + "inertia");

  BodyModel b;
  b.name = spec.name;
  b.mass = spec.mass;
  b.inv_mass = 1.0 / spec.mass;
  b.p_LB = spec.p_LC;
  b.I_C_L = spec.I_C_L;
  const PrincipalAxes pa = principalAxes(spec.I_C_L);
  b.q_LB = pa.q_FP;
  b.inertia_B = pa.moments;
  b.inv_inertia_B = pa.moments.cwiseInverse();
  return b;
}

void validateDamping(const Damping& d, double dt, const std::vector<BodyModel>& bodies) {
  detail::requireNonNegative(d.linear_rate, "damping.linear", "1/s");
  detail::requireNonNegative(d.angular_rate, "damping.angular", "1/s");
  detail::requireNonNegative(d.linear_drag, "damping.linear_drag", "N·s/m");
  detail::requireNonNegative(d.angular_drag, "damping.angular_drag", "N·m·s/rad");
  // The explicit drag step v ← v (1 − σΔt/M) reverses v when σΔt/M ≥ 1.
  for (const BodyModel& b : bodies) {
    const double lin = d.linear_drag * dt * b.inv_mass;
    const double ang = d.angular_drag * dt * b.inv_inertia_B.maxCoeff();
    if (lin >= 1.0) {
      detail::fail("damping.linear_drag", detail::str(d.linear_drag),
                   "σ·dt/mass = " + detail::str(lin) + " >= 1 for body '" + b.name +
                       "' (explicit drag would reverse the velocity; use damping.linear, a decay rate)");
    }
    if (ang >= 1.0) {
      detail::fail("damping.angular_drag", detail::str(d.angular_drag),
                   "σ·dt/I_min = " + detail::str(ang) + " >= 1 for body '" + b.name +
                       "' (explicit drag would reverse the spin; use damping.angular, a decay rate)");
    }
  }
}

}  // namespace

Model::Model(const ModelSpec& spec)
    : dt_(spec.dt), gravity_W_(spec.gravity_W), damping_(spec.damping), gyroscopic_(spec.gyroscopic) {
  if (spec.bodies.empty()) detail::fail("bodies", "[]", "the model needs at least one body");
  detail::requirePositive(spec.dt, "dt", "s");
  detail::requireFinite(spec.gravity_W, "gravity");
  bodies_.reserve(spec.bodies.size());
  for (const BodySpec& b : spec.bodies) bodies_.push_back(buildBody(b));
  validateDamping(spec.damping, spec.dt, bodies_);
  linear_decay_ = std::exp(-spec.damping.linear_rate * spec.dt);
  angular_decay_ = std::exp(-spec.damping.angular_rate * spec.dt);
}

}  // namespace rigid_body_sim::core
