// Timed joint efforts: joint_effort_schedule.h.
#include "rigid_body_sim/core/articulations/joint_effort_schedule.h"

#include <algorithm>

#include "rigid_body_sim/core/step/loads.h"

namespace rigid_body_sim::core {

void JointEffortSchedule::add(std::size_t robot, int joint, double effort, double start, double end) {
  entries_.push_back({robot, joint, effort, start, end});
}

void JointEffortSchedule::addEfforts(std::size_t robot, double t, double h, Eigen::VectorXd& effort) const {
  for (const Entry& e : entries_) {
    if (e.robot != robot) continue;
    const double fraction = stepFraction(e.start, e.end, t, h);
    if (fraction > 0.0) effort(e.joint - 1) += e.effort * fraction;
  }
}

std::size_t JointEffortSchedule::clear(std::size_t robot, int joint) {
  const std::size_t before = entries_.size();
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                [&](const Entry& e) { return e.robot == robot && (joint < 0 || e.joint == joint); }),
                 entries_.end());
  return before - entries_.size();
}

void JointEffortSchedule::removeRobot(std::size_t robot) {
  clear(robot, -1);
  for (Entry& e : entries_) {
    if (e.robot > robot) --e.robot;
  }
}

void JointEffortSchedule::dropFinished(double t) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.end <= t; }),
                 entries_.end());
}

}  // namespace rigid_body_sim::core
