#include "rigid_body_sim/core/step/loads.h"

#include <algorithm>
#include <cmath>

namespace rigid_body_sim::core {

double stepFraction(double start, double end, double t, double h) {
  const double tol = 1e-9 * h, t_end = t + h;
  const auto snap = [&](double s) { return std::abs(s - t) <= tol ? t : std::abs(s - t_end) <= tol ? t_end : s; };
  const double from = std::max(snap(start), t), to = std::min(snap(end), t_end);
  if (!(to > from)) return 0.0;
  if (from == t && to == t_end) return 1.0;
  return std::min((to - from) / h, 1.0);
}

void addWrench(const BodyModel& body, BodyLoad& load, const Wrench& wrench) {
  const Vec3 torque = wrench.torque + wrench.point.cross(wrench.force);  // about the centre of mass
  if (wrench.frame == Frame::kWorld) {
    load.force_W += wrench.force;
    load.torque_W += torque;
  } else {  // link axes L → principal axes B
    const Quat q_BL = body.q_LB.conjugate();
    load.force_B += q_BL * wrench.force;
    load.torque_B += q_BL * torque;
  }
}

Wrench inWorldAxes(const Wrench& wrench, const Quat& q_WF) {
  return {q_WF * wrench.force, q_WF * wrench.torque, q_WF * wrench.point, Frame::kWorld};
}

Impulse inWorldAxes(const Impulse& impulse, const Quat& q_WF) {
  return {q_WF * impulse.linear, q_WF * impulse.angular, q_WF * impulse.point, Frame::kWorld};
}

void applyImpulse(const BodyModel& body, BodyState& s, const Impulse& impulse) {
  const Vec3 dL = impulse.point.cross(impulse.linear) + impulse.angular;  // r × J + H
  Vec3 J_W, dL_B;
  if (impulse.frame == Frame::kWorld) {
    J_W = impulse.linear;
    dL_B = s.q_WB.conjugate() * dL;
  } else {
    const Quat q_BL = body.q_LB.conjugate();
    J_W = s.q_WB * (q_BL * impulse.linear);
    dL_B = q_BL * dL;
  }
  s.v_WB += body.inv_mass * J_W;                   // Δv = J / M
  s.w_B += body.inv_inertia_B.cwiseProduct(dL_B);  // Δω = I⁻¹ (r × J + H)
  s.asleep = false;                                // an impulse wakes a sleeping body
  s.still_time = 0.0;
}

}  // namespace rigid_body_sim::core
