#include "rigid_body_sim/core/contact.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <thread>

#include "rigid_body_sim/core/parallel.h"

namespace rigid_body_sim::core {
namespace {

/// m/s: a contact velocity error below this is the rounding of the impulses
/// that hold a body still (about 1e-18 m/s, the last bits of h g left over).
/// The solver leaves such a contact alone; otherwise rounding would walk its
/// impulse in the last bits at every step.
constexpr double kRoundingSpeed = 1e-15;
/// m/s and rad/s: a body the solve leaves slower than this (every contact
/// held to kRoundingSpeed gives ω below about kRoundingSpeed / 1 mm) ends
/// the solve at exactly zero, so that it rests exactly: far below any motion
/// (3e-5 m a year), and a resting body becomes a fixed point of the step
/// (Workspace::FixedPoint) instead of moving the last bits of its pose.
constexpr double kRestingSpeed = 1e-12;

// ---------------------------------------------------------------- detection

/// Calls visit(item, point, separation, normal_W) for every contact point of
/// a body with φ − radius < margin against the scene. Scene items farther
/// than the body's bounding radius are skipped: φ is 1-Lipschitz, so
/// φ(point) ≥ φ(centre) − bound_radius. Planes take a fast path: with the
/// normal turned into the body frame, φ is one dot product per point.
template <class Visit>
void scanScene(const Model& model, const BodyState& s, int body, double margin, std::vector<double>& scratch,
               Visit&& visit) {
  const BodyModel& b = model.body(body);
  const std::vector<Sdf>& scene = model.scene();
  Mat3 R = Mat3::Zero();
  bool have_R = false;
  const int n_points = static_cast<int>(b.contact_points.size());
  for (int item = 0; item < static_cast<int>(scene.size()); ++item) {
    const Sdf& sdf = scene[item];
    const bool plane = sdf.kind() == Sdf::Kind::kPlane;
    const Vec3 n_W = plane ? Vec3(sdf.pose().q_WS * sdf.params()) : Vec3::Zero();
    const double phi_centre = plane ? n_W.dot(s.p_WB - sdf.pose().p_WS) : sdf.eval(s.p_WB);
    if (phi_centre - b.bound_radius >= margin) continue;
    if (!have_R) {
      R = s.q_WB.toRotationMatrix();
      have_R = true;
    }
    if (plane) {
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
      Vec3 normal_W;
      const double separation = sdf.eval(s.p_WB + r_W, &normal_W) - p.radius;
      if (separation < margin) visit(item, i, separation, normal_W);
    }
  }
}

/// The same for the points of body a against the solid of body o: each
/// point is taken into o's frame, where the solid is.
template <class Visit>
void scanBody(const Model& model, const State& state, int a, int o, double margin, Visit&& visit) {
  const BodyModel &ba = model.body(a), &bo = model.body(o);
  if (bo.solid_B.empty()) return;
  const Sdf& solid = bo.solid_B.front();
  const BodyState &sa = state.bodies[a], &so = state.bodies[o];
  const Quat q_OW = so.q_WB.conjugate();
  const Vec3 centre_O = q_OW * (sa.p_WB - so.p_WB);
  if (solid.eval(centre_O) - ba.bound_radius >= margin) return;
  const Mat3 R_OA = (q_OW * sa.q_WB).toRotationMatrix();  // a's frame into o's
  const Mat3 R_WO = so.q_WB.toRotationMatrix();
  for (int i = 0; i < static_cast<int>(ba.contact_points.size()); ++i) {
    const ContactPoint& p = ba.contact_points[i];
    const Vec3 p_O = centre_O + R_OA * p.r_B;
    // Outside the box around o's solid, grown by the margin: too far to touch.
    const double reach = margin + p.radius;
    if ((p_O.array() < bo.solid_lo_B.array() - reach).any() || (p_O.array() > bo.solid_hi_B.array() + reach).any()) {
      continue;
    }
    Vec3 n_O;
    const double separation = solid.eval(p_O, &n_O) - p.radius;
    if (separation < margin) visit(i, separation, Vec3(R_WO * n_O));
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

/// Turns one body's candidates into contacts: regions by item (or other
/// body) and normal direction (within about 20°; a plane is one region),
/// each reduced to at most four points for the impulse method.
void emitContacts(const Model& model, const State& state, int body, bool reduce, StepScratch& ws) {
  constexpr double kSameRegionCos = 0.94;
  const BodyModel& b = model.body(body);
  const BodyState& s = state.bodies[body];
  std::vector<ContactCandidate>& cands = ws.candidates;
  // Region ids; candidates arrive grouped by item (or other body).
  int regions = 0, group_first_region = 0;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const bool new_group = i == 0 || cands[i].item != cands[i - 1].item || cands[i].other != cands[i - 1].other;
    if (new_group) {
      ws.region_normals.clear();
      group_first_region = regions;
    } else if (cands[i].item >= 0 && model.scene()[cands[i].item].kind() == Sdf::Kind::kPlane) {
      cands[i].region = cands[i - 1].region;  // one normal: one region
      continue;
    }
    int r = -1;
    for (std::size_t k = 0; k < ws.region_normals.size() && r < 0; ++k) {
      if (ws.region_normals[k].dot(cands[i].normal_W) > kSameRegionCos) r = group_first_region + static_cast<int>(k);
    }
    if (r < 0) {
      ws.region_normals.push_back(cands[i].normal_W);
      r = regions++;
    }
    cands[i].region = r;
  }
  // Reduce each region, then emit the kept candidates in key order (item,
  // then point): the contacts of a step come out sorted by (body, other,
  // item, point), which warm starting looks them up by.
  const Quat q_BW = s.q_WB.conjugate();
  std::vector<int>& kept = ws.kept;
  kept.clear();
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
    kept.insert(kept.end(), ws.region_members.begin(), ws.region_members.end());
  }
  std::sort(kept.begin(), kept.end(), [&](int x, int y) {
    return cands[x].item != cands[y].item ? cands[x].item < cands[y].item : cands[x].point < cands[y].point;
  });
  const Mat3 R_WB = s.q_WB.toRotationMatrix();  // one matrix for all points: cheaper than q·r each
  for (int m : kept) {
    const ContactCandidate& cand = cands[m];
    const ContactPoint& p = b.contact_points[cand.point];
    // Filled on the stack, then copied: the compiler drops the default
    // initialisation it overwrites (in place it zeroes the whole struct first).
    Contact c;
    c.body = body;
    c.other = cand.other;
    c.item = cand.item;
    c.point = cand.point;
    c.normal_W = cand.normal_W;
    c.r_W = R_WB * p.r_B - p.radius * cand.normal_W;
    if (c.other >= 0) c.r_other_W = s.p_WB + c.r_W - state.bodies[c.other].p_WB;
    c.separation = cand.separation;
    ws.contacts.push_back(c);
  }
}

/// Sweep and prune along x in strips along y: the pairs of bodies (at least
/// one awake) whose boxes, grown by their margins, overlap, both ways round,
/// into ws.directions. One sweep along x over bodies spread over the ground
/// meets every body of the same x, a whole column of a grid (about √N);
/// strips as wide as the widest box hold the bodies of about one row, and
/// two boxes overlapping in y lie in the same strip or in neighbouring ones,
/// so each box is swept against its own strip and the next. The boxes go
/// into flat arrays in (strip, x) order first, so the inner loops only
/// compare numbers. Sorted, so the result does not depend on the order the
/// workspace kept from the last step, nor on the number of parts.
void broadPhase(const Model& model, const State& state, int parts, Workspace& ws) {
  const int n = static_cast<int>(model.bodyCount());
  std::vector<int>& order = ws.sweep_order;
  if (static_cast<int>(order.size()) != n) {
    order.resize(n);
    for (int i = 0; i < n; ++i) order[i] = i;
  }
  std::vector<double>& lo = ws.box_lo;  // 3 per body, by body index
  std::vector<double>& hi = ws.box_hi;
  std::vector<double>& strip = ws.box_strip;  // per body
  lo.resize(3 * n);
  hi.resize(3 * n);
  strip.resize(n);
  double width = 0.0;  // m: of the widest box
  for (int i = 0; i < n; ++i) {
    const double e = model.body(i).bound_radius + ws.margins[i];
    width = std::max(width, 2.0 * e);
    for (int a = 0; a < 3; ++a) {
      lo[3 * i + a] = state.bodies[i].p_WB(a) - e;
      hi[3 * i + a] = state.bodies[i].p_WB(a) + e;
    }
  }
  const double strip_width = width > 0.0 ? width : 1.0;  // m (no box has size: any width will do)
  for (int i = 0; i < n; ++i) strip[i] = std::floor(state.bodies[i].p_WB.y() / strip_width);
  // Insertion sort on (strip, lo x): the bodies barely move between steps, so this is nearly linear.
  const auto before = [&](int a, int b) { return strip[a] < strip[b] || (strip[a] == strip[b] && lo[3 * a] < lo[3 * b]); };
  for (int k = 1; k < n; ++k) {
    const int v = order[k];
    int m = k - 1;
    while (m >= 0 && before(v, order[m])) {
      order[m + 1] = order[m];
      --m;
    }
    order[m + 1] = v;
  }
  // Per place in the order: lo x, hi x, lo y, hi y, lo z, hi z, strip, and
  // where the next strip starts.
  constexpr int kStride = 8;
  ws.sorted_boxes.resize(kStride * n);
  for (int k = 0; k < n; ++k) {
    const int i = order[k];
    double* b = &ws.sorted_boxes[kStride * k];
    b[0] = lo[3 * i];
    b[1] = hi[3 * i];
    b[2] = lo[3 * i + 1];
    b[3] = hi[3 * i + 1];
    b[4] = lo[3 * i + 2];
    b[5] = hi[3 * i + 2];
    b[6] = strip[i];
  }
  for (int k = n - 1, next = n; k >= 0; --k) {
    if (k + 1 < n && ws.sorted_boxes[kStride * (k + 1) + 6] != ws.sorted_boxes[kStride * k + 6]) next = k + 1;
    ws.sorted_boxes[kStride * k + 7] = next;
  }
  // The sweep: each box against the boxes after it in its strip that start
  // before it ends, and against the boxes of the next strip (if it is the
  // neighbouring one) that overlap it in x; two sleepers make no pair. In
  // `parts` contiguous runs of the order, each run's directions in its own
  // list, then merged and sorted.
  const double* box = ws.sorted_boxes.data();
  runParts(ws, parts, [&](int part) {
    std::vector<std::pair<int, int>>& pairs = ws.parts[part].directions;
    pairs.clear();
    const int begin = n * part / parts, end = n * (part + 1) / parts;
    const auto overlap = [&](int k, int m, bool k_asleep) {
      const double *a = box + kStride * k, *b = box + kStride * m;
      if ((b[2] <= a[3]) & (a[2] <= b[3]) & (b[4] <= a[5]) & (a[4] <= b[5]) &
          !(k_asleep && state.bodies[order[m]].asleep)) {
        pairs.emplace_back(order[k], order[m]);  // both ways: each body's points against the other's solid
        pairs.emplace_back(order[m], order[k]);
      }
    };
    int next_from = -1;  // in the next strip: the first box that may still reach the current one
    for (int k = begin; k < end; ++k) {
      const double* a = box + kStride * k;
      const bool asleep = state.bodies[order[k]].asleep;
      const int strip_end = static_cast<int>(a[7]);
      for (int m = k + 1; m < strip_end && box[kStride * m] <= a[1]; ++m) overlap(k, m, asleep);
      if (strip_end == n || box[kStride * strip_end + 6] != a[6] + 1.0) continue;
      // Boxes are at most `width` long: one starting before lo − width ends before lo.
      if (next_from < strip_end) next_from = strip_end;
      const int next_end = static_cast<int>(box[kStride * strip_end + 7]);
      while (next_from < next_end && box[kStride * next_from] < a[0] - width) ++next_from;
      for (int m = next_from; m < next_end && box[kStride * m] <= a[1]; ++m) {
        if (a[0] <= box[kStride * m + 1]) overlap(k, m, asleep);
      }
    }
  });
  if (parts == 1) {
    ws.directions.swap(ws.parts[0].directions);
  } else {
    ws.directions.clear();
    for (int k = 0; k < parts; ++k) {
      ws.directions.insert(ws.directions.end(), ws.parts[k].directions.begin(), ws.parts[k].directions.end());
    }
  }
  std::sort(ws.directions.begin(), ws.directions.end());
}

// ---------------------------------------------------------------- impulses

bool keyLess(int body_a, int other_a, int item_a, int point_a, int body_b, int other_b, int item_b, int point_b) {
  if (body_a != body_b) return body_a < body_b;
  if (other_a != other_b) return other_a < other_b;
  if (item_a != item_b) return item_a < item_b;
  return point_a < point_b;
}

using Velocities = std::vector<Workspace::Velocity>;

/// The velocity of `body`'s point relative to the other's along n, t₁ and
/// t₂ (Jacobian rows (d, r × d) per body: d·(v + ω × r) = d·v + ω·(r × d)).
inline Vec3 contactVelocity(const SolverContact& c, const Velocities& vel) {
  const Workspace::Velocity& a = vel[c.body];
  Vec3 u(c.normal_W.dot(a.v_W) + c.a.rn.dot(a.w_W), c.tangent1_W.dot(a.v_W) + c.a.rt1.dot(a.w_W),
         c.tangent2_W.dot(a.v_W) + c.a.rt2.dot(a.w_W));
  if (c.other >= 0) {
    const Workspace::Velocity& o = vel[c.other];
    u -= Vec3(c.normal_W.dot(o.v_W) + c.o.rn.dot(o.w_W), c.tangent1_W.dot(o.v_W) + c.o.rt1.dot(o.w_W),
              c.tangent2_W.dot(o.v_W) + c.o.rt2.dot(o.w_W));
  }
  return u;
}

inline double normalVelocity(const SolverContact& c, const Velocities& vel) {
  double u = c.normal_W.dot(vel[c.body].v_W) + c.a.rn.dot(vel[c.body].w_W);
  if (c.other >= 0) u -= c.normal_W.dot(vel[c.other].v_W) + c.o.rn.dot(vel[c.other].w_W);
  return u;
}

/// Applies the impulse λ_N n + λ₁ t₁ + λ₂ t₂ at a contact: + to `body`, − to the other.
inline void applyImpulse(const SolverContact& c, double ln, double l1, double l2, Velocities& vel) {
  const Vec3 P = ln * c.normal_W + l1 * c.tangent1_W + l2 * c.tangent2_W;
  vel[c.body].v_W += c.a.inv_mass * P;
  vel[c.body].w_W += ln * c.a.turn_n + l1 * c.a.turn_t1 + l2 * c.a.turn_t2;
  if (c.other >= 0) {
    vel[c.other].v_W -= c.o.inv_mass * P;
    vel[c.other].w_W -= ln * c.o.turn_n + l1 * c.o.turn_t1 + l2 * c.o.turn_t2;
  }
}

/// Starts a contact from the impulse it carried last step (if it existed,
/// see matchLastImpulses), applied to the bodies before the first sweep.
void warmStart(const Model& model, const Contact& contact, const State& state, Velocities& vel, SolverContact& c) {
  if (contact.last_impulse < 0) return;
  const ContactImpulse last = state.contact_impulses[contact.last_impulse];
  c.normal_impulse = last.normal;
  c.tangent_impulse = Eigen::Vector2d(c.tangent1_W.dot(last.tangent_W), c.tangent2_W.dot(last.tangent_W));
  const double limit = model.contact().friction * c.normal_impulse;
  if (c.tangent_impulse.norm() > limit) c.tangent_impulse *= limit / c.tangent_impulse.norm();
  applyImpulse(c, c.normal_impulse, c.tangent_impulse.x(), c.tangent_impulse.y(), vel);
}

/// Finds each contact's impulse of the last step: both lists are sorted by
/// key, so one merge walk does it.
void matchLastImpulses(const State& state, std::vector<Contact>& contacts) {
  const std::vector<ContactImpulse>& last = state.contact_impulses;
  std::size_t k = 0;
  for (Contact& c : contacts) {
    while (k < last.size() &&
           keyLess(last[k].body, last[k].other, last[k].item, last[k].point, c.body, c.other, c.item, c.point)) {
      ++k;
    }
    const bool same = k < last.size() && last[k].body == c.body && last[k].other == c.other && last[k].item == c.item &&
                      last[k].point == c.point;
    c.last_impulse = same ? static_cast<int>(k) : -1;
  }
}

Mat3 worldInverseInertia(const BodyModel& b, const Quat& q_WB) {
  const Mat3 R = q_WB.toRotationMatrix();
  return R * b.inv_inertia_B.asDiagonal() * R.transpose();
}

/// Coulomb friction on one contact by maximal dissipation: of the impulses
/// |λ| ≤ limit, the one that leaves the least slip energy ½ vᵀK⁻¹v, i.e. the
/// point of the disk nearest to the sticking impulse `stick` in K's metric
/// (K = TᵀKT, the 2×2 tangent block). Inside the disk it is `stick`;
/// outside, λ = (K + νI)⁻¹ K stick with ν > 0 such that |λ| = limit, and the
/// slip left after it is −νλ: the friction opposes the slip it leaves, as
/// Coulomb's law says, whatever K's rotational coupling. Being a projection
/// onto a convex set, it lets Gauss-Seidel converge (taking the direction
/// from the slip before the update instead can cycle). ν solves the secular
/// equation 1/|λ(ν)| = 1/limit by Newton's method in K's eigenbasis (Moré
/// and Sorensen's trust-region step). 1/|λ(ν)| is concave and increasing,
/// so from any ν ≤ ν* Newton climbs to ν* without overshooting, and from
/// ν > ν* its first step lands below ν*: `nu` (in: a guess, such as the
/// contact's ν of the last sweep; out: the ν found, 0 inside the disk)
/// saves most of the iterations of a converging Gauss-Seidel.
Eigen::Vector2d frictionOnDisk(const Eigen::Matrix2d& K, SolverContact::TangentEigen& eigen,
                               const Eigen::Vector2d& stick, double limit, double& nu) {
  if (stick.squaredNorm() <= limit * limit) {
    nu = 0.0;
    return stick;
  }
  if (limit <= 0.0) return Eigen::Vector2d::Zero();
  if (!eigen.ready) {  // K = Q diag(k) Qᵀ, closed form for a symmetric 2×2; once per contact and step
    const double mean = 0.5 * (K(0, 0) + K(1, 1)), half_gap = 0.5 * (K(0, 0) - K(1, 1));
    const double radius = std::sqrt(half_gap * half_gap + K(0, 1) * K(0, 1));
    eigen.isotropic = radius <= 1e-12 * mean;
    eigen.k = Eigen::Vector2d(mean + radius, mean - radius);
    eigen.q1 =
        half_gap >= 0.0 ? Eigen::Vector2d(half_gap + radius, K(0, 1)) : Eigen::Vector2d(K(0, 1), radius - half_gap);
    if (!eigen.isotropic) eigen.q1.normalize();
    eigen.ready = true;
  }
  if (eigen.isotropic) return stick * (limit / stick.norm());  // the plain projection
  const Eigen::Vector2d& k = eigen.k;
  const Eigen::Vector2d& q1 = eigen.q1;
  const Eigen::Vector2d q2(-q1.y(), q1.x());
  const Eigen::Vector2d c(q1.dot(stick), q2.dot(stick));
  const Eigen::Vector2d kc = k.cwiseProduct(c);
  const double inv_limit = 1.0 / limit;
  nu = std::max(nu, 0.0);
  Eigen::Vector2d l = c;  // λ in the eigenbasis
  for (int i = 0; i < 30; ++i) {
    const Eigen::Vector2d d(1.0 / (k.x() + nu), 1.0 / (k.y() + nu));
    l = kc.cwiseProduct(d);
    const double size2 = l.squaredNorm(), size = std::sqrt(size2);
    if (std::abs(size - limit) <= 1e-10 * limit) break;
    // ν += φ/(−φ') for φ = 1/|λ| − 1/limit, with d|λ|/dν = −Σ λᵢ² dᵢ / |λ|.
    nu = std::max(nu + (size2 * inv_limit - size) * size / (l.x() * l.x() * d.x() + l.y() * l.y() * d.y()), 0.0);
  }
  l *= limit / l.norm();  // exactly on the cone
  return l.x() * q1 + l.y() * q2;
}

/// One Gauss-Seidel update of one contact, on the accumulated impulses given:
/// friction first (it matters less than not sinking), then the normal to
/// reach `target` (m/s). Returns the velocity change it made (m/s). The
/// normal velocity after the friction update is u_N + nᵀKT Δλ_T, so the
/// bodies are read once and written once.
double sweepContact(SolverContact& c, double& normal, Eigen::Vector2d& tangent, double target, double friction,
                    Velocities& vel) {
  const Vec3 u = contactVelocity(c, vel);
  if (std::abs(u.x() - target) < kRoundingSpeed && u.tail<2>().squaredNorm() < kRoundingSpeed * kRoundingSpeed) {
    return 0.0;  // the contact holds to rounding: an impulse now would only move λ's last bits
  }
  // Friction: stop the sliding if the cone |λ_T| ≤ μ λ_N allows; otherwise
  // slide with maximal dissipation (frictionOnDisk).
  const Eigen::Vector2d lt = frictionOnDisk(c.tangent_k, c.tangent_eigen, tangent - c.tangent_mass * u.tail<2>(),
                                            friction * normal, c.friction_nu);
  const Eigen::Vector2d dlt = lt - tangent;
  tangent = lt;
  // Normal: reach the target velocity, never pull (λ_N ≥ 0).
  const double vn = u.x() + c.normal_tangent_k.dot(dlt);
  const double ln = std::max(normal - c.normal_mass * (vn - target), 0.0);
  const double dln = ln - normal;
  normal = ln;
  applyImpulse(c, dln, dlt.x(), dlt.y(), vel);
  return (std::abs(dln) + dlt.norm()) / c.normal_mass;
}

/// Sorts the contacts into islands (findIslands). Fills ws.island_contacts
/// (contact indices, island by island, each island in contact order) and
/// ws.island_starts (offsets).
void groupIslands(const Model& model, const State& state, Workspace& ws) {
  findIslands(model, state, ws);
  // A counting sort by island root: islands in root order, each island's
  // contacts in contact order.
  const std::vector<int>& root = ws.island_root;
  std::vector<int>& next = ws.island_of;  // per root: where its island's next contact goes
  next.assign(model.bodyCount(), 0);
  for (const Contact& c : ws.contacts) ++next[root[c.body]];
  ws.island_starts.clear();
  int at = 0;
  for (int& slot : next) {
    const int count = slot;
    slot = at;
    if (count > 0) ws.island_starts.push_back(at);
    at += count;
  }
  ws.island_starts.push_back(at);
  ws.island_contacts.resize(ws.contacts.size());
  for (std::size_t k = 0; k < ws.contacts.size(); ++k) {
    ws.island_contacts[next[root[ws.contacts[k].body]]++] = static_cast<int>(k);
  }
}

/// One body's side of a contact: its Jacobian rows and turns for the arm r,
/// and its share of nᵀKn (returned), of TᵀKT (added to k) and of nᵀKT
/// (added to k_nt; nᵀT = 0, so no mass term).
double prepareSide(const Vec3& r, const SolverContact& c, double inv_mass, const Mat3& inv_I, SolverContact::Side& side,
                   Eigen::Matrix2d& k, Eigen::Vector2d& k_nt) {
  side.rn = r.cross(c.normal_W);
  side.rt1 = r.cross(c.tangent1_W);
  side.rt2 = r.cross(c.tangent2_W);
  side.inv_mass = inv_mass;
  side.turn_n = inv_I * side.rn;
  side.turn_t1 = inv_I * side.rt1;
  side.turn_t2 = inv_I * side.rt2;
  Eigen::Matrix2d ks;
  ks << inv_mass + side.rt1.dot(side.turn_t1), side.rt1.dot(side.turn_t2),  //
      side.rt2.dot(side.turn_t1), inv_mass + side.rt2.dot(side.turn_t2);
  k += ks;
  k_nt += Eigen::Vector2d(side.rn.dot(side.turn_t1), side.rn.dot(side.turn_t2));
  return inv_mass + side.rn.dot(side.turn_n);
}

/// The entries of the notes' K = M⁻¹𝐈 − r* I⁻¹ r* a contact's solve needs
/// (nᵀKn = M⁻¹ + (r×n)ᵀ I⁻¹ (r×n), and TᵀKT likewise, with the other body's
/// terms added), and its target normal velocity. A sleeping body is part of
/// the ground: no mass terms. `previous` is the solver contact before it
/// in the island, if any.
void prepareContact(const Model& model, const State& state, const std::vector<Mat3>& inv_I_W, double h,
                    const Contact& contact, const SolverContact* previous, SolverContact& c) {
  const Vec3& n = contact.normal_W;
  c.body = contact.body;
  c.other = contact.other;
  c.normal_W = n;
  if (previous != nullptr && previous->normal_W == n) {  // the points of one region share n and its tangents
    c.tangent1_W = previous->tangent1_W;
    c.tangent2_W = previous->tangent2_W;
  } else {
    c.tangent1_W = (std::abs(n.x()) < 0.57 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    c.tangent2_W = n.cross(c.tangent1_W);
  }
  Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
  Eigen::Vector2d k_nt = Eigen::Vector2d::Zero();
  double knn = prepareSide(contact.r_W, c, model.body(c.body).inv_mass, inv_I_W[c.body], c.a, k, k_nt);
  if (c.other >= 0 && !state.bodies[c.other].asleep) {
    knn += prepareSide(contact.r_other_W, c, model.body(c.other).inv_mass, inv_I_W[c.other], c.o, k, k_nt);
  } else if (c.other >= 0) {
    c.o = SolverContact::Side();  // a sleeper: ground, no terms (for the scene, other < 0, o is never read)
  }
  c.normal_mass = 1.0 / knn;
  c.tangent_k = k;
  c.normal_tangent_k = k_nt;
  c.tangent_mass = k.inverse();
  c.separation = contact.separation;
  c.target_normal_velocity = c.separation > 0.0 ? -c.separation / h : 0.0;
  c.normal_impulse = 0.0;
  c.tangent_impulse.setZero();
  c.friction_nu = 0.0;
  c.tangent_eigen.ready = false;
}

/// For the solver contacts [first, last) of one island: prepare, warm
/// start, restitution (impact passes), projected Gauss-Seidel; then the
/// results go back to the contacts.
void solveIsland(const Model& model, int first, int last, double h, const State& state, Velocities& vel, Workspace& ws,
                 StepScratch& scratch) {
  const ContactSettings& cs = model.contact();
  const double threshold = model.restitutionThreshold();
  SolverContact* const begin = ws.solver_contacts.data() + first;
  SolverContact* const end = ws.solver_contacts.data() + last;
  double fastest = 0.0;  // (m/s)²: the largest contact speed, each taken before its warm start
  for (int k = first; k < last; ++k) {
    const Contact& contact = ws.contacts[ws.island_contacts[k]];
    SolverContact& c = ws.solver_contacts[k];
    c.contact = ws.island_contacts[k];
    prepareContact(model, state, ws.inverse_inertias, h, contact, k > first ? &c - 1 : nullptr, c);
    fastest = std::max(fastest, contactVelocity(c, vel).squaredNorm());
    warmStart(model, contact, state, vel, c);
  }
  // Sweeps stop once none changes a velocity by more than 1e-7 m/s (1e-10 m
  // of drift a step: what a resting stack needs), or by more than 1e-6 of
  // the fastest contact's speed when the island moves (a relative residual).
  const double tolerance = std::max(1e-7, 1e-6 * std::sqrt(fastest));
  // Impacts first, as a sequence of simultaneous collisions: the contacts
  // arriving faster than the threshold are solved together to separate at
  // e × their approach speed (the pre-solve speed, for the first pass).
  // If that sets other contacts approaching (an impulse passed along a row
  // of touching bodies), they collide in the next pass: Newton's cradle.
  // Each pass has its own impulses, so a collision, once resolved, does not
  // keep pushing.
  if (cs.restitution > 0.0) {
    const int max_passes = 2 * (last - first) + 2;
    std::vector<int>& hit = scratch.impact_contacts;
    for (int pass = 0; pass < max_passes; ++pass) {
      hit.clear();
      for (SolverContact* c = begin; c != end; ++c) {
        const double vn = normalVelocity(*c, vel);
        const bool arrives = c->separation <= 0.0 || vn * h < -c->separation;
        if (arrives && vn < -threshold) {
          c->impact_target = -cs.restitution * vn;
          c->impact_normal = 0.0;
          c->impact_tangent.setZero();
          hit.push_back(static_cast<int>(c - begin));
        }
      }
      if (hit.empty()) break;
      for (int sweep = 0; sweep < cs.iterations; ++sweep) {
        double largest = 0.0;
        for (int k : hit) {
          SolverContact& c = begin[k];
          largest =
              std::max(largest, sweepContact(c, c.impact_normal, c.impact_tangent, c.impact_target, cs.friction, vel));
        }
        if (largest < tolerance) break;
      }
    }
  }
  // Then projected Gauss-Seidel over every contact: no penetration, Coulomb
  // friction; a speculative contact may close its gap, no more.
  double recent[4] = {0.0, 0.0, 0.0, 0.0};  // the last four sweeps' largest changes
  for (int sweep = 0; sweep < cs.iterations; ++sweep) {
    double largest = 0.0;
    for (SolverContact* c = begin; c != end; ++c) {
      largest = std::max(largest, sweepContact(*c, c->normal_impulse, c->tangent_impulse, c->target_normal_velocity,
                                               cs.friction, vel));
    }
    if (largest < tolerance) break;
    // Stalled: four sweeps took off less than a tenth. Gauss-Seidel on
    // friction whose limit moves with the normal impulse can settle into a
    // small cycle instead of converging; more sweeps would not change it.
    if (sweep >= 8 && largest > 0.9 * recent[sweep % 4]) break;
    recent[sweep % 4] = largest;
  }
  for (const SolverContact* c = begin; c != end; ++c) {
    Contact& contact = ws.contacts[c->contact];
    contact.normal_impulse = c->normal_impulse;
    contact.tangent_impulse_W = c->tangent_impulse.x() * c->tangent1_W + c->tangent_impulse.y() * c->tangent2_W;
    contact.predicted_separation = c->separation + h * normalVelocity(*c, vel);
  }
}

}  // namespace

/// How many parts to split `work` units into: one unless there is enough
/// work for a second core to pay (and a pool to run it on).
int partsFor(Workspace& ws, std::size_t work) {
  static const int cores = static_cast<int>(std::thread::hardware_concurrency());  // a system call: once
  int threads = ws.threads > 0 ? ws.threads : cores;
  threads = std::max(1, std::min(threads, 8));
  if (threads == 1 || work < ws.min_parallel_work) return 1;  // the hand-over would cost more than it saves
  if (!ws.pool || ws.pool->threads() != threads) ws.pool = std::make_shared<WorkerPool>(threads);
  return threads;
}

void detectContacts(const Model& model, const State& state, double h, Workspace& ws) {
  ws.contacts.clear();
  ws.deepest_penetration = 0.0;
  const int n = static_cast<int>(model.bodyCount());
  const bool multi = n > 1 && model.contact().method != ContactMethod::kShapeMatching;
  if (model.scene().empty() && !multi) {
    ws.in_contact.clear();  // no scene, no other body: no contact (and no allocation)
    return;
  }
  ws.in_contact.assign(model.bodyCount(), 0);
  const ContactSettings& cs = model.contact();
  const bool impulse = cs.method == ContactMethod::kImpulse;
  const auto margin = [&](int body) {
    if (state.bodies[body].asleep) return std::max(cs.position_slop, 1e-4);
    if (cs.method == ContactMethod::kPenaltyQuadratic) return cs.penalty_buffer;
    if (cs.method == ContactMethod::kPenaltyLogBarrier) return cs.barrier_buffer;
    return speculativeMargin(model.body(body), state.bodies[body], h, cs.position_slop);
  };
  // Body against body, both ways: a's points against o's solid for every
  // pair the broad phase keeps, as directions (a, o) sorted by a then o.
  ws.directions.clear();
  int parts = 1;
  if (multi) {
    ws.margins.resize(n);
    for (int i = 0; i < n; ++i) ws.margins[i] = margin(i);
    std::size_t awake = 0;
    for (const BodyState& b : state.bodies) awake += !b.asleep;
    parts = partsFor(ws, awake);
    if (ws.parts.size() < static_cast<std::size_t>(parts)) ws.parts.resize(parts);
    broadPhase(model, state, parts, ws);
  }
  // Body by body (each against the scene, then against the others in
  // order), so contacts come out sorted by key; split over the cores in
  // contiguous ranges of bodies, merged in order.
  if (ws.parts.empty()) ws.parts.resize(1);
  runParts(ws, parts, [&](int k) {
    StepScratch& out = ws.parts[k];
    out.contacts.clear();
    out.deepest = 0.0;
    const int begin = n * k / parts, end = n * (k + 1) / parts;
    auto dir = std::lower_bound(ws.directions.begin(), ws.directions.end(), std::make_pair(begin, -1));
    for (int body = begin; body < end; ++body) {
      const BodyState& s = state.bodies[body];
      if (!s.asleep && !model.scene().empty()) {
        out.candidates.clear();
        scanScene(model, s, body, multi ? ws.margins[body] : margin(body), out.separations,
                  [&](int item, int point, double separation, const Vec3& normal) {
                    out.candidates.push_back({-1, item, point, 0, separation, normal});
                    out.deepest = std::max(out.deepest, -separation);
                  });
        if (!out.candidates.empty()) emitContacts(model, state, body, impulse, out);
      }
      for (; dir != ws.directions.end() && dir->first == body; ++dir) {
        const int o = dir->second;
        out.candidates.clear();
        scanBody(model, state, body, o, ws.margins[body] + ws.margins[o],
                 [&](int point, double separation, const Vec3& normal) {
                   out.candidates.push_back({o, -1, point, 0, separation, normal});
                   out.deepest = std::max(out.deepest, -separation);
                 });
        if (!out.candidates.empty()) emitContacts(model, state, body, impulse, out);
      }
    }
  });
  if (parts == 1) {
    ws.contacts.swap(ws.parts[0].contacts);  // no copy; the old buffer is reused next time
  } else {
    for (int k = 0; k < parts; ++k) {
      ws.contacts.insert(ws.contacts.end(), ws.parts[k].contacts.begin(), ws.parts[k].contacts.end());
    }
  }
  for (int k = 0; k < parts; ++k) ws.deepest_penetration = std::max(ws.deepest_penetration, ws.parts[k].deepest);
  for (const Contact& c : ws.contacts) {
    ws.in_contact[c.body] = 1;
    if (c.other >= 0) ws.in_contact[c.other] = 1;
  }
}

void findIslands(const Model& model, const State& state, Workspace& ws) {
  std::vector<int>& parent = ws.island_root;
  parent.resize(model.bodyCount());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  const auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Contact& c : ws.contacts) {
    if (c.other < 0 || state.bodies[c.other].asleep || state.bodies[c.body].asleep) continue;
    const int a = find(c.body), b = find(c.other);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the island's smallest body
  }
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = find(static_cast<int>(i));
}

bool wakeTouchedSleepers(const Model& model, State& state, const Workspace& ws, double h) {
  // Wake a sleeper when an awake body comes at it faster than a resting
  // contact would (gravity's one step), or presses in deeper than the slop.
  const double still = model.sleep().linear_velocity + model.gravity().norm() * h;
  bool woke = false;
  for (const Contact& c : ws.contacts) {
    if (c.other < 0) continue;
    BodyState &a = state.bodies[c.body], &o = state.bodies[c.other];
    if (a.asleep == o.asleep) continue;
    const BodyState& awake = a.asleep ? o : a;
    BodyState& sleeper = a.asleep ? a : o;
    const Vec3 w = awake.q_WB * awake.w_B;
    const Vec3 arm = a.asleep ? c.r_other_W : c.r_W;
    const double approach = std::abs(c.normal_W.dot(awake.v_WB + w.cross(arm)));
    if (approach > still || c.separation < -model.contact().position_slop) {
      sleeper.asleep = false;
      sleeper.still_time = 0.0;
      woke = true;
    }
  }
  return woke;
}

void solveContactImpulses(const Model& model, State& state, double h, Workspace& ws) {
  if (ws.contacts.empty()) {
    state.contact_impulses.clear();
    return;
  }
  // The bodies in contact, in world axes: v, ω_W = R w_B and I⁻¹_W = R I⁻¹ Rᵀ
  // (a sleeper's velocities are zero and it has no inertia terms: it is ground).
  Velocities& vel = ws.velocities;
  vel.resize(model.bodyCount());
  ws.inverse_inertias.resize(model.bodyCount());
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    if (!ws.in_contact[i]) continue;
    const BodyState& b = state.bodies[i];
    vel[i].v_W = b.v_WB;
    vel[i].w_W = b.q_WB * b.w_B;
    if (!b.asleep) ws.inverse_inertias[i] = worldInverseInertia(model.body(i), b.q_WB);
  }
  // Islands: contacts only couple bodies they join (the scene and sleepers
  // join nothing), so each island is solved on its own, to its own
  // convergence: a box still bouncing does not keep the others sweeping.
  // Islands share no body, so they split over the cores with the same result.
  matchLastImpulses(state, ws.contacts);
  groupIslands(model, state, ws);
  const int islands = static_cast<int>(ws.island_starts.size()) - 1;
  const int parts = islands > 1 ? partsFor(ws, ws.contacts.size()) : 1;
  ws.parts.resize(std::max<std::size_t>(ws.parts.size(), parts));
  ws.solver_contacts.resize(ws.contacts.size());
  runParts(ws, parts, [&](int part) {
    // Contiguous runs of islands holding about equal numbers of contacts.
    const std::size_t total = ws.contacts.size();
    for (int k = 0; k < islands; ++k) {
      const std::size_t at = static_cast<std::size_t>(ws.island_starts[k]);
      if (static_cast<int>(at * parts / total) != part) continue;
      solveIsland(model, ws.island_starts[k], ws.island_starts[k + 1], h, state, vel, ws, ws.parts[part]);
    }
  });
  // The contacts come sorted by key (see detectContacts), and so do these.
  // A body a contact pushes (λ_N > 0) is held up, not merely touching.
  std::vector<char>& held = ws.held_still;
  held.assign(model.bodyCount(), 0);
  state.contact_impulses.clear();
  for (const Contact& c : ws.contacts) {
    state.contact_impulses.push_back({c.body, c.other, c.item, c.point, c.normal_impulse, c.tangent_impulse_W});
    if (c.normal_impulse > 0.0) {
      held[c.body] = 1;
      if (c.other >= 0) held[c.other] = 1;
    }
  }
  // Velocities below kRestingSpeed are rounding: zero, so that the body rests
  // exactly. A body held up and left exactly still is in equilibrium.
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    BodyState& b = state.bodies[i];
    if (!ws.in_contact[i] || b.asleep) continue;
    if (vel[i].v_W.squaredNorm() < kRestingSpeed * kRestingSpeed &&
        vel[i].w_W.squaredNorm() < kRestingSpeed * kRestingSpeed) {
      b.v_WB.setZero();
      b.w_B.setZero();
      continue;
    }
    held[i] = 0;
    b.v_WB = vel[i].v_W;
    b.w_B = b.q_WB.conjugate() * vel[i].w_W;
  }
}

