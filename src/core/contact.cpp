#include "rigid_body_sim/core/contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigid_body_sim::core {
namespace {

/// Calls visit(item, point, separation, normal_W) for every contact point of
/// a body with φ − radius < margin. Scene items farther than the
/// body's bounding radius are skipped: φ is 1-Lipschitz, so
/// φ(point) ≥ φ(centre) − bound_radius. Planes take a fast path: with the
/// normal turned into the body frame, φ is one dot product per point.
template <class Visit>
void scanBody(const Model& model, const BodyState& s, int body, double margin, std::vector<double>& scratch,
              Visit&& visit) {
  const BodyModel& b = model.body(body);
  const std::vector<Sdf>& scene = model.scene();
  Mat3 R = Mat3::Zero();
  bool have_R = false;
  const int n_points = static_cast<int>(b.contact_points.size());
  for (int item = 0; item < static_cast<int>(scene.size()); ++item) {
    const Sdf& sdf = scene[item];
    if (sdf.eval(s.p_WB) - b.bound_radius >= margin) continue;
    if (!have_R) {
      R = s.q_WB.toRotationMatrix();
      have_R = true;
    }
    if (sdf.kind() == Sdf::Kind::kPlane) {
      const Vec3 n_W = sdf.pose().q_WS * sdf.params();
      const double phi_centre = n_W.dot(s.p_WB - sdf.pose().p_WS);
      const Vec3 n_B = R.transpose() * n_W;
      // Only the extreme points can be deepest against a plane; groups whose
      // bounding sphere stays beyond the margin are skipped whole. Within a
      // group, two passes: all separations (vectorizable), then the few
      // within the margin.
      scratch.resize(b.extreme_points);
      double* sep = scratch.data();
      const double *x = b.extreme_x.data(), *y = b.extreme_y.data(), *z = b.extreme_z.data(),
                   *rad = b.extreme_radius.data();
      const double nx = n_B.x(), ny = n_B.y(), nz = n_B.z();
      for (const BodyModel::PointGroup& g : b.extreme_groups) {
        if (phi_centre + n_B.dot(g.centre_B) - g.radius >= margin) continue;
        const int begin = static_cast<int>(g.begin), end = static_cast<int>(g.end);
        for (int i = begin; i < end; ++i) sep[i] = phi_centre + nx * x[i] + ny * y[i] + nz * z[i] - rad[i];
        for (int i = begin; i < end; ++i) {
          if (sep[i] < margin) visit(item, i, sep[i], n_W);
        }
      }
      continue;
    }
    for (int i = 0; i < n_points; ++i) {
      const ContactPoint& p = b.contact_points[i];
      const Vec3 r_W = R * p.r_B;
      Vec3 n_W;
      const double separation = sdf.eval(s.p_WB + r_W, &n_W) - p.radius;
      if (separation < margin) visit(item, i, separation, n_W);
    }
  }
}

/// How far a body can move in h, plus a small constant so resting contacts persist (m).
double speculativeMargin(const BodyModel& b, const BodyState& s, double h, double slop) {
  return (s.v_WB.norm() + s.w_B.norm() * b.bound_radius) * h + std::max(slop, 1e-4);
}

/// Of the candidates listed in `members` (one region), keeps at most four
/// that span its area (the usual contact-manifold reduction): the deepest
/// point, the farthest from it, the farthest from the line through both,
/// and the farthest on the other side of that line. Near-ties (within a
/// nanometre, or 1e-9 relative) go to the lowest point index, so the same
/// points are kept from step to step, which lets the solver warm-start.
/// Distances are rigid, so it works on the body-frame points.
void reduceRegion(const std::vector<ContactCandidate>& cands, const BodyModel& b, const Vec3& n_B,
                  std::vector<int>& members, std::vector<Vec3>& at) {
  const std::size_t n = members.size();
  if (n <= 4) return;
  at.resize(n);
  for (std::size_t k = 0; k < n; ++k) at[k] = b.contact_points[cands[members[k]].point].r_B;
  // The index of the largest score (the first one on near-ties).
  const auto argmax = [n](auto score, double tie) {
    std::size_t best = 0;
    double best_score = score(0);
    for (std::size_t k = 1; k < n; ++k) {
      const double sc = score(k);
      if (sc > best_score + tie + 1e-9 * std::abs(best_score)) {
        best_score = sc;
        best = k;
      }
    }
    return std::make_pair(best, best_score);
  };
  const std::size_t a = argmax([&](std::size_t k) { return -cands[members[k]].separation; }, 1e-9).first;
  const std::size_t b2 = argmax([&](std::size_t k) { return (at[k] - at[a]).squaredNorm(); }, 1e-18).first;
  const Vec3 normal_of_ab = (at[b2] - at[a]).cross(n_B);  // in the plane, across the line ab
  const auto side = [&](std::size_t k) { return normal_of_ab.dot(at[k] - at[a]); };
  const auto [c, c_score] = argmax([&](std::size_t k) { return std::abs(side(k)); }, 1e-18);
  const double sign = side(c) >= 0.0 ? 1.0 : -1.0;
  const auto [d, d_score] = argmax([&](std::size_t k) { return -sign * side(k); }, 1e-18);
  const int kept[4] = {members[a], members[b2], members[c], members[d]};
  members.resize(2);
  members[0] = kept[0];
  members[1] = kept[1];
  if (c_score > 0.0) members.push_back(kept[2]);
  if (d_score > 0.0) members.push_back(kept[3]);
}

/// Turns one body's candidates into contacts: regions by item and normal
/// direction (within about 20°; a plane is one region), each reduced to at
/// most four points for the impulse method.
void emitContacts(const Model& model, const BodyState& s, int body, bool reduce, Workspace& ws) {
  constexpr double kSameRegionCos = 0.94;
  const BodyModel& b = model.body(body);
  std::vector<ContactCandidate>& cands = ws.candidates;
  // Region ids; candidates arrive grouped by item.
  int regions = 0, item_first_region = 0;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const bool new_item = i == 0 || cands[i].item != cands[i - 1].item;
    if (new_item) {
      ws.region_normals.clear();
      item_first_region = regions;
    } else if (model.scene()[cands[i].item].kind() == Sdf::Kind::kPlane) {
      cands[i].region = cands[i - 1].region;  // one normal: one region
      continue;
    }
    int r = -1;
    for (std::size_t k = 0; k < ws.region_normals.size() && r < 0; ++k) {
      if (ws.region_normals[k].dot(cands[i].normal_W) > kSameRegionCos) r = item_first_region + static_cast<int>(k);
    }
    if (r < 0) {
      ws.region_normals.push_back(cands[i].normal_W);
      r = regions++;
    }
    cands[i].region = r;
  }
  const Quat q_BW = s.q_WB.conjugate();
  std::size_t start = 0;
  for (int r = 0; r < regions; ++r) {
    ws.region_members.clear();
    for (std::size_t i = start; i < cands.size(); ++i) {
      if (cands[i].region == r) ws.region_members.push_back(static_cast<int>(i));
    }
    start = static_cast<std::size_t>(ws.region_members.front());  // regions begin in order
    if (reduce) {
      reduceRegion(cands, b, q_BW * cands[ws.region_members.front()].normal_W, ws.region_members, ws.region_points);
    }
    for (int m : ws.region_members) {
      const ContactCandidate& cand = cands[m];
      const ContactPoint& p = b.contact_points[cand.point];
      Contact& c = ws.contacts.emplace_back();
      c.body = body;
      c.item = cand.item;
      c.point = cand.point;
      c.normal_W = cand.normal_W;
      c.r_W = s.q_WB * p.r_B - p.radius * cand.normal_W;
      c.separation = cand.separation;
    }
  }
}

