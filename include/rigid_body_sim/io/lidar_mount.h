// Where a robot's range sensors sit: each config entry (io::LidarEntry,
// io::DepthCameraEntry) on one of its links, or on a link a fixed joint
// lumped into one (as a laser_link usually is), at its pose there. ROS-free.
#pragma once

#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

/// A lidar on link `link` of a robot, its frame at X_LS in that link's.
struct RobotLidar {
  LidarEntry entry;
  int link = 0;     ///< the moving link (index in the model) that carries it
  core::Pose X_LS;  ///< the sensor (at entry.pose in entry.link) in the moving link's frame
};

/// A depth camera on link `link` of a robot, at X_LS in that link's frame.
struct RobotCamera {
  DepthCameraEntry entry;
  int link = 0;
  core::Pose X_LS;
};

/// `entries` on `model`'s links (their settings checked when the config was read).
/// Refused as mountLidars refuses a link.
std::vector<RobotCamera> mountCameras(const std::vector<DepthCameraEntry>& entries,
                                      const core::ArticulationModel& model);

/// `entries` on `model`'s links. Refused (ConfigError naming `entries[k].key`):
/// a link the robot does not have (the message lists its links), settings
/// core::checkLidar refuses, a rate outside the publish rates.
std::vector<RobotLidar> mountLidars(const std::vector<LidarEntry>& entries, const core::ArticulationModel& model);

}  // namespace rigid_body_sim::io
