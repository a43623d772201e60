// Where a robot's lidars sit: lidar_mount.h.
#include "rigid_body_sim/io/lidar_mount.h"

#include <stdexcept>
#include <string>

#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::io {

namespace {

/// The pose of `name` in link j's frame: j itself, or one of its fixed links (each posed in its parent's).
bool poseIn(const core::ArticulatedLink& link, const std::string& name, core::Pose& X) {
  if (link.name == name) {
    X = core::Pose{};
    return true;
  }
  for (const core::FixedLink& f : link.fixed_links) {
    if (f.name != name) continue;
    core::Pose X_LP;
    if (!poseIn(link, f.parent, X_LP)) return false;
    X = X_LP * f.X_PK;
    return true;
  }
  return false;
}

}  // namespace

std::vector<RobotLidar> mountLidars(const std::vector<LidarEntry>& entries, const core::ArticulationModel& model) {
  std::vector<RobotLidar> out;
  for (const LidarEntry& e : entries) {
    try {  // a URDF's markup is checked here; the config's was when it was read
      core::checkLidar(e.settings);
    } catch (const std::invalid_argument& err) {
      throw ConfigError(e.key + ": " + err.what());
    }
    if (!(e.rate >= core::ranges::kMinRate && e.rate <= core::ranges::kMaxPublishRate)) {
      throw ConfigError(e.key + ": its rate " + std::to_string(e.rate) + " Hz is not within [" +
                        std::to_string(core::ranges::kMinRate) + ", " + std::to_string(core::ranges::kMaxPublishRate) +
                        "]");
    }
    RobotLidar mounted{e, -1, {}};
    for (std::size_t j = 0; j < model.links.size() && mounted.link < 0; ++j) {
      if (poseIn(model.links[j], e.link, mounted.X_LS)) mounted.link = static_cast<int>(j);
    }
    if (mounted.link < 0) {
      std::string names;
      for (const core::ArticulatedLink& l : model.links) {
        names += (names.empty() ? "'" : ", '") + l.name + "'";
        for (const core::FixedLink& f : l.fixed_links) names += ", '" + f.name + "'";
      }
      throw ConfigError("config key '" + e.key + ".link': robot '" + model.name + "' has no link '" + e.link +
                        "' (its links: " + names + ")");
    }
    mounted.X_LS = mounted.X_LS * e.pose;
    out.push_back(std::move(mounted));
  }
  return out;
}

}  // namespace rigid_body_sim::io