bool keyLess(int body_a, int item_a, int point_a, int body_b, int item_b, int point_b) {
  if (body_a != body_b) return body_a < body_b;
  if (item_a != item_b) return item_a < item_b;
  return point_a < point_b;
}

/// Applies the impulse λ_N n + λ₁ t₁ + λ₂ t₂ at a contact to its body.
void applyImpulse(const Contact& c, double inv_mass, double ln, double l1, double l2, Vec3& v, Vec3& w) {
  v += inv_mass * (ln * c.normal_W + l1 * c.tangent1_W + l2 * c.tangent2_W);
  w += ln * c.turn_n + l1 * c.turn_t1 + l2 * c.turn_t2;
}

/// Starts every contact from the impulse it carried last step (if it
/// existed), applied to the bodies before the first sweep. The last step's
/// list is sorted by (body, item, point).
void warmStart(const Model& model, State& state, std::vector<Vec3>& w_W, std::vector<Contact>& contacts) {
  const std::vector<ContactImpulse>& last = state.contact_impulses;
  for (Contact& c : contacts) {
    const auto it = std::lower_bound(last.begin(), last.end(), c, [](const ContactImpulse& x, const Contact& y) {
      return keyLess(x.body, x.item, x.point, y.body, y.item, y.point);
    });
    if (it == last.end() || it->body != c.body || it->item != c.item || it->point != c.point) continue;
    c.normal_impulse = it->normal;
    c.tangent_impulse = Eigen::Vector2d(c.tangent1_W.dot(it->tangent_W), c.tangent2_W.dot(it->tangent_W));
    const double limit = model.contact().friction * c.normal_impulse;
    if (c.tangent_impulse.norm() > limit) c.tangent_impulse *= limit / c.tangent_impulse.norm();
    applyImpulse(c, model.body(c.body).inv_mass, c.normal_impulse, c.tangent_impulse.x(), c.tangent_impulse.y(),
                 state.bodies[c.body].v_WB, w_W[c.body]);
  }
}

