// Contact regions and their reduction (contact_regions.h).
#include "contact_regions.h"

#include <algorithm>
#include <cmath>

#include "rigid_body_sim/core/contacts/contact.h"

namespace rigid_body_sim::core::detail {
namespace {

/// Of the candidates listed in `members` (one region), keeps at most four
/// that span its area (the usual contact-manifold reduction): the deepest
/// point, the farthest from it, the farthest from the line through both,
/// and the farthest on the other side of that line. Near-ties (within a
/// nanometre, or 1e-9 relative) go to the lowest point index, so the same
/// points are kept from step to step, which lets the solver warm-start.
/// Distances are rigid, so it works on the body-frame points.
void reduceRegion(const SolverSettings& settings, const std::vector<ContactCandidate>& cands, const Vec3& n_B,
                  std::vector<int>& members, std::vector<Vec3>& at) {
  const std::size_t n = members.size();
  if (n <= 4) return;
  at.resize(n);
  for (std::size_t k = 0; k < n; ++k) at[k] = cands[members[k]].r_B;
  // The index of the largest score (the first one on near-ties).
  const double relative = settings.reduction_tie_relative;
  const auto argmax = [n, relative](auto score, double tie) {
    std::size_t best = 0;
    double best_score = score(0);
    for (std::size_t k = 1; k < n; ++k) {
      const double sc = score(k);
      if (sc > best_score + tie + relative * std::abs(best_score)) {
        best_score = sc;
        best = k;
      }
    }
    return std::make_pair(best, best_score);
  };
  const std::size_t a =
      argmax([&](std::size_t k) { return -cands[members[k]].separation; }, settings.reduction_tie_depth).first;
  const std::size_t b2 =
      argmax([&](std::size_t k) { return (at[k] - at[a]).squaredNorm(); }, settings.reduction_tie_distance2).first;
  const Vec3 normal_of_ab = (at[b2] - at[a]).cross(n_B);  // in the plane, across the line ab
  const auto side = [&](std::size_t k) { return normal_of_ab.dot(at[k] - at[a]); };
  const auto [c, c_score] = argmax([&](std::size_t k) { return std::abs(side(k)); }, settings.reduction_tie_distance2);
  const double sign = side(c) >= 0.0 ? 1.0 : -1.0;
  const auto [d, d_score] = argmax([&](std::size_t k) { return -sign * side(k); }, settings.reduction_tie_distance2);
  const int kept[4] = {members[a], members[b2], members[c], members[d]};
  members.resize(2);
  members[0] = kept[0];
  members[1] = kept[1];
  if (c_score > 0.0) members.push_back(kept[2]);
  if (d_score > 0.0) members.push_back(kept[3]);
}

}  // namespace

[[gnu::flatten]] void emitContacts(const Model& model, const State& state, int body, bool reduce, PartScratch& out) {
  const double same_region_cos = model.solver().region_cos;
  const BodyModel& b = model.body(body);
  const BodyState& s = state.bodies[body];
  std::vector<ContactCandidate>& cands = out.candidates;
  // Region ids; candidates arrive grouped by item (or other body).
  int regions = 0, group_first_region = 0;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const bool new_group = i == 0 || cands[i].item != cands[i - 1].item || cands[i].other != cands[i - 1].other;
    if (new_group) {
      out.region_normals.clear();
      group_first_region = regions;
    } else if (cands[i].item >= 0 && model.scene()[cands[i].item].kind() == Sdf::Kind::kPlane) {
      cands[i].region = cands[i - 1].region;  // one normal: one region
      continue;
    }
    int r = -1;
    for (std::size_t k = 0; k < out.region_normals.size() && r < 0; ++k) {
      if (out.region_normals[k].dot(cands[i].normal_W) > same_region_cos) r = group_first_region + static_cast<int>(k);
    }
    if (r < 0) {
      out.region_normals.push_back(cands[i].normal_W);
      r = regions++;
    }
    cands[i].region = r;
  }
  // Reduce each region, then emit the kept candidates in key order (item,
  // then point): the contacts of a step come out sorted by (body, other,
  // item, point), which warm starting looks them up by.
  const Quat q_BW = s.q_WB.conjugate();
  std::vector<int>& kept = out.kept;
  kept.clear();
  std::size_t start = 0;
  for (int r = 0; r < regions; ++r) {
    out.region_members.clear();
    for (std::size_t i = start; i < cands.size(); ++i) {
      if (cands[i].region == r) out.region_members.push_back(static_cast<int>(i));
    }
    start = static_cast<std::size_t>(out.region_members.front());  // regions begin in order
    if (reduce) {
      reduceRegion(model.solver(), cands, q_BW * cands[out.region_members.front()].normal_W, out.region_members,
                   out.region_points);
    }
    kept.insert(kept.end(), out.region_members.begin(), out.region_members.end());
  }
  std::sort(kept.begin(), kept.end(), [&](int x, int y) {
    return cands[x].item != cands[y].item ? cands[x].item < cands[y].item : cands[x].point < cands[y].point;
  });
  const Mat3 R_WB = s.q_WB.toRotationMatrix();  // one matrix for all points: cheaper than q·r each
  for (int m : kept) {
    const ContactCandidate& cand = cands[m];
    const double radius = cand.point < 0 ? 0.0 : b.contact_points[cand.point].radius;  // a box pair's own point
    // Filled on the stack, then copied: the compiler drops the default
    // initialisation it overwrites (in place it zeroes the whole struct first).
    Contact c;
    c.body = body;
    c.other = cand.other;
    c.item = cand.item;
    c.point = cand.point;
    c.normal_W = cand.normal_W;
    c.r_W = R_WB * cand.r_B - radius * cand.normal_W;
    if (c.other >= 0) c.r_other_W = s.p_WB + c.r_W - state.bodies[c.other].p_WB;
    c.separation = cand.separation;
    out.contacts.push_back(c);
  }
}

}  // namespace rigid_body_sim::core::detail