void correctPositions(const Model& model, State& state, Workspace& ws) {
  const double slop = model.contact().position_slop;
  // Resting contacts end the step where they began: nothing to correct.
  // (Linear prediction; rotation adds O(h²ω²r), far below the slop at rest.)
  // Only the islands (of the impulse solve) with a contact predicted to end
  // deeper than half the slop are corrected (the prediction is linear: half
  // the slop is its margin).
  std::vector<char>& needs = ws.island_flags;  // per island root
  needs.assign(model.bodyCount(), 0);
  bool any = false;
  for (const Contact& c : ws.contacts) {
    if (c.predicted_separation <= -0.5 * slop) needs[ws.island_root[c.body]] = any = true;
  }
  if (!any) return;
  std::vector<int>& todo = ws.correct_contacts;  // in contact order
  todo.clear();
  for (std::size_t k = 0; k < ws.contacts.size(); ++k) {
    if (needs[ws.island_root[ws.contacts[k].body]]) todo.push_back(static_cast<int>(k));
  }
  constexpr int kSweeps = 4;
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    double deepest = 0.0;
    for (const int index : todo) {
      const Contact& c = ws.contacts[index];
      const BodyModel& b = model.body(c.body);
      BodyState& s = state.bodies[c.body];
      const ContactPoint& p = b.contact_points[c.point];
      const Vec3 arm = s.q_WB * p.r_B;
      Vec3 n;
      double separation;
      BodyState* o = nullptr;
      if (c.other < 0) {
        separation = model.scene()[c.item].eval(s.p_WB + arm, &n) - p.radius;
      } else {
        o = &state.bodies[c.other];
        Vec3 n_O;
        separation =
            model.body(c.other).solid_B.front().eval(o->q_WB.conjugate() * (s.p_WB + arm - o->p_WB), &n_O) - p.radius;
        n = o->q_WB * n_O;
        if (o->asleep) o = nullptr;  // a sleeper stays put, like the ground
      }
      const double C = separation + slop;
      if (C >= 0.0) continue;
      deepest = std::min(deepest, C);
      const Vec3 r = arm - p.radius * n;
      const Mat3 inv_I = worldInverseInertia(b, s.q_WB);
      const Vec3 rn = r.cross(n);
      double k = b.inv_mass + rn.dot(inv_I * rn);
      Vec3 r_o = Vec3::Zero();
      Mat3 inv_I_o = Mat3::Zero();
      if (o != nullptr) {
        r_o = s.p_WB + r - o->p_WB;
        inv_I_o = worldInverseInertia(model.body(c.other), o->q_WB);
        const Vec3 on = r_o.cross(n);
        k += model.body(c.other).inv_mass + on.dot(inv_I_o * on);
      }
      const Vec3 P = (-C / k) * n;  // positional impulse that closes C to first order
      const auto move = [](BodyState& x, double inv_mass, const Mat3& inv_I_W, const Vec3& arm_W, const Vec3& impulse) {
        x.p_WB += inv_mass * impulse;
        const Vec3 half_turn = 0.5 * (inv_I_W * arm_W.cross(impulse));
        x.q_WB = Quat(1.0, half_turn.x(), half_turn.y(), half_turn.z()) * x.q_WB;
        x.q_WB.normalize();
      };
      move(s, b.inv_mass, inv_I, r, P);
      if (o != nullptr) move(*o, model.body(c.other).inv_mass, inv_I_o, r_o, -P);
    }
    if (deepest >= 0.0) break;
  }
}

