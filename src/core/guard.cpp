// The speed limits and the finite-state guard (docs/physics.md §5.9).
#include "guard.h"

#include <algorithm>
#include <cmath>

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

bool finite(const BodyState& s) {
  // One sum of every component is finite when they all are (NaN and ±∞
  // carry through a sum); only a finite but overflowing sum needs a closer look.
  const double sum = s.p_WB.sum() + s.v_WB.sum() + s.q_WB.coeffs().sum() + s.w_B.sum() + s.still_time;
  if (std::isfinite(sum)) return true;
  return s.p_WB.allFinite() && s.v_WB.allFinite() && s.q_WB.coeffs().allFinite() && s.w_B.allFinite() &&
         std::isfinite(s.still_time);
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

void limitSpeeds(const Model& model, int i, BodyState& s, Workspace& ws) {
  const SpeedLimits& limits = model.limits();
  const bool linear = clampLength(s.v_WB, limits.linear);
  const bool angular = clampLength(s.w_B, limits.angular);  // |ω| is the same in B as in W
  if ((linear || angular) && (ws.speed_limited.empty() || ws.speed_limited.back() != i)) {
    ws.speed_limited.push_back(i);
  }
}

void keepPoses(const State& state, Workspace& ws) {
  std::vector<detail::KeptPose>& kept = ws.scratch->kept_poses;
  kept.resize(state.bodies.size());
  for (std::size_t i = 0; i < state.bodies.size(); ++i) kept[i] = {state.bodies[i].p_WB, state.bodies[i].q_WB};
}

void guardFinite(State& state, Workspace& ws) {
  const std::vector<detail::KeptPose>& kept = ws.scratch->kept_poses;
  for (std::size_t i = 0; i < state.bodies.size(); ++i) {
    BodyState& s = state.bodies[i];
    if (finite(s)) continue;
    const int body = static_cast<int>(i);
    ws.diverged.push_back({body, whatDiverged(s)});
    BodyState back;  // at rest, awake
    if (i < kept.size() && kept[i].p_WB.allFinite() && kept[i].q_WB.coeffs().allFinite()) {
      back.p_WB = kept[i].p_WB;
      back.q_WB = kept[i].q_WB;
    } else {  // it came in non-finite: no finite pose to go back to
      ws.diverged.back().what += " (no finite pose to go back to: the world origin)";
    }
    s = back;
    const auto involves = [body](const ContactKey& c) { return c.body == body || c.other == body; };
    auto& impulses = state.contact_impulses;
    impulses.erase(std::remove_if(impulses.begin(), impulses.end(), involves), impulses.end());
    ws.contacts.erase(std::remove_if(ws.contacts.begin(), ws.contacts.end(), involves), ws.contacts.end());
  }
}

}  // namespace rigid_body_sim::core
