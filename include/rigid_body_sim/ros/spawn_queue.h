// The hand-over of a spawned body from the spawn thread to the loop.
// ~spawn_body runs on a thread of its own: it reads and checks the request,
// builds the body and opens its ports (the slow parts), then queues it and
// waits; the loop, between two steps, adds what is queued and answers each
// through its promise. Once the loop has ended, spawns are refused.
#pragma once

#include <atomic>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "rigid_body_sim/SpawnBody.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/io/controllers.h"
#include "rigid_body_sim/io/sensor_mount.h"
#include "rigid_body_sim/ros/body_ports.h"
#include "rigid_body_sim/ros/topic_claims.h"

namespace rigid_body_sim::node {

class SpawnQueue {
 public:
  /// A body built for the loop to add.
  struct Spawn {
    SpawnBody::Request request;
    core::PreparedBody body;
    std::unique_ptr<BodyPorts> ports;  ///< opened on the spawn thread (openPorts)
    /// A robot instead (its URDF has moving joints): it, and its joints as
    /// joint_names set them (the base placed by the loop).
    std::optional<core::Scene::RobotSpec> robot;
    core::ArticulationState robot_start;
    io::RobotControls controls;              ///< the robot's, read and checked on the spawn thread
    std::string frame_prefix;                ///< its frames' tf_prefix, "" or "PREFIX/" (framePrefix)
    io::RobotSensors sensors;                ///< the robot's: the request's imu, its URDF's Gazebo markup
    std::vector<TopicClaims::Claim> topics;  ///< its publishers' (robotTopics), claimed before it is added
    std::string sensor_prefix;               ///< its sensors' topics' namespace, "NAME/" or robot_namespace's
    std::string control_prefix;              ///< its controllers' and joint_states' (robotTopicPrefix)
  };
  /// Adds a spawn to the world, or says why not (loop thread).
  using Insert = std::function<SpawnBody::Response(Spawn&)>;

  /// Spawn thread: queues `spawn` and waits for the loop's answer; if the
  /// loop ends first (stop()), or `alive` turns false, the answer says the
  /// body was not added.
  SpawnBody::Response submit(Spawn spawn, const std::function<bool()>& alive = {});
  /// Loop thread: answers every spawn queued since the last call with
  /// `insert`'s answer; whatever it throws is that spawn's answer (no
  /// request may end the node).
  void drain(const Insert& insert);
  /// The loop has ended: the spawns waiting and those to come are refused.
  void stop() { stopping_ = true; }

 private:
  struct Waiting {
    Spawn spawn;
    std::promise<SpawnBody::Response> done;
  };
  std::mutex mutex_;
  std::vector<std::shared_ptr<Waiting>> waiting_;
  std::atomic<bool> stopping_{false};
};

}  // namespace rigid_body_sim::node