void accumulatePenaltyForces(const Model& model, const State& state, const Workspace& ws, int body, Vec3& force_W,
                             Vec3& torque_W) {
  const ContactSettings& cs = model.contact();
  const bool barrier = cs.method == ContactMethod::kPenaltyLogBarrier;
  constexpr double kStictionSpeed = 1e-3;  // m/s: friction is viscous below it (regularised Coulomb)
  for (const Contact& c : ws.contacts) {
    if (c.body != body && c.other != body) continue;
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
    const auto angular = [&](int i) { return state.bodies[i].q_WB * state.bodies[i].w_B; };
    Vec3 u = state.bodies[c.body].v_WB + angular(c.body).cross(c.r_W);
    if (c.other >= 0) u -= state.bodies[c.other].v_WB + angular(c.other).cross(c.r_other_W);
    const double vn = c.normal_W.dot(u);
    fn = std::max(fn - cs.penalty_damping * vn, 0.0);
    const Vec3 vt = u - vn * c.normal_W;
    const Vec3 f = fn * c.normal_W - (cs.friction * fn / std::max(vt.norm(), kStictionSpeed)) * vt;
    if (c.body == body) {
      force_W += f;
      torque_W += c.r_W.cross(f);
    } else {  // the other side of a body-body contact: equal and opposite
      force_W -= f;
      torque_W -= c.r_other_W.cross(f);
    }
  }
}

double minSeparation(const Model& model, const BodyState& s, int body, double margin) {
  double smallest = std::numeric_limits<double>::infinity();
  std::vector<double> scratch;
  scanScene(model, s, body, margin, scratch,
            [&](int, int, double separation, const Vec3&) { smallest = std::min(smallest, separation); });
  return smallest;
}

}  // namespace rigid_body_sim::core
