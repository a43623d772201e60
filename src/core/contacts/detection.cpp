// Contact detection (the step's first stage): each awake body's points
// against the scene's and the other bodies' signed distances (the pairs from
// the broad phase, broad_phase.cpp); the regions they form and their
// reduction are in contact_regions.cpp. The responses are in contact_solver.cpp (impulses)
// and penalty.cpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "box_pair.h"
#include "broad_phase.h"
#include "contact_regions.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "round_contact.h"
#include "step/scratch.h"
#include "step/sleep.h"

namespace rigid_body_sim::core {
namespace {

using detail::emitContacts;
using detail::PartScratch;
using detail::StepScratch;

/// Calls visit(item, point, separation, normal_W, r_B) for every contact point of
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
    const Vec3 n_W = plane ? Vec3(sdf.pose().rotation * sdf.normal()) : Vec3::Zero();
    const double phi_centre = plane ? n_W.dot(s.p_WB - sdf.pose().translation) : sdf.eval(s.p_WB);
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
          if (sep[i] < margin) visit(item, i, sep[i], n_W, Vec3(x[i], y[i], z[i]));
        }
      }
      for (const int i : b.rim_points) {  // closed form
        const ContactPoint& p = b.contact_points[i];
        const detail::RoundHit hit = detail::rimOnPlane(b.round[p.round], p.phase, n_B, phi_centre);
        if (hit.phi - p.radius < margin) visit(item, i, hit.phi - p.radius, n_W, hit.r_B);
      }
      continue;
    }
    for (int i = 0; i < n_points; ++i) {
      const ContactPoint& p = b.contact_points[i];
      if (p.round >= 0) {
        detail::RoundHit hit;
        if (detail::roundOnSdf(b.round[p.round], p.phase, sdf, R, s.p_WB, hit) && hit.phi - p.radius < margin) {
          visit(item, i, hit.phi - p.radius, hit.normal_F, hit.r_B);
        }
        continue;
      }
      const Vec3 r_W = R * p.r_B;
      Vec3 normal_W;
      const double separation = sdf.eval(s.p_WB + r_W, &normal_W) - p.radius;
      if (separation < margin) visit(item, i, separation, normal_W, p.r_B);
    }
  }
}

/// The same for the points of body a against the solid of body o: each
/// point is taken into o's frame, where the solid is.
template <class Visit>
[[gnu::flatten]] void scanBody(const Model& model, const State& state, int a, int o, double margin, Visit&& visit) {
  const BodyModel &ba = model.body(a), &bo = model.body(o);
  if (bo.solid_B.empty()) return;
  const Sdf& solid = bo.solid_B.front();
  const BodyState &sa = state.bodies[a], &so = state.bodies[o];
  const Quat q_OW = so.q_WB.conjugate();
  const Vec3 centre_O = q_OW * (sa.p_WB - so.p_WB);
  if (solid.eval(centre_O) - ba.bound_radius >= margin) return;
  const Mat3 R_OA = (q_OW * sa.q_WB).toRotationMatrix();  // a's frame into o's
  const Mat3 R_WO = so.q_WB.toRotationMatrix();
  // Two boxes: one axis for the pair (box_pair.h); the solid still says which points are near.
  detail::BoxInFrame box_a, box_o;
  const bool boxes = detail::pairBoxes(ba, bo, R_OA, centre_O, box_a, box_o);
  const detail::PairPlane plane = boxes ? detail::boxPairPlane(box_o, box_a, o < a) : detail::PairPlane{};
  if (boxes && plane.gap >= margin) return;  // apart along some axis by more than the margin: no point is near
  const std::vector<ContactPoint>& points = ba.contact_points;  // one look-up through the shared pointer
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const ContactPoint& p = points[i];
    const Vec3 p_O = centre_O + R_OA * p.r_B;
    const RoundFeature* round = p.round >= 0 ? &ba.round[p.round] : nullptr;
    // Outside the box around o's solid, grown by the margin: too far to touch.
    const double reach = margin + p.radius + (round != nullptr ? round->rho + round->half_length : 0.0);
    if ((p_O.array() < bo.solid_lo_B.array() - reach).any() || (p_O.array() > bo.solid_hi_B.array() + reach).any()) {
      continue;
    }
    Vec3 n_O;
    double separation;
    Vec3 r_B = p.r_B;
    if (round != nullptr) {
      detail::RoundHit hit;
      if (!detail::roundOnSdf(*round, p.phase, solid, R_OA, centre_O, hit)) continue;
      separation = hit.phi - p.radius;
      n_O = hit.normal_F;
      r_B = hit.r_B;
    } else {
      separation = solid.eval(p_O, &n_O) - p.radius;
    }
    if (!(separation < margin)) continue;  // also a NaN distance (a degenerate mesh's grid): no contact
    if (boxes) {
      separation = plane.n_F.dot(p_O) - plane.support - p.radius;
      n_O = plane.n_F;
    }
    // A point of a's face meets o's solid head on, or not at all: near o's
    // edges o's gradient turns sideways (a box sliding over another's face
    // samples would stop at each one), and o's own points against a's solid
    // give those contacts their true normal.
    if (p.normal_B.dot(p.normal_B) > 0.0 && (R_OA * p.normal_B).dot(n_O) > -SolverSettings::kFaceContactCos) continue;
    visit(i, separation, Vec3(R_WO * n_O), r_B);
  }
  if (!boxes) return;
  detail::PairPoint extra[detail::kMaxPairPoints];
  for (int k = 0, n = detail::pairPoints(box_o, box_a, plane, extra); k < n; ++k) {
    const double separation = plane.n_F.dot(extra[k].p_F) - plane.support;
    if (separation < margin)
      visit(extra[k].id, separation, Vec3(R_WO * plane.n_F), R_OA.transpose() * (extra[k].p_F - centre_O));
  }
}

