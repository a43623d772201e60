// A trajectory of a group of joints through timed waypoints, interpolated
// as ros_controllers' JointTrajectoryController does (docs/physics.md
// §11.11): each piece between two waypoints a polynomial, linear where
// either end gives positions only, cubic where both give velocities,
// quintic where both give accelerations. A new trajectory takes over from
// the one being followed without a jump. ROS-free: the node turns
// trajectory_msgs/JointTrajectory into waypoints; the controller
// (joint_control.h) tracks the setpoints through effort.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace rigid_body_sim::core {

/// One waypoint: trajectory_msgs/JointTrajectoryPoint, joints in the
/// controller's order.
struct TrajectoryPoint {
  double time = 0.0;                 ///< s from the trajectory's start
  std::vector<double> position;      ///< per joint (rad or m)
  std::vector<double> velocity;      ///< per joint (rad/s or m/s), or empty
  std::vector<double> acceleration;  ///< per joint (rad/s² or m/s²), or empty (needs velocity)
};

/// `points` given for the joints named `names` (a JointTrajectory's
/// joint_names, its points' fields in that order) put in the order of
/// `joints` (a controller's joint names): "" or why not (a count that
/// differs, a name not among them or given twice, naming joint_names[m]),
/// and then nothing has changed. A field of another length than the names
/// is left as it is, for JointTrajectory::check to name.
std::string orderTrajectory(const std::vector<std::string>& joints, const std::vector<std::string>& names,
                            std::vector<TrajectoryPoint>& points);

/// Where one joint should be at a time.
struct Setpoint {
  double position = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
};

class JointTrajectory {
 public:
  JointTrajectory() = default;
  /// Standing still at `position` (one value per joint) at any time.
  explicit JointTrajectory(const std::vector<double>& position);

  /// "" if `points` can be followed by `joints` joints, else why not (the
  /// first problem, naming the point and field): each point's positions
  /// one per joint, velocities and accelerations none or one per joint
  /// (accelerations only with velocities), every value finite, times
  /// finite, ≥ 0 and strictly increasing.
  static std::string check(const std::vector<TrajectoryPoint>& points, std::size_t joints);

  /// Follows this trajectory until max(`start`, `now`), then `points`
  /// (checked by check(); times from `start`, s of the same clock as
  /// `now`) in turn. Points at or before `now` are dropped, the count
  /// returned; the first kept one is reached from where this trajectory
  /// is at the switch, so nothing jumps. A joint with `wraps[k]` (a
  /// continuous joint) has the new positions moved by whole turns so that
  /// it does not turn round more than half a turn to the first point. All
  /// points past: nothing changes and −1 is returned.
  int follow(double now, double start, const std::vector<TrajectoryPoint>& points, const std::vector<char>& wraps);

  /// Joint k's setpoint at time t. Before the first piece it is the
  /// first's start, after the last the last's end, at rest (ros_controllers'
  /// segments sample so outside their span).
  Setpoint sample(double t, std::size_t k) const;

  std::size_t joints() const { return joints_; }
  /// When the last piece ends (s).
  double endTime() const { return pieces_.empty() ? 0.0 : pieces_.back().end; }

 private:
  /// One polynomial per joint over [start, end]: Σ c[i] (t − start)^i.
  struct Piece {
    double start = 0.0, end = 0.0;
    std::vector<std::array<double, 6>> coefficients;  ///< per joint
  };
  /// The piece from `a` (at t0) to `b` (at t1), each joint's boundary
  /// states of the lowest order both give (`order`: 0 position, 1 + velocity, 2 + acceleration).
  static Piece piece(double t0, const std::vector<Setpoint>& a, double t1, const std::vector<Setpoint>& b, int order);
  /// The piece in force at t: the last one starting at or before t, else the first.
  std::size_t pieceAt(double t) const;

  std::size_t joints_ = 0;
  std::vector<Piece> pieces_;  ///< by start time
};

}  // namespace rigid_body_sim::core
