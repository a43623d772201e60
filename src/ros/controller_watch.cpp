// A controller in trouble, said once: controller_watch.h.
#include "rigid_body_sim/ros/controller_watch.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rigid_body_sim::node {

std::vector<std::string> ControllerWatch::observe(std::size_t r, const std::string& robot,
                                                  const core::ArticulationModel& model,
                                                  const core::JointControllers& controllers,
                                                  const core::ArticulationState& state, const Eigen::VectorXd& effort,
                                                  double dt) {
  const int n = model.jointCount();
  if (saturated_.size() <= r) saturated_.resize(r + 1), pressed_.resize(r + 1);
  saturated_[r].resize(static_cast<std::size_t>(n) + 1, 0.0);
  pressed_[r].resize(static_cast<std::size_t>(n) + 1, 0.0);
  std::vector<std::string> said;
  for (int j = 1; j <= n && j - 1 < effort.size() && j - 1 < state.q.size(); ++j) {
    const int c = controllers.ownerOf(j);
    const core::JointLimits& limits = model.links[j].limits;
    const double u = effort(j - 1), q = state.q(j - 1);
    const bool saturated =
        c >= 0 && std::isfinite(limits.effort) && limits.effort > 0.0 && std::abs(u) >= limits.effort;
    // Pressing hard: at a limit, pushing outward with half the effort limit or more.
    const bool hard = std::isfinite(limits.effort) ? std::abs(u) >= 0.5 * limits.effort : u != 0.0;
    const bool pressed =
        c >= 0 && hard && ((u > 0.0 && q >= limits.upper - kAtLimit) || (u < 0.0 && q <= limits.lower + kAtLimit));
    double& held = saturated_[r][j];
    double& against = pressed_[r][j];
    held = saturated ? held + dt : 0.0;
    against = pressed ? against + dt : 0.0;
    if ((held < kSustained && against < kSustained) || !said_.insert({r, j}).second) continue;
    std::ostringstream os;
    os << "robot '" << robot << "': controller '" << controllers.specs()[c].name << "' has ";
    if (held >= kSustained) {
      os << "held joint '" << model.links[j].joint << "' at its URDF effort limit (" << limits.effort << ") for "
         << kSustained << " s: are its gains too high for the joint (it may be unstable), or is the joint blocked?";
    } else {
      os << "driven joint '" << model.links[j].joint << "' against its " << (u > 0.0 ? "upper" : "lower") << " limit ("
         << (u > 0.0 ? limits.upper : limits.lower) << ") for " << kSustained
         << " s: is its target past the limit, or its gains unstable?";
    }
    os << " (said once per joint)";
    said.push_back(os.str());
  }
  return said;
}

void ControllerWatch::restart(std::size_t r) {
  if (r < saturated_.size()) {
    std::fill(saturated_[r].begin(), saturated_[r].end(), 0.0);
    std::fill(pressed_[r].begin(), pressed_[r].end(), 0.0);
  }
}

void ControllerWatch::removeRobot(std::size_t r) {
  if (r < saturated_.size()) {
    saturated_.erase(saturated_.begin() + static_cast<std::ptrdiff_t>(r));
    pressed_.erase(pressed_.begin() + static_cast<std::ptrdiff_t>(r));
  }
  std::set<std::pair<std::size_t, int>> said;
  for (const auto& [robot, joint] : said_) {
    if (robot != r) said.insert({robot > r ? robot - 1 : robot, joint});
  }
  said_ = std::move(said);
}

}  // namespace rigid_body_sim::node
