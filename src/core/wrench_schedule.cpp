#include "rigid_body_sim/core/wrench_schedule.h"

#include <algorithm>

namespace rigid_body_sim::core {

void WrenchSchedule::clear(int body) {
  entries_.erase(
      std::remove_if(entries_.begin(), entries_.end(), [body](const Entry& e) { return body < 0 || e.body == body; }),
      entries_.end());
}

void WrenchSchedule::dropFinished(double t) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [t](const Entry& e) { return e.end <= t; }),
                 entries_.end());
}

void WrenchSchedule::loadsFor(const Model& model, const State& state, double t, double h, Loads& out) const {
  out.clear();
  for (const Entry& e : entries_) {
    const double overlap = std::min(e.end, t + h) - std::max(e.start, t);
    if (!(overlap > 0.0)) continue;
    if (out.empty()) out.resize(model.bodyCount());
    Wrench w = e.axes_body < 0
                   ? e.wrench
                   : inWorldAxes(e.wrench, linkState(model.body(e.axes_body), state.bodies[e.axes_body]).q_WL);
    const double fraction = std::min(overlap / h, 1.0);
    w.force *= fraction;
    w.torque *= fraction;
    addWrench(model.body(e.body), out[e.body], w);
  }
}

}  // namespace rigid_body_sim::core