Mat3 worldInverseInertia(const BodyModel& b, const Quat& q_WB) {
  const Mat3 R = q_WB.toRotationMatrix();
  return R * b.inv_inertia_B.asDiagonal() * R.transpose();
}

}  // namespace

void detectContacts(const Model& model, const State& state, double h, Workspace& ws) {
  ws.contacts.clear();
  ws.deepest_penetration = 0.0;
  if (model.scene().empty()) {
    ws.in_contact.clear();  // no scene, no contact (and no allocation)
    return;
  }
  ws.in_contact.assign(model.bodyCount(), 0);
  const ContactSettings& cs = model.contact();
  const bool impulse = cs.method == ContactMethod::kImpulse;
  for (int body = 0; body < static_cast<int>(model.bodyCount()); ++body) {
    const BodyState& s = state.bodies[body];
    if (s.asleep) continue;
    const BodyModel& b = model.body(body);
    double margin = speculativeMargin(b, s, h, cs.position_slop);
    if (cs.method == ContactMethod::kPenaltyQuadratic) margin = cs.penalty_buffer;
    if (cs.method == ContactMethod::kPenaltyLogBarrier) margin = cs.barrier_buffer;
    ws.candidates.clear();
    scanBody(model, s, body, margin, ws.separations, [&](int item, int point, double separation, const Vec3& n) {
      ws.candidates.push_back({item, point, 0, separation, n});
      ws.deepest_penetration = std::max(ws.deepest_penetration, -separation);
    });
    if (ws.candidates.empty()) continue;
    ws.in_contact[body] = 1;
    emitContacts(model, s, body, impulse, ws);
  }
}

