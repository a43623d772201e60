#include "rigid_body_sim/core/step/diagnostics.h"

#include <algorithm>

#include "contacts/round_contact.h"

namespace rigid_body_sim::core {

double kineticEnergy(const BodyModel& body, const BodyState& s) {
  return 0.5 * body.mass * s.v_WB.squaredNorm() + 0.5 * s.w_B.dot(body.inertia_B.cwiseProduct(s.w_B));
}

double potentialEnergy(const BodyModel& body, const BodyState& s, const Vec3& gravity_W) {
  return -body.mass * gravity_W.dot(s.p_WB);
}

double totalEnergy(const Model& model, const State& state) {
  double e = 0.0;
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    e += kineticEnergy(model.body(i), state.bodies[i]) +
         potentialEnergy(model.body(i), state.bodies[i], model.gravity());
  }
  return e;
}

double sceneDepth(const Model& model, std::size_t body, const BodyState& s) {
  double depth = 0.0;
  const BodyModel& b = model.body(body);
  const Mat3 R = s.q_WB.toRotationMatrix();
  for (const ContactPoint& c : b.contact_points) {
    for (const Sdf& shape : model.scene()) {
      if (c.round < 0) {
        depth = std::max(depth, c.radius - shape.eval(s.p_WB + R * c.r_B));
        continue;
      }
      // A rim or side (a cylinder's, a capsule's): at its deepest point, as detection measures it.
      detail::RoundHit hit;
      if (detail::roundOnSdf(b.round[c.round], c.phase, shape, R, s.p_WB, hit)) {
        depth = std::max(depth, c.radius - hit.phi);
      }
    }
  }
  return depth;
}

Vec3 angularMomentumWorld(const BodyModel& body, const BodyState& s) {
  return s.q_WB * body.inertia_B.cwiseProduct(s.w_B);
}

}  // namespace rigid_body_sim::core
