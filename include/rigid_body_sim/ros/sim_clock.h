// The node's one clock: every stamp it publishes (odometry, tf, /clock), every
// time in a service response or message, and every time a user gives it
// (apply_wrench's start_time) are read on this clock (docs/ros_api.md, "Time").
//
// - With /use_sim_time: sim time itself, steps × Δt from 0, published on /clock.
// - Without: wall time at an anchor plus the sim time since the anchor. It
//   advances by exactly Δt per step, stands still while the simulation is
//   paused, and is re-anchored to the wall clock whenever the simulation
//   starts running (start, unpause, reset, falling behind), so at
//   realtime_factor 1 it stays within a loop tick of every other node's
//   ros::Time::now(). A re-anchoring never moves it backwards: when steps
//   taken while paused put it ahead of the wall clock, the simulation waits
//   for the wall clock to catch up before it runs on.
#pragma once

#include <cstdint>
#include <string>

namespace rigid_body_sim::node {

class SimClock {
 public:
  /// `dt`: s per step. `wall_anchored`: false for sim time (never re-anchored).
  SimClock(double dt, bool wall_anchored) : dt_(dt), wall_anchored_(wall_anchored) {}

  bool wallAnchored() const { return wall_anchored_; }

  /// The clock's reading at step count `steps` (ns).
  int64_t stampAt(long long steps) const;

  /// Wall-anchored only (sim time ignores it): from now on, step count
  /// `steps` reads max(`wall_now_ns`, stampAt(steps)). Returns how far the
  /// clock is then ahead of the wall clock (ns, ≥ 0; steps taken while
  /// paused can put it ahead): the node waits that long before stepping on.
  int64_t anchor(long long steps, int64_t wall_now_ns);

  /// The sim time (s since the start, steps × Δt) at which the clock reads
  /// `stamp_ns`, along the current anchor. A stamp within 1 ns of a step's
  /// reading gives that step's sim time exactly (stamps are whole ns; sim
  /// times are multiples of Δt).
  double simTimeAt(int64_t stamp_ns) const;

 private:
  double dt_;
  bool wall_anchored_;
  long long anchor_steps_ = 0;
  int64_t anchor_ns_ = 0;
};

/// A stamp in ns as "S.NNNNNNNNN" (seconds, exact), for messages.
std::string formatStamp(int64_t stamp_ns);

/// The node's time: the steps taken since start (sim time = steps × Δt,
/// also across resets) and the one clock they are read on. The node owns
/// it; the request classes read it.
struct NodeTime {
  NodeTime(double dt_in, bool wall_anchored) : clock(dt_in, wall_anchored), dt(dt_in) {}

  SimClock clock;
  long long steps = 0;
  double dt;  ///< s per step

  double simTime() const { return static_cast<double>(steps) * dt; }  ///< s
  int64_t stampNs() const { return clock.stampAt(steps); }            ///< the clock's reading now
  std::string text() const { return formatStamp(stampNs()) + " s"; }  ///< "S.NNNNNNNNN s", for messages
};

}  // namespace rigid_body_sim::node
