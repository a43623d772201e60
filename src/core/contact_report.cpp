// Touching pairs for the node's ~contacts (docs/physics.md §10.3).
#include "rigid_body_sim/core/contact_report.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace rigid_body_sim::core {

std::vector<ContactPairReport> contactPairs(const Model& model, const State& state,
                                            const std::vector<Contact>& contacts) {
  const double dt = model.dt();
  std::map<std::tuple<int, int, int>, ContactPairReport> pairs;
  // The pair's normal: the normals weighted by their impulses, or without
  // any impulse, the deepest point's.
  std::map<std::tuple<int, int, int>, Vec3> weighted_normal;
  for (const Contact& c : contacts) {
    const bool touching = c.normal_impulse > 0.0 || c.separation <= 0.0;
    if (!touching) continue;
    // Between bodies, the report is on the lower index: seen from the other
    // side, the normal and the forces turn round.
    const bool flip = c.other >= 0 && c.other < c.body;
    const int body = flip ? c.other : c.body, other = flip ? c.body : c.other;
    const double sign = flip ? -1.0 : 1.0;
    ContactPairReport& r = pairs[{body, other, c.item}];
    r.body = body;
    r.other = other;
    r.item = c.item;
    if (r.points_W.empty() || -c.separation > r.depth) r.normal_W = sign * c.normal_W;
    r.points_W.push_back(state.bodies[c.body].p_WB + c.r_W);
    r.depth = std::max(r.depth, -c.separation);
    r.normal_force_W += sign * c.normal_impulse / dt * c.normal_W;
    r.friction_force_W += sign * c.tangent_impulse_W / dt;
    // (try_emplace: a default Eigen vector is not zero)
    weighted_normal.try_emplace({body, other, c.item}, Vec3::Zero()).first->second +=
        sign * c.normal_impulse * c.normal_W;
  }
  std::vector<ContactPairReport> out;
  out.reserve(pairs.size());
  for (auto& [key, r] : pairs) {
    const Vec3 n = weighted_normal.at(key);
    if (n.norm() > 0.0) r.normal_W = n.normalized();
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace rigid_body_sim::core
