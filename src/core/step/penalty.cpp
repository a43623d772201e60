// The penalty responses: contact forces from the separations detection
// found (quadratic with a buffer, or the log barrier).
#include <algorithm>
#include <cmath>

#include "barrier.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/step/workspace.h"
#include "scratch.h"

namespace rigid_body_sim::core {

void accumulatePenaltyForces(const Model& model, const State& state, const Workspace& ws, int body, Vec3& force_W,
                             Vec3& torque_W) {
  const ContactSettings& cs = model.contact();
  const bool barrier = cs.method == ContactMethod::kPenaltyLogBarrier;
  const double stiction_speed =
      model.solver().stiction_speed;                         // m/s: friction is viscous below it (regularised Coulomb)
  const std::vector<double>& end = ws.scratch->barrier_end;  // filled in the barrier's later passes
  const bool have_end = barrier && end.size() == ws.contacts.size();
  for (std::size_t k = 0; k < ws.contacts.size(); ++k) {
    const Contact& c = ws.contacts[k];
    if (c.body != body && c.other != body) continue;
    const double phi = c.separation;
    double fn = 0.0;
    if (barrier) {
      // ρ/φ, shifted to vanish at the buffer's edge, as the exact work of its
      // potential over the step; φ > 0 is kept by step control (docs/physics.md §7.2).
      fn = barrierForce(cs, phi, have_end ? end[k] : phi);
      if (fn <= 0.0) continue;
    } else {
      if (phi >= cs.penalty_buffer) continue;
      fn = cs.penalty_stiffness * (cs.penalty_buffer - phi);
    }
    const auto angular = [&](int i) { return state.bodies[i].q_WB * state.bodies[i].w_B; };
    Vec3 u = state.bodies[c.body].v_WB + angular(c.body).cross(c.r_W);
    if (c.other >= 0) u -= state.bodies[c.other].v_WB + angular(c.other).cross(c.r_other_W);
    const double vn = c.normal_W.dot(u);
    fn = std::max(fn - cs.penalty_damping * vn, 0.0);
    const Vec3 vt = u - vn * c.normal_W;
    const double mu = model.friction(c.body, c.point, c.other);
    const Vec3 f = fn * c.normal_W - (mu * fn / std::max(vt.norm(), stiction_speed)) * vt;
    if (c.body == body) {
      force_W += f;
      torque_W += c.r_W.cross(f);
    } else {  // the other side of a body-body contact: equal and opposite
      force_W -= f;
      torque_W -= c.r_other_W.cross(f);
    }
  }
}

}  // namespace rigid_body_sim::core
