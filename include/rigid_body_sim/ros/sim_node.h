// The ROS node: a thin adapter over the core. It owns one Model and one
// State, steps them at a fixed rate, publishes tf and nav_msgs/Odometry, and
// turns services and the ~wrench topic into loads, impulses and new states.
#pragma once

#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <visualization_msgs/MarkerArray.h>

#include <chrono>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "rigid_body_sim/ApplyImpulse.h"
#include "rigid_body_sim/ApplyWrench.h"
#include "rigid_body_sim/BodyState.h"
#include "rigid_body_sim/BodyStates.h"
#include "rigid_body_sim/ClearWrenches.h"
#include "rigid_body_sim/Contacts.h"
#include "rigid_body_sim/DeleteBody.h"
#include "rigid_body_sim/GetState.h"
#include "rigid_body_sim/PhysicsConfig.h"
#include "rigid_body_sim/SetState.h"
#include "rigid_body_sim/SpawnBody.h"
#include "rigid_body_sim/Step.h"
#include "rigid_body_sim/core/contacts/contact_report.h"
#include "rigid_body_sim/core/devices/velocity_driver.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/core/step/step.h"
#include "rigid_body_sim/core/step/wrench_schedule.h"
#include "rigid_body_sim/io/world.h"
#include "rigid_body_sim/ros/addressing.h"
#include "rigid_body_sim/ros/body_ports.h"
#include "rigid_body_sim/ros/counted_publisher.h"
#include "rigid_body_sim/ros/joint_requests.h"
#include "rigid_body_sim/ros/link_sensor_ports.h"
#include "rigid_body_sim/ros/load_requests.h"
#include "rigid_body_sim/ros/markers.h"
#include "rigid_body_sim/ros/pacer.h"
#include "rigid_body_sim/ros/params.h"
#include "rigid_body_sim/ros/robot_commands.h"
#include "rigid_body_sim/ros/robot_ports.h"
#include "rigid_body_sim/ros/sim_clock.h"
#include "rigid_body_sim/ros/spawn_queue.h"
#include "rigid_body_sim/ros/state_publisher.h"
#include "rigid_body_sim/ros/state_requests.h"
#include "rigid_body_sim/ros/topic_claims.h"
#include "rigid_body_sim/ros/world_edits.h"

namespace rigid_body_sim::node {

class SimNode {
 public:
  /// Reads the parameters and robot_description and builds the model.
  /// Throws std::exception with a message naming the problem (bad URDF, bad
  /// parameter); main() reports it with ROS_FATAL and exits.
  SimNode(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh);

  /// Stops the spawn thread (a spawn waiting for the loop is refused).
  ~SimNode();

  /// Steps and publishes until ROS shuts down.
  void run();

 private:
  // Stepping and publishing.
  double simTime() const { return time_.simTime(); }
  /// The node's clock now (the stamp of the current state).
  ros::Time stamp() const { return ros::Time().fromNSec(time_.stampNs()); }
  /// stamp() for messages: "S.NNNNNNNNN s".
  std::string now() const { return time_.text(); }
  void stepOnce();
  /// Says what the step reported: bodies and robots the speed limits held
  /// (once each), bodies the guard put back (their wrenches cleared) and
  /// robots it put back (their timed joint efforts cleared).
  void reportStep();
  /// tf and odometry now (StatePublisher::state), then the markers if due;
  /// and every robot's joint states.
  void publish();
  /// The bodies' part of publish().
  void publishBodies();

