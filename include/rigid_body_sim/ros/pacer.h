// How many steps the node's loop takes at each tick, so that sim time
// follows the wall clock × ~realtime_factor from a reference, and what each
// tick and each world edit cost the loop (~report_timing). ROS-free: the
// loop gives it the steady clock's readings.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace rigid_body_sim::node {

class Pacer {
 public:
  using Clock = std::chrono::steady_clock;
  /// Steps the loop may be behind the wall clock; beyond, it gives up and is
  /// rebased (it cannot keep up with the real-time factor).
  static constexpr int kMaxStepsBehind = 1000;
  /// Sim time the loop steps at most between two turns of its callbacks (s):
  /// catching up after a stall, it takes the steps due in slices of this and
  /// serves the callbacks between them, so a command waits at most this long
  /// in sim time. (Taken in one burst, the steps of a 0.6 s stall on a busy
  /// machine ran a base 0.6 s on its old cmd_vel.)
  static constexpr double kCallbackPeriod = 0.01;

  /// From now on sim time `sim_time` (s) corresponds to the wall instant
  /// `wall` (the clock's anchor plus any wait for the wall clock to catch up).
  void rebase(Clock::time_point wall, double sim_time);

  /// Steps of `dt` to take at `now`, from step count `steps` (sim time
  /// steps × dt), so that sim time reaches (wall time since the reference) ×
  /// `realtime_factor` to the nearest step; at most one slice of
  /// kCallbackPeriod (more() then says so) and at most kMaxStepsBehind
  /// (behind() then says so).
  int stepsDue(Clock::time_point now, long long steps, double dt, double realtime_factor);
  /// The last stepsDue() was capped at kMaxStepsBehind: the loop cannot keep up.
  bool behind() const { return behind_; }
  /// The last stepsDue() left steps due beyond its slice: the loop serves its
  /// callbacks and asks again, without waiting for the next tick.
  bool more() const { return more_; }

  /// ~report_timing: records a tick starting at `now`, and what a spawn or a
  /// delete cost the loop (s).
  void recordTick(Clock::time_point now);
  void recordSpawn(double seconds) { spawns_.push_back(seconds); }
  void recordDelete(double seconds) { deletes_.push_back(seconds); }

  /// The report: the ticks' |period − `period`| p50, p99 and largest, and
  /// the edits' p50, p90 and largest, one line each ("" for what has too
  /// few records).
  std::vector<std::string> report(double period, double sim_time) const;

 private:
  Clock::time_point ref_wall_{};
  double ref_sim_ = 0.0;
  bool behind_ = false;
  bool more_ = false;
  std::vector<double> periods_;  ///< s between tick starts
  bool ticked_ = false;
  Clock::time_point last_tick_{};
  std::vector<double> spawns_, deletes_;  ///< s each cost the loop
};

}  // namespace rigid_body_sim::node
