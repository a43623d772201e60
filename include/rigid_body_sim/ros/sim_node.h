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
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
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
#include "rigid_body_sim/core/contact_report.h"
#include "rigid_body_sim/core/step.h"
#include "rigid_body_sim/core/velocity_driver.h"
#include "rigid_body_sim/core/wrench_schedule.h"
#include "rigid_body_sim/io/world.h"
#include "rigid_body_sim/ros/body_directory.h"
#include "rigid_body_sim/ros/counted_publisher.h"
#include "rigid_body_sim/ros/pacer.h"
#include "rigid_body_sim/ros/params.h"
#include "rigid_body_sim/ros/sim_clock.h"

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
  double simTime() const { return static_cast<double>(steps_) * model_.dt(); }
  /// The node's clock now (the stamp of the current state).
  ros::Time stamp() const { return ros::Time().fromNSec(clock_.stampAt(steps_)); }
  /// stamp() for messages: "S.NNNNNNNNN s".
  std::string now() const { return formatStamp(clock_.stampAt(steps_)) + " s"; }
  void stepOnce();
  /// Says what the step reported: bodies the speed limits held (once each),
  /// bodies the guard put back (their wrenches cleared).
  void reportStep();
  void publish();
  void publishClock();
  void publishBodyStates();  ///< ~body_states, while someone subscribes
  /// Links fixed to bodies `first` on, added to static_frames_ (0: all of
  /// them, the set made again), which goes to /tf_static whole.
  void publishFixedFrames(std::size_t first = 0);
  void resendMarkersIfDue();

  // Requests. Each validates first: a refused request changes nothing.
  bool applyWrench(ApplyWrench::Request& req, ApplyWrench::Response& res);
  bool applyImpulse(ApplyImpulse::Request& req, ApplyImpulse::Response& res);
  bool clearWrenches(ClearWrenches::Request& req, ClearWrenches::Response& res);
  bool getState(GetState::Request& req, GetState::Response& res);
  bool setState(SetState::Request& req, SetState::Response& res);
  bool reset(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool pause(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool unpause(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool step(Step::Request& req, Step::Response& res);
  void onWrench(const std::string& body, const geometry_msgs::WrenchStamped::ConstPtr& msg);

  // World editing (world_requests.cpp). ~spawn_body runs on its own thread:
  // it reads and checks the request and builds the body (the slow part), then
  // hands it to the loop, which adds it between two steps (insertBody) and
  // answers through the promise.
  bool spawnBody(SpawnBody::Request& req, SpawnBody::Response& res);
  bool deleteBody(DeleteBody::Request& req, DeleteBody::Response& res);
  /// What a body carries besides its shape (config keys imu, odom_noise, cmd_vel).
  struct BodyDevices {
    std::optional<io::ImuEntry> imu;
    std::optional<core::OdomNoiseSettings> odom_noise;
    std::optional<core::DriverSettings> cmd_vel;
  };
  struct BodyPorts;
  struct PendingSpawn {
    SpawnBody::Request request;
    core::PreparedBody body;
    std::unique_ptr<BodyPorts> ports;        ///< opened on the spawn thread (openPorts)
    std::promise<SpawnBody::Response> done;  ///< what the loop answers
  };
  /// Adds the spawns built since the last tick (loop thread, between steps).
  void insertPendingBodies();
  /// The body of `spawn` into the model, state and topics, or why not.
  SpawnBody::Response insertBody(PendingSpawn& spawn);
  /// After a body was added last: a fresh workspace, its names, markers and fixed frames.
  void afterSpawn();
  /// After body `body`, named `name`, was deleted: a fresh workspace, the
  /// names, markers and fixed frames without it.
  void afterDelete(int body, const std::string& name);
  /// A new workspace with the same knobs: its caches assumed the old model.
  void freshWorkspace();

  // Live tuning (reconfigure.cpp): the dynamic_reconfigure server ~physics.
  void startReconfigure();
  /// The settings ~physics shows: the model's and the node's as they are now.
  PhysicsConfig physicsNow() const;
  /// Applies what it can of `config` between steps; a value the checks
  /// refuse is put back to the one in force, with a warning naming it.
  void onReconfigure(PhysicsConfig& config, uint32_t level);
  /// Tells ~physics of a change made elsewhere (the pause services).
  void showPhysics();
  void setPaused(bool paused);

  /// The body named `name` ("" = the only body), or an error message.
  std::optional<int> findBody(const std::string& name, std::string& error) const;
  /// The pose of `frame` ("" or the world frame: the identity, else a
  /// body's tf frame as it is now) in the world, or an error message.
  std::optional<core::Pose> findPose(const std::string& frame, std::string& error) const;
  /// The axes a request's vectors are given in, for the body it addresses.
  struct Axes {
    core::Frame frame = core::Frame::kWorld;  ///< kBody: the body's own root link, turning with it
    int other = -1;                           ///< ≥ 0: this other body's root link, turning with it
  };
  /// `frame` for `body`: "" or the world frame → world; the body's tf frame
  /// (or root link name) → its own axes; another body's tf frame → that
  /// body's axes; anything else is an error.
  std::optional<Axes> findFrame(const std::string& frame, int body, std::string& error) const;
  /// The orientation of `axes` now, for `body` (world: the identity).
  core::Quat orientationOf(const Axes& axes, int body) const;
  /// What a request addresses: a body by name and the axes of its vectors (both as above).
  struct Target {
    int body;
    Axes axes;
  };
  std::optional<Target> findTarget(const std::string& body, const std::string& frame, std::string& error) const;
  /// `body`'s state for a message, its twist in `axes`.
  BodyState bodyState(int body, const Axes& axes) const;
  /// The loop paces sim time against the wall clock from now on, and,
  /// unless paused, the wall-anchored clock is re-anchored. Returns how long
  /// (s) the loop waits for the wall clock to catch up with the node's clock.
  double rebaseClock();

  ros::NodeHandle nh_, pnh_;
  NodeParams params_;
  const NodeSettings& settings_ = params_.node;  ///< ~physics changes params_.node
  io::World world_;
  const core::Model& model_ = world_.model;
  core::State& state_ = world_.state;
  core::State initial_;
  core::Workspace workspace_;
  core::WrenchSchedule schedule_;
  core::Loads loads_;

  /// What the node keeps per body beside the model, in the model's order.
  /// A body's names are fixed when it is created: the one body of a world
  /// that starts with one has the single-body names for life (its frame
  /// the root link, `odom`, `~wrench`); every other body, listed in a world
  /// or spawned, has them under its name ("NAME/").
  struct BodyPorts {
    std::string prefix;          ///< "" or "NAME/", before its frames and topics
    ros::NodeHandle nh, pnh;     ///< its topics' handles (the node's, copied: openPorts)
    std::string frame;           ///< its tf frame: prefix + root link
    CountedPublisher odom;       ///< PREFIXodom
    ros::Subscriber wrench;      ///< ~PREFIXwrench
    bool speed_limited = false;  ///< the speed limits have held it (warned once)
    /// Its IMU (sensors.cpp), sampled whether or not anyone listens. The
    /// devices with a random generator (2.5 KB each) are held apart: in
    /// place they made every body's ports 6 KB, devices or not.
    std::unique_ptr<core::Imu> imu;
    CountedPublisher imu_pub;                     ///< PREFIXimu, sensor_msgs/Imu
    std::string imu_frame;                        ///< prefix + the IMU's frame_id
    long long imu_every = 1;                      ///< steps per IMU sample
    std::unique_ptr<core::OdomNoise> odom_noise;  ///< noise on odom; the exact state then goes to ground_truth
    CountedPublisher ground_truth;                ///< PREFIXground_truth, with odom_noise
    double last_odom = 0.0;                       ///< s of sim time of its last odom report (for the drift)
    std::optional<core::VelocityDriver> driver;   ///< drives it toward its cmd_vel
    ros::Subscriber cmd_vel;                      ///< PREFIXcmd_vel, geometry_msgs/Twist
    bool clipped = false;                         ///< a command was clipped (warned once)
    std::size_t colour = 0;                       ///< its markers' colour: the order it entered the world in
  };
  std::vector<BodyPorts> ports_;
  BodyDirectory directory_;  ///< the bodies by name and by frame
  /// What directory_ holds for body i.
  BodyDirectory::Entry directoryEntry(std::size_t i) const;
  /// Indexes the bodies by name and frame again (at start, after a delete).
  void indexBodies();
  std::size_t bodies_entered_ = 0;  ///< bodies that have entered the world, the next one's colour
  /// The ports of `body` under `prefix`: its frames, topics and devices.
  /// Throws io::ConfigError (an IMU on no such link, or on a taken frame)
  /// before anything is advertised. Reads only its arguments, so the spawn
  /// thread opens a spawned body's ports: each topic is a round trip to the
  /// master, 1-2 ms the loop does not wait for. startPorts() starts them.
  /// `topics` false: only its devices' topics, none for odometry or wrenches
  /// (~per_body_topics).
  BodyPorts openPorts(const core::BodyModel& body, const std::string& prefix, const BodyDevices& devices,
                      bool topics = true);
  /// Starts `ports`' sensors at `start`, now (loop thread).
  void startPorts(BodyPorts& ports, const core::BodyState& start);
  /// Closes `ports` on the spawn thread: closing a topic waits for the master too.
  void closeLater(BodyPorts&& ports);
  void onCmdVel(const std::string& body, const geometry_msgs::Twist::ConstPtr& msg);
  // Contacts (contacts.cpp).
  void publishContacts();         ///< ~contacts and ~contact_markers, while someone subscribes
  core::ContactLedger contacts_;  ///< what touches what, the sleepers' contacts kept
  CountedPublisher contacts_pub_, contact_markers_pub_;
  /// Samples the IMUs due at this step and publishes them (sensors.cpp).
  void sampleSensors();
  /// The IMU of body i starts a new period at its state now (after set_state, reset).
  void restartSensors(int body);
  const double dt_ = model_.dt();  ///< for the spawn thread (no edit changes it)
  std::vector<std::string> frames() const;
  std::vector<std::size_t> colours() const;  ///< each body's BodyPorts::colour, in the model's order

  bool paused_ = false;
  bool use_sim_time_ = false;
  long long steps_ = 0;  ///< steps since start: sim time = steps × dt, also across resets
  SimClock clock_;       ///< what every stamp and every time a user reads or gives is on
  long long publish_every_ = 1;
  long long body_states_every_ = 1;
  ros::Time last_published_;

  Pacer pacer_;  ///< sim time against the wall clock × realtime factor; the loop's timing

  ros::Publisher clock_pub_, scene_pub_, body_pub_;
  CountedPublisher body_states_pub_;
  tf2_ros::TransformBroadcaster tf_;
  std::vector<geometry_msgs::TransformStamped> tf_batch_;  ///< every body's transform, sent as one /tf message
  /// /tf_static, latched, as tf2_ros's static broadcaster sends it: every
  /// fixed frame in one message. The node keeps the set itself so that a
  /// deleted body's frames leave it (the broadcaster keeps all it was given,
  /// and making a new one cost two round trips to the master per delete).
  ros::Publisher tf_static_pub_;
  tf2_msgs::TFMessage static_frames_;
  visualization_msgs::MarkerArray scene_markers_, body_markers_;
  struct MarkersResend {
    ros::WallTime connected;  ///< when a subscriber to the markers connected
    int publishes = 0;        ///< tf publications since
  };
  std::optional<MarkersResend> markers_resend_;
  std::vector<ros::ServiceServer> services_;

  // The spawn thread: ~spawn_body on its own queue.
  const core::BodyBuilder builder_ = model_.bodyBuilder();
  ros::CallbackQueue spawn_queue_;
  ros::ServiceServer spawn_service_;
  std::unique_ptr<ros::AsyncSpinner> spawn_spinner_;
  std::mutex pending_mutex_;
  std::vector<std::shared_ptr<PendingSpawn>> pending_;  ///< built, for the loop to add
  std::atomic<bool> stopping_{false};                   ///< the loop has ended: spawns are refused
  boost::recursive_mutex reconfigure_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<PhysicsConfig>> reconfigure_;
};

}  // namespace rigid_body_sim::node
