// Touching pairs for the node's ~contacts (docs/physics.md §10.3).
#include "rigid_body_sim/core/contacts/contact_report.h"

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
    if (!touching(c)) continue;
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

void ContactLedger::update(const State& state, const std::vector<Contact>& step_contacts) {
  const std::size_t n = state.bodies.size();
  bool changed = was_asleep_.size() != n;
  was_asleep_.resize(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const char asleep = state.bodies[i].asleep ? 1 : 0;
    changed = changed || asleep != was_asleep_[i];
    was_asleep_[i] = asleep;
  }
  if (!changed) return;
  kept_for_.resize(n, 0);
  const auto asleep = [&](int b) { return b < 0 || state.bodies[b].asleep; };
  kept_.erase(
      std::remove_if(kept_.begin(), kept_.end(), [&](const Contact& c) { return !asleep(c.body) || !asleep(c.other); }),
      kept_.end());
  for (std::size_t i = 0; i < n; ++i) {
    if (!state.bodies[i].asleep) kept_for_[i] = 0;
  }
  for (const Contact& c : step_contacts) {
    if (!kept_for_[c.body] && asleep(c.body) && asleep(c.other) && touching(c)) kept_.push_back(c);
  }
  for (const Contact& c : kept_) kept_for_[c.body] = 1;
}

std::vector<Contact> ContactLedger::touchingNow(const State& state, const std::vector<Contact>& step_contacts) const {
  std::vector<Contact> now = kept_;
  for (const Contact& c : step_contacts) {
    const bool awake = !state.bodies[c.body].asleep || (c.other >= 0 && !state.bodies[c.other].asleep);
    if (awake && touching(c)) now.push_back(c);
  }
  return now;
}

void ContactLedger::removeBody(int body) {
  std::vector<Contact> kept;
  for (Contact c : kept_) {
    if (c.body == body || c.other == body) continue;
    if (c.body > body) --c.body;
    if (c.other > body) --c.other;
    kept.push_back(c);
  }
  kept_ = std::move(kept);
  if (static_cast<std::size_t>(body) < kept_for_.size()) kept_for_.erase(kept_for_.begin() + body);
  if (static_cast<std::size_t>(body) < was_asleep_.size()) was_asleep_.erase(was_asleep_.begin() + body);
}

void ContactLedger::insertBody(int body) {
  for (Contact& c : kept_) {
    if (c.body >= body) ++c.body;
    if (c.other >= body) ++c.other;
  }
  if (static_cast<std::size_t>(body) <= kept_for_.size()) kept_for_.insert(kept_for_.begin() + body, char{0});
  if (static_cast<std::size_t>(body) <= was_asleep_.size()) was_asleep_.insert(was_asleep_.begin() + body, char{0});
}

const std::vector<Contact>& StepContacts::touching() {
  if (!found_touching_) touching_ = ledger_.touchingNow(state_, step_contacts_);
  found_touching_ = true;
  return touching_;
}

const std::vector<ContactPairReport>& StepContacts::pairs() {
  if (!found_pairs_) pairs_ = contactPairs(model_, state_, touching());
  found_pairs_ = true;
  return pairs_;
}

}  // namespace rigid_body_sim::core