void solveContactImpulses(const Model& model, State& state, double h, Workspace& ws) {
  if (ws.contacts.empty()) {
    state.contact_impulses.clear();
    return;
  }
  const ContactSettings& cs = model.contact();
  const double threshold = model.restitutionThreshold();
  // Work in world axes: ω_W = R w_B for the bodies in contact.
  std::vector<Vec3>& w_W = ws.angular_velocities;
  w_W.resize(model.bodyCount());
  for (std::size_t i = 0; i < model.bodyCount(); ++i) w_W[i] = state.bodies[i].q_WB * state.bodies[i].w_B;
  // Prepare each contact: the entries of the notes' K = M⁻¹𝐈 − r* I⁻¹ r*
  // the solver needs (nᵀKn = M⁻¹ + (r×n)ᵀ I⁻¹ (r×n), and TᵀKT likewise),
  // and the target normal velocity.
  int last_body = -1;
  Mat3 inv_I_W = Mat3::Zero();
  for (Contact& c : ws.contacts) {
    const BodyModel& b = model.body(c.body);
    const BodyState& s = state.bodies[c.body];
    if (c.body != last_body) {
      inv_I_W = worldInverseInertia(b, s.q_WB);
      last_body = c.body;
    }
    const Vec3& n = c.normal_W;
    c.tangent1_W = (std::abs(n.x()) < 0.57 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    c.tangent2_W = n.cross(c.tangent1_W);
    const Vec3 rn = c.r_W.cross(n), r1 = c.r_W.cross(c.tangent1_W), r2 = c.r_W.cross(c.tangent2_W);
    c.turn_n = inv_I_W * rn;
    c.turn_t1 = inv_I_W * r1;
    c.turn_t2 = inv_I_W * r2;
    c.normal_mass = 1.0 / (b.inv_mass + rn.dot(c.turn_n));
    Eigen::Matrix2d k;
    k << b.inv_mass + r1.dot(c.turn_t1), r1.dot(c.turn_t2),  //
        r2.dot(c.turn_t1), b.inv_mass + r2.dot(c.turn_t2);
    c.tangent_mass = k.inverse();
    const double vn = n.dot(s.v_WB + w_W[c.body].cross(c.r_W));
    // Bounce if the point reaches the surface this step fast enough;
    // otherwise it may close the gap (a speculative contact), no more.
    const bool arrives = c.separation <= 0.0 || vn * h < -c.separation;
    if (arrives && vn < -threshold) {
      c.target_normal_velocity = -cs.restitution * vn;
    } else {
      c.target_normal_velocity = c.separation > 0.0 ? -c.separation / h : 0.0;
    }
    c.normal_impulse = 0.0;
    c.tangent_impulse.setZero();
  }
  warmStart(model, state, w_W, ws.contacts);
  // Projected Gauss-Seidel: friction first, then the normal, per contact.
  constexpr double kTolerance = 1e-8;  // m/s of velocity change in a sweep: 1e-11 m of drift per step
  for (int sweep = 0; sweep < cs.iterations; ++sweep) {
    double largest = 0.0;
    for (Contact& c : ws.contacts) {
      const double inv_mass = model.body(c.body).inv_mass;
      Vec3& v = state.bodies[c.body].v_WB;
      Vec3& w = w_W[c.body];
      // Friction: stop the sliding if the cone |λ_T| ≤ μ λ_N allows.
      // Otherwise slide: a point that is clearly slipping gets the full
      // μ λ_N against its slip (Coulomb's sliding friction opposes the slip,
      // whatever K's rotational coupling makes of the sticking impulse);
      // near sticking, the sticking impulse is scaled into the cone.
      constexpr double kSlipSpeed = 1e-3;  // m/s
      Vec3 u = v + w.cross(c.r_W);
      const Eigen::Vector2d vt(c.tangent1_W.dot(u), c.tangent2_W.dot(u));
      Eigen::Vector2d lt = c.tangent_impulse - c.tangent_mass * vt;
      const double limit = cs.friction * c.normal_impulse;
      const double stick = lt.norm();
      if (stick > limit) {
        const double slip = vt.norm();
        lt = slip > kSlipSpeed ? Eigen::Vector2d(-limit / slip * vt) : Eigen::Vector2d(lt * (limit / stick));
      }
      const Eigen::Vector2d dlt = lt - c.tangent_impulse;
      c.tangent_impulse = lt;
      applyImpulse(c, inv_mass, 0.0, dlt.x(), dlt.y(), v, w);
      // Normal: reach the target velocity, never pull (λ_N ≥ 0).
      u = v + w.cross(c.r_W);
      const double vn = c.normal_W.dot(u);
      const double ln = std::max(c.normal_impulse - c.normal_mass * (vn - c.target_normal_velocity), 0.0);
      const double dln = ln - c.normal_impulse;
      c.normal_impulse = ln;
      applyImpulse(c, inv_mass, dln, 0.0, 0.0, v, w);
      largest = std::max(largest, (std::abs(dln) + dlt.norm()) / c.normal_mass);
    }
    if (largest < kTolerance) break;
  }
  for (Contact& c : ws.contacts) {
    const double vn = c.normal_W.dot(state.bodies[c.body].v_WB + w_W[c.body].cross(c.r_W));
    c.predicted_separation = c.separation + h * vn;
  }
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    state.bodies[i].w_B = state.bodies[i].q_WB.conjugate() * w_W[i];
  }
  state.contact_impulses.clear();
  for (const Contact& c : ws.contacts) {
    const Vec3 tangent = c.tangent1_W * c.tangent_impulse.x() + c.tangent2_W * c.tangent_impulse.y();
    state.contact_impulses.push_back({c.body, c.item, c.point, c.normal_impulse, tangent});
  }
  std::sort(state.contact_impulses.begin(), state.contact_impulses.end(),
            [](const ContactImpulse& x, const ContactImpulse& y) {
              return keyLess(x.body, x.item, x.point, y.body, y.item, y.point);
            });
}