/// How many pairs ahead the body-pair scan fetches the other body's data.
constexpr std::ptrdiff_t kFetchAhead = 4;

/// Asks the cache for what scanBody reads of body o: at N = 10,000 the
/// bodies' data (6 MB of models, 1.3 MB of states) outgrows the 2 MB L2,
/// and the first read of the other body's solid was a fifth of the scan's
/// time (perf, bench/HISTORY.md). Changes no result.
inline void fetchPairData(const Model& model, const State& state, int o) {
  const BodyModel& b = model.body(o);
  __builtin_prefetch(&b.solid_B);
  __builtin_prefetch(&b.bound_radius);
  __builtin_prefetch(&state.bodies[o]);
  __builtin_prefetch(&state.bodies[o].w_B);
}

/// How far a body can move in h, plus a small constant so resting contacts
/// persist (m). With restitution e the solve may send a point off at up to
/// (1 + e) times the speed it came with: a box landing on one corner turns
/// its other corners down faster than it fell, and a corner beyond the
/// margin would go through in the step (4 mm at 5 m/s and e = 0.5, as
/// tested), so the motion's share grows by that factor (physics §5.1).
double speculativeMargin(const BodyModel& b, const BodyState& s, double h, double slop, double min_margin,
                         double rebound = 1.0) {
  return (s.v_WB.norm() + s.w_B.norm() * b.bound_radius) * h * rebound + std::max(slop, min_margin);
}

