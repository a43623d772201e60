// One topic, one publisher. Which of the node's publishers holds each topic,
// so that a second on a taken topic is refused naming both: roscpp would
// either interleave two of one type on the topic without a word, or log
// "Tried to advertise on topic ... already advertised" for another type and
// publish nothing from the second. The names every robot's publishers use
// are made here, once, by the functions below, which the classes that open
// them call too; the claims are checked before a robot is added (at start,
// and for a spawn before the world changes) and dropped with it.
// ROS-free: names are resolved through a function the node gives.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "rigid_body_sim/io/controllers.h"
#include "rigid_body_sim/io/sensor_mount.h"

namespace rigid_body_sim::node {

/// A device's topic under a robot's `prefix` ("NAME/" or ""), or from the
/// root as given ("/...").
std::string deviceTopic(const std::string& prefix, const std::string& topic);

/// A depth camera's image, camera_info and points topics: under its
/// namespace (`topic`, itself under `prefix`), or each from the root.
std::array<std::string, 3> cameraTopics(const std::string& prefix, const io::DepthCameraEntry& camera);

/// A DiffDriveController's namespace: CONTROLLER/ under `prefix`
/// (ros_controllers'), or `prefix` alone (gazebo_ros_diff_drive's).
std::string driveNamespace(const std::string& prefix, const std::string& controller, const io::DriveTopics& topics);

class TopicClaims {
 public:
  /// One publisher's topic (as given, unresolved) and what it is, for messages.
  struct Claim {
    std::string topic;
    std::string what;  ///< "lidar <gazebo reference=...>", "joint_states"
  };
  /// Resolves a topic as the master names it; throws for a name it refuses.
  using Resolve = std::function<std::string(const std::string&)>;

  explicit TopicClaims(Resolve resolve) : resolve_(std::move(resolve)) {}

  /// Why `claims` (one robot's) may not be taken: a topic an owner holds,
  /// or one two of them share, each named with what holds it; "" when they may.
  std::string problem(const std::vector<Claim>& claims) const;
  /// Takes `claims` for `owner` (problem() found none).
  void take(const std::string& owner, const std::vector<Claim>& claims);
  /// Drops every topic `owner` holds (a robot deleted).
  void release(const std::string& owner);

 private:
  struct Holder {
    std::string owner, what;
  };
  Resolve resolve_;
  std::map<std::string, Holder> taken_;  ///< by resolved topic
  mutable std::mutex mutex_;             ///< the spawn thread checks, the loop takes and drops
};

/// The topics robot `robot`'s publishers take: its joint_states and each
/// drive's under `control_prefix` (its robotNamespace's, or its own), its
/// sensors' under `prefix`.
std::vector<TopicClaims::Claim> robotTopics(const std::string& prefix, const std::string& control_prefix,
                                            const io::RobotSensors& sensors, const io::RobotControls& controls);

}  // namespace rigid_body_sim::node