void correctPositions(const Model& model, State& state, Workspace& ws) {
  const double slop = model.contact().position_slop;
  // Resting contacts end the step where they began: nothing to correct.
  // (Linear prediction; rotation adds O(h²ω²r), far below the slop at rest.)
  const bool all_clear = std::all_of(ws.contacts.begin(), ws.contacts.end(),
                                     [&](const Contact& c) { return c.predicted_separation > -0.5 * slop; });
  if (all_clear) return;
  constexpr int kSweeps = 4;
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    double deepest = 0.0;
    for (const Contact& c : ws.contacts) {
      const BodyModel& b = model.body(c.body);
      BodyState& s = state.bodies[c.body];
      const ContactPoint& p = b.contact_points[c.point];
      const Vec3 arm = s.q_WB * p.r_B;
      Vec3 n;
      const double separation = model.scene()[c.item].eval(s.p_WB + arm, &n) - p.radius;
      const double C = separation + slop;
      if (C >= 0.0) continue;
      deepest = std::min(deepest, C);
      const Vec3 r = arm - p.radius * n;
      const Mat3 inv_I_W = worldInverseInertia(b, s.q_WB);
      const Vec3 rn = r.cross(n);
      const double k = b.inv_mass + rn.dot(inv_I_W * rn);
      const Vec3 P = (-C / k) * n;  // positional impulse that closes C to first order
      s.p_WB += b.inv_mass * P;
      const Vec3 half_turn = 0.5 * (inv_I_W * r.cross(P));
      s.q_WB = Quat(1.0, half_turn.x(), half_turn.y(), half_turn.z()) * s.q_WB;
      s.q_WB.normalize();
    }
    if (deepest >= 0.0) break;
  }
}

void accumulatePenaltyForces(const Model& model, const State& state, const Workspace& ws, int body, Vec3& force_W,
                             Vec3& torque_W) {
  const ContactSettings& cs = model.contact();
  const BodyState& s = state.bodies[body];
  const Vec3 w_W = s.q_WB * s.w_B;
  const bool barrier = cs.method == ContactMethod::kPenaltyLogBarrier;
  constexpr double kStictionSpeed = 1e-3;  // m/s: friction is viscous below it (regularised Coulomb)
  for (const Contact& c : ws.contacts) {
    if (c.body != body) continue;
    const double phi = c.separation;
    double fn = 0.0;
    if (barrier) {
      if (phi >= cs.barrier_buffer) continue;
      // The notes' ρ/φ, shifted to vanish at the buffer's edge; φ > 0 is kept by step control.
      fn = cs.barrier_strength * (1.0 / std::max(phi, 1e-9) - 1.0 / cs.barrier_buffer);
    } else {
      if (phi >= cs.penalty_buffer) continue;
      fn = cs.penalty_stiffness * (cs.penalty_buffer - phi);
    }
    const Vec3 u = s.v_WB + w_W.cross(c.r_W);
    const double vn = c.normal_W.dot(u);
    fn = std::max(fn - cs.penalty_damping * vn, 0.0);
    const Vec3 vt = u - vn * c.normal_W;
    const double speed = vt.norm();
    const Vec3 f = fn * c.normal_W - (cs.friction * fn / std::max(speed, kStictionSpeed)) * vt;
    force_W += f;
    torque_W += c.r_W.cross(f);
  }
}

double minSeparation(const Model& model, const BodyState& s, int body, double margin) {
  double smallest = std::numeric_limits<double>::infinity();
  std::vector<double> scratch;
  scanBody(model, s, body, margin, scratch,
           [&](int, int, double separation, const Vec3&) { smallest = std::min(smallest, separation); });
  return smallest;
}

}  // namespace rigid_body_sim::core
