#include "rigid_body_sim/core/bodies/state.h"

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

LinkState frameState(const LinkState& link, const Pose& X_LS) {
  LinkState frame = link;
  const Vec3 r_W = link.q_WL * X_LS.translation;
  frame.p_WL = link.p_WL + r_W;
  frame.q_WL = Quat(link.q_WL * X_LS.rotation).normalized();
  frame.v_WL = link.v_WL + link.w_W.cross(r_W);
  return frame;
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

void wakeAll(State& state) {
  for (BodyState& b : state.bodies) {
    b.asleep = false;
    b.still_time = 0.0;
  }
}

void removeBody(const Model& model, State& state, int i) { removeBodies(model, state, i, 1); }

void removeBodies(const Model& model, State& state, int first, int count) {
  const int end = first + count;
  const auto gone = [&](int j) { return j >= first && j < end; };
  const auto wake = [&](int j) {
    state.bodies[j].asleep = false;
    state.bodies[j].still_time = 0.0;
  };
  for (int i = first; i < end; ++i) {
    const double reach = model.body(i).bound_radius + SolverSettings::kWakeReach;  // m
    for (std::size_t j = 0; j < state.bodies.size(); ++j) {
      const double gap = (state.bodies[j].p_WB - state.bodies[i].p_WB).norm() - model.body(j).bound_radius;
      if (!gone(static_cast<int>(j)) && gap <= reach) wake(static_cast<int>(j));
    }
  }
  std::vector<ContactImpulse>& impulses = state.contact_impulses;
  std::vector<ContactImpulse> kept;
  kept.reserve(impulses.size());
  for (ContactImpulse c : impulses) {
    if (gone(c.body) || gone(c.other)) {
      const int partner = gone(c.body) ? c.other : c.body;
      if (partner >= 0 && !gone(partner)) wake(partner);
      continue;
    }
    if (c.body >= end) c.body -= count;  // a monotone renaming: the list stays sorted by key
    if (c.other >= end) c.other -= count;
    kept.push_back(c);
  }
  impulses = std::move(kept);
  state.bodies.erase(state.bodies.begin() + first, state.bodies.begin() + end);
}

void insertBody(State& state, int i, const BodyState& start) {
  for (ContactImpulse& c : state.contact_impulses) {  // a monotone renaming: the list stays sorted by key
    if (c.body >= i) ++c.body;
    if (c.other >= i) ++c.other;
  }
  state.bodies.insert(state.bodies.begin() + i, start);
}

State restState(const Model& model) {
  State state;
  for (const BodyModel& b : model.bodies()) state.bodies.push_back(bodyStateFromLink(b, LinkState{}));
  return state;
}

}  // namespace rigid_body_sim::core