  // The services that run the loop (pacing.cpp): pause, unpause, step.
  bool pause(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool unpause(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool step(Step::Request& req, Step::Response& res);

  // ~spawn_body (spawn_requests.cpp) runs on its own thread: it reads and
  // checks the request, builds the body (the slow part) and opens its
  // ports, then hands it to the loop (SpawnQueue), which adds it between
  // two steps (WorldEdits) and answers.
  bool spawnBody(SpawnBody::Request& req, SpawnBody::Response& res);
  /// After a body was added last: its markers and fixed frames.
  void afterSpawn();
  /// After the body named `name` was deleted: the markers and fixed frames without it.
  void afterDelete(const std::string& name);
  /// After the robot of `spawn` was added last: its joint_states and controllers under its name.
  void afterRobotSpawn(SpawnQueue::Spawn& spawn);
  /// Robot r's base leaves world -> base on tf where its odometry puts it there.
  void leaveBase(std::size_t r);
  /// After robot r, named `name`, was deleted: its joint_states and controllers go.
  void afterRobotDelete(std::size_t r, const std::string& name);

  // Live tuning (reconfigure.cpp): the dynamic_reconfigure server ~physics.
  void startReconfigure();
  /// Applies what it can of `config` between steps (applyTuning); a value
  /// the checks refuse is put back to the one in force, with a warning naming it.
  void onReconfigure(PhysicsConfig& config, uint32_t level);
  /// Tells ~physics of a change made elsewhere (the pause services).
  void showPhysics();
  void setPaused(bool paused);

  /// The loop paces sim time against the wall clock from now on, and,
  /// unless paused, the wall-anchored clock is re-anchored. Returns how long
  /// (s) the loop waits for the wall clock to catch up with the node's clock.
  double rebaseClock();

  ros::NodeHandle nh_, pnh_;
  /// Every robot's publishers' topics, one publisher each (topic_claims.h).
  TopicClaims topic_claims_{[this](const std::string& topic) { return nh_.resolveName(topic); }};
  NodeParams params_;
  const NodeSettings& settings_ = params_.node;  ///< ~physics changes params_.node
  /// The robots' controllers as the world was loaded, until commands_ takes them.
  std::vector<io::RobotControls> start_controls_;
  /// The robots' sensors as the world was loaded, until link_sensors_ takes them.
  std::vector<io::RobotSensors> start_sensors_;
  /// The model and every table in its bodies' order: a world edit goes through it once.
  core::Simulation sim_;
  const core::Model& model_ = sim_.model();
  core::State& state_ = sim_.state;
  core::Workspace& workspace_ = sim_.workspace.bodies;
  core::WrenchSchedule& schedule_ = sim_.schedule;
  core::Loads loads_;
  std::vector<core::ArticulationLoads> robot_loads_;  ///< per robot, its controllers' efforts
  std::optional<RobotCommands> commands_;             ///< the robots' controllers and their topics
  std::optional<LinkSensorPorts> link_sensors_;       ///< the sensors on robots' links: motion, ray and force devices

  /// Every body's frames, topics and devices, and its names: a spawn, a
  /// delete and a reset go through it (body_ports.h).
  PortRegistry ports_{spawn_queue_};
  Addressing address_{sim_, ports_, params_.node.world_frame};  ///< what a request names
  /// apply_wrench, apply_impulse, clear_wrenches, ~wrench, cmd_vel.
  LoadRequests load_requests_{sim_, ports_, address_, params_.node, time_};
  /// Spawned bodies in, ~delete_body's out, between steps.
  WorldEdits world_edits_{sim_,
                          ports_,
                          robot_publisher_,
                          address_,
                          params_.node,
                          time_,
                          pacer_,
                          topic_claims_,
                          {[this] { afterSpawn(); }, [this](const std::string& name) { afterDelete(name); },
                           [this](SpawnQueue::Spawn& spawn) { afterRobotSpawn(spawn); },
                           [this](std::size_t r, const std::string& name) { afterRobotDelete(r, name); }}};
  /// get_state, set_state, reset: each published at once, a reset re-paced.
  StateRequests state_requests_{
      sim_,
      ports_,
      address_,
      time_,
      {[this] { publish(); },
       [this] {
         rebaseClock();
         commands_->restart(sim_);  // nothing drives a reset robot back (gazebo_ros_pkgs #1311)
         link_sensors_->restart(sim_);
       }}};
  /// set_model_configuration, get_joint_properties.
  JointRequests joint_requests_{sim_, time_, [this](std::size_t r) {
                                  commands_->restart(sim_, r);
                                  link_sensors_->restartImus(sim_, r);
                                  publish();
                                }};
  PortContext port_context_;  ///< what opening a body's ports needs of the node (read only once made)
  /// Samples the bodies' IMUs due at this step and publishes them (sensors.cpp).
  void sampleSensors();
  const double dt_ = model_.dt();                           ///< for the spawn thread (no edit changes it)
  const core::SpeedLimits spawn_limits_ = model_.limits();  ///< for the spawn thread (no edit changes them)

  std::set<std::string> robots_speed_limited_;  ///< the robots reportStep has said so of
  bool paused_ = false;
  bool use_sim_time_ = false;
  NodeTime time_;                   ///< the steps since start and the one clock
  long long& steps_ = time_.steps;  ///< sim time = steps × dt, also across resets
  SimClock& clock_ = time_.clock;   ///< what every stamp and every time a user reads or gives is on
  long long publish_every_ = 1;
  long long body_states_every_ = 1;

  Pacer pacer_;  ///< sim time against the wall clock × realtime factor; the loop's timing

  std::optional<StatePublisher> publisher_;        ///< tf, odometry, ~body_states, /clock, /tf_static
  std::optional<MarkerPublisher> markers_;         ///< ~scene_markers, ~body_markers
  std::optional<RobotPublisher> robot_publisher_;  ///< each robot's joint_states and floating base
  std::vector<ros::ServiceServer> services_;

  // The spawn thread: ~spawn_body on its own queue.
  const core::BodyBuilder builder_ = model_.bodyBuilder();
  ros::CallbackQueue spawn_queue_;
  ros::ServiceServer spawn_service_;
  std::unique_ptr<ros::AsyncSpinner> spawn_spinner_;
  SpawnQueue spawns_;  ///< built on the spawn thread, for the loop to add
  boost::recursive_mutex reconfigure_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<PhysicsConfig>> reconfigure_;
};

}  // namespace rigid_body_sim::node
