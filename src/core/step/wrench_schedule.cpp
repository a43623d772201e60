#include "rigid_body_sim/core/step/wrench_schedule.h"

#include <algorithm>

namespace rigid_body_sim::core {

bool WrenchSchedule::add(int body, const Wrench& wrench, double start, double end, int axes_body) {
  if (body < 0) return false;
  if (count_.size() <= static_cast<std::size_t>(body)) count_.resize(static_cast<std::size_t>(body) + 1, 0);
  if (count_[body] >= kMaxPerBody) return false;
  ++count_[body];
  const auto at =
      std::upper_bound(waiting_.begin(), waiting_.end(), start, [](double s, const Entry& e) { return s < e.start; });
  waiting_.insert(at, {body, wrench, start, end, axes_body});
  return true;
}

void WrenchSchedule::hold(int body, const Wrench& wrench, double start, double timeout, int axes_body) {
  const auto at = std::lower_bound(held_.begin(), held_.end(), body, [](const Entry& e, int b) { return e.body < b; });
  const Entry entry{body, wrench, start, timeout, axes_body};
  if (at != held_.end() && at->body == body) {
    *at = entry;
  } else {
    held_.insert(at, entry);
  }
}

bool WrenchSchedule::holds(int body) const {
  return std::any_of(held_.begin(), held_.end(), [body](const Entry& e) { return e.body == body; });
}

std::size_t WrenchSchedule::count(int body) const {
  return body >= 0 && static_cast<std::size_t>(body) < count_.size() ? count_[body] : 0;
}

void WrenchSchedule::clear(int body) {
  const auto of = [body](const Entry& e) { return body < 0 || e.body == body; };
  acting_.erase(std::remove_if(acting_.begin(), acting_.end(), of), acting_.end());
  waiting_.erase(std::remove_if(waiting_.begin(), waiting_.end(), of), waiting_.end());
  held_.erase(std::remove_if(held_.begin(), held_.end(), of), held_.end());
  for (std::size_t i = 0; i < count_.size(); ++i) {
    if (body < 0 || static_cast<int>(i) == body) count_[i] = 0;
  }
}

std::size_t WrenchSchedule::removeBody(int body) {
  const std::size_t before = size();
  const auto gone = [body](const Entry& e) { return e.body == body || e.axes_body == body; };
  const auto renumber = [&](std::vector<Entry>& entries) {
    entries.erase(std::remove_if(entries.begin(), entries.end(), gone), entries.end());
    for (Entry& e : entries) {
      if (e.body > body) --e.body;
      if (e.axes_body > body) --e.axes_body;
    }
  };
  renumber(acting_);
  renumber(waiting_);
  renumber(held_);
  count_.assign(count_.size() > static_cast<std::size_t>(body) ? count_.size() - 1 : count_.size(), 0);
  for (const Entry& e : acting_) ++count_[e.body];
  for (const Entry& e : waiting_) ++count_[e.body];
  return before - size();
}

void WrenchSchedule::insertBody(int body) {
  for (std::vector<Entry>* entries : {&acting_, &waiting_, &held_}) {
    for (Entry& e : *entries) {
      if (e.body >= body) ++e.body;
      if (e.axes_body >= body) ++e.axes_body;
    }
  }
  if (static_cast<std::size_t>(body) <= count_.size()) count_.insert(count_.begin() + body, 0);
}

void WrenchSchedule::dropFinished(double t) {
  // The waiting wrenches that started are a prefix of waiting_.
  const auto started = std::find_if(waiting_.begin(), waiting_.end(), [t](const Entry& e) { return !(e.start < t); });
  acting_.insert(acting_.end(), waiting_.begin(), started);
  waiting_.erase(waiting_.begin(), started);
  const auto ended = [t](const Entry& e) { return e.end <= t; };
  for (const Entry& e : acting_) {
    if (ended(e)) --count_[e.body];
  }
  acting_.erase(std::remove_if(acting_.begin(), acting_.end(), ended), acting_.end());
  held_.erase(std::remove_if(held_.begin(), held_.end(), [t](const Entry& e) { return t - e.start > e.end; }),
              held_.end());
}

void WrenchSchedule::loadsFor(const Model& model, const State& state, double t, double h, Loads& out) const {
  out.clear();
  const auto add = [&](const Entry& e) {
    const double fraction = stepFraction(e.start, e.end, t, h);
    if (!(fraction > 0.0)) return;
    if (out.empty()) out.resize(model.bodyCount());
    Wrench w = e.axes_body < 0
                   ? e.wrench
                   : inWorldAxes(e.wrench, linkState(model.body(e.axes_body), state.bodies[e.axes_body]).q_WL);
    w.force *= fraction;
    w.torque *= fraction;
    addWrench(model.body(e.body), out[e.body], w);
  };
  for (const Entry& e : acting_) add(e);
  for (const Entry& e : waiting_) {  // sorted by start: stop at the first that starts after the step
    if (!(e.start < t + h)) break;
    add(e);
  }
  for (const Entry& e : held_) {
    // It acts on [start, start + timeout): the step from t acts if it starts
    // before the end (half a step of slack for rounding), in full.
    if (t - e.start > e.end - 0.5 * h) continue;
    if (out.empty()) out.resize(model.bodyCount());
    addWrench(model.body(e.body), out[e.body],
              e.axes_body < 0
                  ? e.wrench
                  : inWorldAxes(e.wrench, linkState(model.body(e.axes_body), state.bodies[e.axes_body]).q_WL));
  }
}

}  // namespace rigid_body_sim::core
