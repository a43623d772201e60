// The speed limits and the finite-state guard (docs/physics.md §5.9).
#include "guard.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "scratch.h"

namespace rigid_body_sim::core {
namespace {

/// Scales x back to length `limit` if it is longer; false if it was not (or
/// is not finite: the guard's business). stableNorm: |x|² of a finite x may
/// overflow.
bool clampLength(Vec3& x, double limit) {
  const double n2 = x.squaredNorm();
  if (n2 <= limit * limit || !x.allFinite()) return false;
  x *= limit / (std::isfinite(n2) ? std::sqrt(n2) : x.stableNorm());
  return true;
}

std::string whatDiverged(const BodyState& s) {
  std::string what;
  const auto add = [&what](bool ok, const char* name) {
    if (ok) return;
    if (!what.empty()) what += ", ";
    what += name;
  };
  add(s.p_WB.allFinite(), "position");
  add(s.v_WB.allFinite(), "velocity");
  add(s.q_WB.coeffs().allFinite(), "orientation");
  add(s.w_B.allFinite(), "angular velocity");
  add(std::isfinite(s.still_time), "still time");
  return what;
}

}  // namespace

void holdToLimits(const Model& model, int i, BodyState& s, Workspace& ws) {
  const SpeedLimits& limits = model.limits();
  const bool linear = clampLength(s.v_WB, limits.max_linear_speed);
  const bool angular = clampLength(s.w_B, limits.max_angular_speed);  // |ω| is the same in B as in W
  if ((linear || angular) && (ws.speed_limited.empty() || ws.speed_limited.back() != i)) {
    ws.speed_limited.push_back(i);
  }
}

void putBack(int i, BodyState& s, Workspace& ws) {
  Divergence d{i, whatDiverged(s)};
  BodyState back;  // at rest, awake
  if (s.p_WB.allFinite() && s.q_WB.coeffs().allFinite()) {
    back.p_WB = s.p_WB;
    back.q_WB = s.q_WB;
  } else {  // no finite pose to go back to
    d.what += " (no finite pose to keep: the world origin)";
  }
  s = back;
  const std::lock_guard<std::mutex> lock(ws.scratch->guard_mutex);
  ws.diverged.push_back(std::move(d));
}

void finishGuard(State& state, Workspace& ws) {
  std::sort(ws.diverged.begin(), ws.diverged.end(),
            [](const Divergence& a, const Divergence& b) { return a.body < b.body; });
  for (const Divergence& d : ws.diverged) {
    const auto involves = [&d](const ContactKey& c) { return c.body == d.body || c.other == d.body; };
    auto& impulses = state.contact_impulses;
    impulses.erase(std::remove_if(impulses.begin(), impulses.end(), involves), impulses.end());
    ws.contacts.erase(std::remove_if(ws.contacts.begin(), ws.contacts.end(), involves), ws.contacts.end());
  }
}

}  // namespace rigid_body_sim::core