/// The contacts at the current state (detectContacts without the waking),
/// when there is a scene or another body.
[[gnu::noinline]] void findContacts(const Model& model, const State& state, double h, Workspace& ws) {
  StepScratch& sc = *ws.scratch;
  ws.contacts.clear();
  ws.deepest_penetration = 0.0;
  const int n = static_cast<int>(model.bodyCount());
  const bool multi = n > 1 && model.contact().method != ContactMethod::kShapeMatching;
  sc.in_contact.resize(model.bodyCount());  // resize and fill: assign() was not inlined here
  std::fill(sc.in_contact.begin(), sc.in_contact.end(), 0);
  const ContactSettings& cs = model.contact();
  const bool impulse = cs.method == ContactMethod::kImpulse;
  const auto margin = [&](int body) {
    if (state.bodies[body].asleep) return std::max(cs.position_slop, model.solver().min_margin);
    if (cs.method == ContactMethod::kPenaltyQuadratic) return cs.penalty_buffer;
    if (cs.method == ContactMethod::kPenaltyLogBarrier) {  // and what the step may bring into it (barrier.h)
      return cs.barrier_buffer + speculativeMargin(model.body(body), state.bodies[body], h, 0.0, 0.0);
    }
    return speculativeMargin(model.body(body), state.bodies[body], h, cs.position_slop, model.solver().min_margin,
                             1.0 + model.maxRestitution());
  };
  // Body against body, both ways: a's points against o's solid for every
  // pair the broad phase keeps, as directions (a, o) sorted by a then o.
  sc.directions.clear();
  int parts = 1;
  if (multi) {
    sc.margins.resize(n);
    for (int i = 0; i < n; ++i) sc.margins[i] = margin(i);
    std::size_t awake = 0;
    for (const BodyState& b : state.bodies) awake += !b.asleep;
    parts = detail::partsFor(ws, awake);
    broadPhase(model, state, parts, ws);
  }
  // Body by body (each against the scene, then against the others in
  // order), so contacts come out sorted by key; split over the cores in
  // contiguous ranges of bodies, merged in order.
  if (sc.parts.empty()) sc.parts.resize(1);
  detail::runParts(ws, parts, [&](int k) {
    PartScratch& out = sc.parts[k];
    out.contacts.clear();
    out.deepest = 0.0;
    const Range range = partRange(n, k, parts);
    const int begin = static_cast<int>(range.begin), end = static_cast<int>(range.end);
    auto dir = std::lower_bound(sc.directions.begin(), sc.directions.end(), std::make_pair(begin, -1));
    for (int body = begin; body < end; ++body) {
      const BodyState& s = state.bodies[body];
      if (!s.asleep && !model.scene().empty()) {
        // A body struck in this step moves by what the blow gives it too: its
        // scene margin grows by the margin of the bodies that may strike it.
        double blow = 0.0;
        for (auto d = dir; d != sc.directions.end() && d->first == body; ++d)
          blow = std::max(blow, sc.margins[d->second]);
        out.candidates.clear();
        scanScene(model, s, body, (multi ? sc.margins[body] : margin(body)) + blow, out.separations,
                  [&](int item, int point, double separation, const Vec3& normal, const Vec3& r_B) {
                    out.candidates.push_back({-1, item, point, 0, separation, normal, r_B});
                    out.deepest = std::max(out.deepest, -separation);
                  });
        if (!out.candidates.empty()) emitContacts(model, state, body, impulse, out);
      }
      for (; dir != sc.directions.end() && dir->first == body; ++dir) {
        const int o = dir->second;
        if (sc.directions.end() - dir > kFetchAhead) fetchPairData(model, state, (dir + kFetchAhead)->second);
        out.candidates.clear();
        scanBody(model, state, body, o, sc.margins[body] + sc.margins[o],
                 [&](int point, double separation, const Vec3& normal, const Vec3& r_B) {
                   out.candidates.push_back({o, -1, point, 0, separation, normal, r_B});
                   out.deepest = std::max(out.deepest, -separation);
                 });
        if (!out.candidates.empty()) emitContacts(model, state, body, impulse, out);
      }
    }
  });
  if (parts == 1) {
    ws.contacts.swap(sc.parts[0].contacts);  // no copy; the old buffer is reused next time
  } else {
    for (int k = 0; k < parts; ++k) {
      ws.contacts.insert(ws.contacts.end(), sc.parts[k].contacts.begin(), sc.parts[k].contacts.end());
    }
  }
  for (int k = 0; k < parts; ++k) ws.deepest_penetration = std::max(ws.deepest_penetration, sc.parts[k].deepest);
  for (const Contact& c : ws.contacts) {
    sc.in_contact[c.body] = 1;
    if (c.other >= 0) sc.in_contact[c.other] = 1;
  }
}

}  // namespace

void detectContacts(const Model& model, State& state, double h, Workspace& ws) {
  const bool other_bodies = model.bodyCount() > 1 && model.contact().method != ContactMethod::kShapeMatching;
  if (model.scene().empty() && !other_bodies) {  // nothing to touch (and no allocation)
    ws.contacts.clear();
    ws.deepest_penetration = 0.0;
    ws.scratch->in_contact.clear();
    return;
  }
  findContacts(model, state, h, ws);
  // A woken body takes part from this step on: detect again with it awake.
  if (model.bodyCount() > 1 && wakeTouchedSleepers(model, state, ws, h)) findContacts(model, state, h, ws);
}

double minSeparation(const Model& model, const BodyState& s, int body, double margin) {
  double smallest = std::numeric_limits<double>::infinity();
  std::vector<double> scratch;
  scanScene(model, s, body, margin, scratch,
            [&](int, int, double separation, const Vec3&, const Vec3&) { smallest = std::min(smallest, separation); });
  return smallest;
}

}  // namespace rigid_body_sim::core
