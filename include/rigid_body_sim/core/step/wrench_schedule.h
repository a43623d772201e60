// Wrenches applied over windows of sim time (the node's apply_wrench), and
// wrenches held until replaced or timed out (the node's ~wrench topic).
#pragma once

#include <limits>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/step/loads.h"

namespace rigid_body_sim::core {

/// Wrenches, each on one body over [start, end) of sim time. A step of
/// length h from t receives every wrench weighted by the fraction of
/// [t, t + h) its window covers, so a window of any length delivers exactly
/// force × length of impulse, even when it does not line up with the steps.
/// Wrenches add up. A step costs O(wrenches acting), not O(wrenches
/// scheduled): those yet to start wait apart, in order of start, and each
/// body holds at most kMaxPerBody.
class WrenchSchedule {
 public:
  static constexpr double kForever = std::numeric_limits<double>::infinity();
  /// Wrenches one body may hold, acting or yet to start (50,000 future
  /// wrenches once made a paused step 453 µs).
  static constexpr std::size_t kMaxPerBody = 1000;

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

  /// Schedules a wrench on `body` over [start, end); false (and nothing
  /// added) when the body already holds kMaxPerBody.
  bool add(int body, const Wrench& wrench, double start, double end, int axes_body = -1);

  /// Holds a wrench on `body` from `start` (the node's ~wrench topic): it
  /// replaces the one `body` held and acts, in whole steps, on every step
  /// that starts before `start` + `timeout` (less half a step, for
  /// rounding), until replaced or cleared; `timeout` kForever: until
  /// cleared. `axes_body` as add()'s. Not counted in kMaxPerBody.
  void hold(int body, const Wrench& wrench, double start, double timeout, int axes_body = -1);
  /// Whether `body` holds a wrench (hold()).
  bool holds(int body) const;

  /// Removes the wrenches of `body` (every body if body < 0), held ones too.
  void clear(int body);

  /// Follows Model::withoutBody(body): drops the wrenches on `body` and
  /// those given in its axes (they have none left), held ones too, and
  /// moves the later bodies' indices down by one. Returns how many of the
  /// timed ones (add()) it dropped.
  std::size_t removeBody(int body);
  /// Follows Model::insertBody(body): the indices from `body` on move up by one.
  void insertBody(int body);

  /// Forgets wrenches whose window ended by time t (held ones, whose
  /// timeout did), and counts those that started before t as acting.
  void dropFinished(double t);

  /// The loads of the step [t, t + h) from `state` (at t), one per body of
  /// `model`; empty if no wrench touches the step. Per body the timed
  /// wrenches first, in order of start, then the held one.
  void loadsFor(const Model& model, const State& state, double t, double h, Loads& out) const;

  /// Wrenches held for `body`, acting or yet to start.
  std::size_t count(int body) const;
  /// Timed wrenches (add()) in all.
  std::size_t size() const { return acting_.size() + waiting_.size(); }

 private:
  std::vector<Entry> acting_;       ///< started before the last dropFinished(), in order of start
  std::vector<Entry> waiting_;      ///< yet to start, sorted by start (ties in order of add)
  std::vector<std::size_t> count_;  ///< per body
  std::vector<Entry> held_;         ///< at most one per body, in order of body; `end` is the timeout (s)
};

}  // namespace rigid_body_sim::core
