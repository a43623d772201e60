// The world's edits on the loop's thread, between two steps: a spawned
// body goes in (built and its ports opened on the spawn thread, handed over
// by the SpawnQueue), ~delete_body takes one out. Each checks first: a
// refused edit changes nothing. The simulation and the ports change
// together (core::Simulation, PortRegistry); what the node shows of the
// world (markers, fixed frames) follows through two hooks.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "rigid_body_sim/DeleteBody.h"
#include "rigid_body_sim/SpawnBody.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/ros/addressing.h"
#include "rigid_body_sim/ros/body_ports.h"
#include "rigid_body_sim/ros/pacer.h"
#include "rigid_body_sim/ros/params.h"
#include "rigid_body_sim/ros/robot_ports.h"
#include "rigid_body_sim/ros/sim_clock.h"
#include "rigid_body_sim/ros/spawn_queue.h"
#include "rigid_body_sim/ros/topic_claims.h"

namespace rigid_body_sim::node {

class WorldEdits {
 public:
  /// What an edit asks of the node once made: `added` after a body joined
  /// last, `removed` after the body of that name left, `robot_added` after
  /// the robot of a spawn joined last (its topics under its name, its
  /// controllers and frames as the spawn has them), `robot_removed` after
  /// robot r, of that name, left.
  struct Hooks {
    std::function<void()> added;
    std::function<void(const std::string&)> removed;
    std::function<void(SpawnQueue::Spawn& spawn)> robot_added;
    std::function<void(std::size_t r, const std::string& name)> robot_removed;
  };

  /// Reads the robots' frames from `robots` (when made), the node's time
  /// from `time`; a robot's topics are claimed in `topics` before it is
  /// added, and dropped with it; records each edit's cost in `pacer` under
  /// ~report_timing.
  WorldEdits(core::Simulation& sim, PortRegistry& ports, const std::optional<RobotPublisher>& robots,
             const Addressing& address, const NodeSettings& settings, const NodeTime& time, Pacer& pacer,
             TopicClaims& topics, Hooks hooks)
      : sim_(sim),
        ports_(ports),
        robots_(robots),
        address_(address),
        settings_(settings),
        time_(time),
        pacer_(pacer),
        topics_(topics),
        hooks_(std::move(hooks)) {}

  /// Adds every spawn queued since the last call, answering each.
  void insertQueued(SpawnQueue& queue);
  /// The body of `spawn` into the world, its ports with it, or why not
  /// (a taken name or frame, a pose or twist out of bounds).
  SpawnBody::Response insert(SpawnQueue::Spawn& spawn);
  /// ~delete_body: the body and its ports go, or the robot and its
  /// topics and controllers; what rested on it wakes.
  bool deleteBody(DeleteBody::Request& req, DeleteBody::Response& res);

 private:
  /// The robot of `spawn` (spawn.robot) into the world, its base at the
  /// request's pose and twist, or why not (a name or link frame taken).
  SpawnBody::Response insertRobot(SpawnQueue::Spawn& spawn);
  /// ~delete_body of robot r.
  void deleteRobot(std::size_t r, DeleteBody::Response& res);
  /// "" if `name` names nothing in the world yet, else why not.
  std::string nameTaken(const std::string& name) const;
  /// "" if tf frame `frame` is nobody's yet, else whose: "the world",
  /// "body 'NAME'" or "robot 'NAME'" (a robot's links: the URDF's names after its tf_prefix).
  std::string frameOwner(const std::string& frame) const;
  /// The request's pose and twist, given in its `frame`, as the link's in the
  /// world; or nothing, and `why` (an unknown frame, a position or speed out of bounds).
  std::optional<core::LinkState> requestedStart(const SpawnBody::Request& req, std::string& why) const;

  core::Simulation& sim_;
  PortRegistry& ports_;
  const std::optional<RobotPublisher>& robots_;
  const Addressing& address_;
  const NodeSettings& settings_;
  const NodeTime& time_;
  Pacer& pacer_;
  TopicClaims& topics_;
  Hooks hooks_;
};

}  // namespace rigid_body_sim::node
