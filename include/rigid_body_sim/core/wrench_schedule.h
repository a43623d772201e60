// Wrenches applied over windows of sim time (the node's apply_wrench).
#pragma once

#include <limits>
#include <vector>

#include "rigid_body_sim/core/loads.h"
#include "rigid_body_sim/core/model.h"

namespace rigid_body_sim::core {

/// Wrenches, each on one body over [start, end) of sim time. A step of
/// length h from t receives every wrench weighted by the fraction of
/// [t, t + h) its window covers, so a window of any length delivers exactly
/// force × length of impulse, even when it does not line up with the steps.
/// Wrenches add up.
class WrenchSchedule {
 public:
  static constexpr double kForever = std::numeric_limits<double>::infinity();

  struct Entry {
    int body = 0;
    Wrench wrench;
    double start = 0.0;     ///< s, sim time
    double end = kForever;  ///< s, sim time; kForever: until cleared
    /// ≥ 0: the wrench is given in the root link axes of this other body and
    /// turns with it (re-expressed in world axes at the start of each step;
    /// wrench.frame is then kWorld). −1: wrench.frame says.
    int axes_body = -1;
  };

  void add(int body, const Wrench& wrench, double start, double end, int axes_body = -1) {
    entries_.push_back({body, wrench, start, end, axes_body});
  }

  /// Removes the wrenches of `body` (every body if body < 0).
  void clear(int body);

  /// Forgets wrenches whose window ended by time t.
  void dropFinished(double t);

  /// The loads of the step [t, t + h) from `state` (at t), one per body of
  /// `model`; empty if no wrench touches the step.
  void loadsFor(const Model& model, const State& state, double t, double h, Loads& out) const;

  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::vector<Entry> entries_;
};

}  // namespace rigid_body_sim::core
