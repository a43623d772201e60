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

void mount(const core::ArticulationModel& model, const std::string& link, const core::Pose& pose,
           const std::string& key, int& j, core::Pose& X_LS) {
  j = -1;
  for (std::size_t i = 0; i < model.links.size() && j < 0; ++i) {
    if (poseIn(model.links[i], link, X_LS)) j = static_cast<int>(i);
  }
  if (j < 0) {
    std::string names;
    for (const core::ArticulatedLink& l : model.links) {
      names += (names.empty() ? "'" : ", '") + l.name + "'";
      for (const core::FixedLink& f : l.fixed_links) names += ", '" + f.name + "'";
    }
    throw ConfigError("config key '" + key + ".link': robot '" + model.name + "' has no link '" + link +
                      "' (its links: " + names + ")");
  }
  X_LS = X_LS * pose;
}

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
    mount(model, e.link, e.pose, e.key, mounted.link, mounted.X_LS);
    out.push_back(std::move(mounted));
  }
  return out;
}

std::vector<RobotCamera> mountCameras(const std::vector<DepthCameraEntry>& entries,
                                      const core::ArticulationModel& model) {
  std::vector<RobotCamera> out;
  for (const DepthCameraEntry& e : entries) {
    RobotCamera mounted{e, -1, {}};
    mount(model, e.link, e.pose, e.key, mounted.link, mounted.X_LS);
    out.push_back(std::move(mounted));
  }
  return out;
}

}  // namespace rigid_body_sim::io
