// Efforts on robots' joints over windows of sim time, as the node's
// apply_joint_effort gives them (gazebo_msgs' start time and duration): each
// acts on the steps it overlaps, in proportion to the overlap, so the
// impulse delivered is effort × duration off the step grid too. ROS-free.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <vector>

namespace rigid_body_sim::core {

class JointEffortSchedule {
 public:
  /// `effort` (N·m or N) on robot r's joint `joint` (a link index) over
  /// [start, end) s of sim time; end = ∞: until cleared.
  void add(std::size_t robot, int joint, double effort, double start,
           double end = std::numeric_limits<double>::infinity());
  /// Adds to `effort` (robot r's, one per joint, joint j at j − 1) each
  /// entry's effort times the part of [t, t + h) it covers over h.
  void addEfforts(std::size_t robot, double t, double h, Eigen::VectorXd& effort) const;
  /// Removes robot r's efforts on `joint` (every joint for −1); returns how many.
  std::size_t clear(std::size_t robot, int joint);
  /// Robot r left the world: its entries go, the later robots' move down by one.
  void removeRobot(std::size_t robot);
  /// Removes every entry.
  void clearAll() { entries_.clear(); }
  /// Drops the entries that ended by t.
  void dropFinished(double t);
  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    std::size_t robot;
    int joint;
    double effort, start, end;
  };
  std::vector<Entry> entries_;
};

}  // namespace rigid_body_sim::core
