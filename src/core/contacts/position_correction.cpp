// The position correction after the impulse solve (docs/physics.md §5.8):
// nonlinear Gauss-Seidel on positions, as Box2D does.
#include "box_pair.h"
#include "island.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "round_contact.h"
#include "step/scratch.h"
#include "stiff_body.h"

namespace rigid_body_sim::core {

using detail::StepScratch;

void correctPositions(const Model& model, State& state, Workspace& ws) {
  const double slop = model.contact().position_slop;
  StepScratch& sc = *ws.scratch;
  // Resting contacts end the step where they began: nothing to correct.
  // (Linear prediction; rotation adds O(h²ω²r), far below the slop at rest.)
  // Only the islands (of the impulse solve) with a contact predicted to end
  // deeper than a fraction of the slop (correction_trigger, a half) are
  // corrected (the prediction is linear: the rest of the slop is its margin).
  std::vector<char>& needs = sc.island_flags;  // per island root
  needs.assign(model.bodyCount(), 0);
  bool any = false;
  for (const Contact& c : ws.contacts) {
    if (c.predicted_separation <= -model.solver().correction_trigger * slop)
      needs[islandOf(state, sc.island_root, c)] = any = true;
  }
  if (!any) return;
  std::vector<int>& todo = sc.correct_contacts;  // in contact order
  todo.clear();
  for (std::size_t k = 0; k < ws.contacts.size(); ++k) {
    if (needs[islandOf(state, sc.island_root, ws.contacts[k])]) todo.push_back(static_cast<int>(k));
  }
  // A stiff body (a heavy body with a small inertia, alone on the ground):
  // its contacts together first, as its impulses were (stiff_body.h).
  if (sc.stiff.size() == state.bodies.size()) {
    std::vector<int>& own = sc.stiff_contacts;
    for (std::size_t i = 0; i < sc.stiff.size(); ++i) {
      if (!sc.stiff[i]) continue;
      const int body = static_cast<int>(i);
      own.clear();
      for (const int k : todo) {
        if (ws.contacts[k].body == body || ws.contacts[k].other == body) own.push_back(k);
      }
      detail::correctStiffBody(model.body(i), state.bodies[i], body, ws.contacts, own, slop, 1e-3 * slop);
    }
  }
  for (int sweep = 0; sweep < model.solver().position_iterations; ++sweep) {
    double deepest = 0.0;
    for (const int index : todo) {
      const Contact& c = ws.contacts[index];
      const BodyModel& b = model.body(c.body);
      BodyState& s = state.bodies[c.body];
      const bool pair_point = c.point < 0;  // a point of a box pair's own (box_pair.h)
      const ContactPoint& p = b.contact_points[pair_point ? 0 : c.point];
      const double radius = pair_point ? 0.0 : p.radius;
      BodyState* o = c.other < 0 ? nullptr : &state.bodies[c.other];
      // The surface, in its frame F: the scene item's (the world) or the other body's solid.
      const Sdf& surface = o == nullptr ? model.scene()[c.item] : model.body(c.other).solid_B.front();
      const Quat q_FW = o == nullptr ? Quat::Identity() : o->q_WB.conjugate();
      const Vec3 p_FB = o == nullptr ? s.p_WB : Vec3(q_FW * (s.p_WB - o->p_WB));
      Vec3 arm, n_F;
      double phi;
      detail::BoxInFrame box_s, box_o;
      const Mat3 R_FB = (q_FW * s.q_WB).toRotationMatrix();
      if (o != nullptr && detail::pairBoxes(b, model.body(c.other), R_FB, p_FB, box_s, box_o)) {
        // Two boxes: along the pair's one normal, as detection measured it (box_pair.h).
        const detail::PairPlane plane = detail::boxPairPlane(box_o, box_s, c.other < c.body);
        Vec3 p_F = p_FB + R_FB * p.r_B;
        if (pair_point && !detail::pairPoint(box_o, box_s, plane, c.point, p_F)) continue;
        arm = o->q_WB * (p_F - p_FB);
        phi = plane.n_F.dot(p_F) - plane.support;
        n_F = plane.n_F;
      } else if (pair_point) {
        continue;
      } else if (p.round >= 0) {  // where the round feature is deepest now
        detail::RoundHit hit;
        if (!detail::roundOnSdf(b.round[p.round], p.phase, surface, R_FB, p_FB, hit)) {
          continue;
        }
        arm = s.q_WB * hit.r_B;
        phi = hit.phi;
        n_F = hit.normal_F;
      } else {
        arm = s.q_WB * p.r_B;
        phi = surface.eval(o == nullptr ? Vec3(s.p_WB + arm) : Vec3(q_FW * (s.p_WB + arm - o->p_WB)), &n_F);
      }
      const double separation = phi - radius;
      const Vec3 n = o == nullptr ? n_F : Vec3(o->q_WB * n_F);
      if (o != nullptr && o->asleep) o = nullptr;  // a sleeper stays put, like the ground
      const double C = separation + slop;
      if (!(C < 0.0)) continue;  // also a NaN distance: no correction (the guard ran before this stage)
      deepest = std::min(deepest, C);
      const Vec3 r = arm - radius * n;
      const Mat3 inv_I = detail::worldInverseInertia(b, s.q_WB);
      const Vec3 rn = r.cross(n);
      const bool body_moves = !s.asleep;  // a sleeper's own points against an awake body: it stays put
      double k = body_moves ? b.inv_mass + rn.dot(inv_I * rn) : 0.0;
      Vec3 r_o = Vec3::Zero();
      Mat3 inv_I_o = Mat3::Zero();
      if (o != nullptr) {
        r_o = s.p_WB + r - o->p_WB;
        inv_I_o = detail::worldInverseInertia(model.body(c.other), o->q_WB);
        const Vec3 on = r_o.cross(n);
        k += model.body(c.other).inv_mass + on.dot(inv_I_o * on);
      }
      const Vec3 P = (-C / k) * n;   // positional impulse that closes C to first order
      if (!P.allFinite()) continue;  // a degenerate normal or mass: never a non-finite pose
      const auto move = [](BodyState& x, double inv_mass, const Mat3& inv_I_W, const Vec3& arm_W, const Vec3& impulse) {
        x.p_WB += inv_mass * impulse;
        const Vec3 half_turn = 0.5 * (inv_I_W * arm_W.cross(impulse));
        x.q_WB = Quat(1.0, half_turn.x(), half_turn.y(), half_turn.z()) * x.q_WB;
        x.q_WB.normalize();
      };
      if (body_moves) move(s, b.inv_mass, inv_I, r, P);
      if (o != nullptr) move(*o, model.body(c.other).inv_mass, inv_I_o, r_o, -P);
    }
    if (deepest >= 0.0) break;
  }
}

}  // namespace rigid_body_sim::core
