#include "rigid_body_sim/core/state.h"

namespace rigid_body_sim::core {

// With R_WB = R_WL R_LB and p_WB = p_WL + R_WL p_LB, the two velocities of
// one rigid body differ by the lever arm: v_WB = v_WL + ω × (R_WL p_LB).

LinkState linkState(const BodyModel& body, const BodyState& s) {
  LinkState link;
  link.q_WL = s.q_WB * body.q_LB.conjugate();
  const Vec3 r_W = link.q_WL * body.p_LB;  // link origin → centre of mass
  link.p_WL = s.p_WB - r_W;
  link.w_W = s.q_WB * s.w_B;
  link.v_WL = s.v_WB - link.w_W.cross(r_W);
  return link;
}

BodyState bodyStateFromLink(const BodyModel& body, const LinkState& link) {
  BodyState s;
  s.q_WB = (link.q_WL * body.q_LB).normalized();
  const Vec3 r_W = link.q_WL * body.p_LB;
  s.p_WB = link.p_WL + r_W;
  s.v_WB = link.v_WL + link.w_W.cross(r_W);
  s.w_B = s.q_WB.conjugate() * link.w_W;
  return s;
}

bool atRest(const Model& model, const BodyState& s) {
  return s.asleep || (s.still_time > 0.0 && s.still_time >= model.sleep().time);
}

State restState(const Model& model) {
  State state;
  for (const BodyModel& b : model.bodies()) state.bodies.push_back(bodyStateFromLink(b, LinkState{}));
  return state;
}

}  // namespace rigid_body_sim::core
