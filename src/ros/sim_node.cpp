// The node's set-up: the world (loaded as rbsim loads it), its topics,
// services and first messages. The loop is in pacing.cpp, the messages in
// state_publisher.cpp and markers.cpp, the services in *_requests.cpp.
#include "rigid_body_sim/ros/sim_node.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/scene_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/io/world.h"
#include "rigid_body_sim/ros/markers.h"

namespace rigid_body_sim::node {
namespace {

/// The bodies and robots: robot_description for one, or the config's
/// `bodies`, each urdf naming a parameter that holds a URDF or else a file
/// (package://, absolute, or relative to ~config_file's folder); the world
/// itself is set up as rbsim sets it up (io::loadScene).
io::SceneSetup loadWorld(const NodeParams& params, const ros::NodeHandle& nh) {
  const auto robot_description = [&] {
    std::string xml;
    if (!nh.getParam("robot_description", xml)) {
      throw std::runtime_error("parameter '" + nh.resolveName("robot_description") +
                               "' is not set: load the body's URDF there (launch/sim.launch does), or list "
                               "bodies in ~bodies");
    }
    return io::UrdfText{xml, nh.resolveName("robot_description"), ""};
  };
  ROS_INFO("sim_node: loading the world (a big mesh takes seconds; Ctrl-C stops it)");
  return io::loadScene(params.sim, robot_description, [&](const io::BodyEntry& entry) {
    std::string xml;
    try {
      if (nh.getParam(entry.urdf, xml)) return io::UrdfText{xml, nh.resolveName(entry.urdf), ""};
    } catch (const ros::InvalidNameException&) {
      // Not a parameter name (package://..., a path with dots): a file.
    }
    const bool relative = entry.urdf.rfind("package://", 0) != 0 && entry.urdf.rfind("file://", 0) != 0 &&
                          !std::filesystem::path(entry.urdf).is_absolute();
    if (relative && !std::filesystem::path(params.node.config_file).is_absolute()) {
      throw io::ConfigError("bodies '" + entry.name + "': urdf '" + entry.urdf +
                            "' is a relative path, but ~config_file ('" + params.node.config_file +
                            "') is no absolute path to the config, so its folder is unknown: launch with "
                            "config:=$PWD/FILE.yaml, or give the urdf as package:// or an absolute path");
    }
    return io::readUrdfFile(entry.urdf, params.sim.base_dir);
  });
}

/// The simulation of `world`; its controllers go to `controls`, its
/// sensors to `sensors`, and what its loading repaired or warns of to the
/// log, each message once.
core::Simulation startOf(io::SceneSetup world, std::vector<io::RobotControls>& controls,
                         std::vector<io::RobotSensors>& sensors) {
  for (const std::string& note : world.notes) ROS_WARN("sim_node: %s", note.c_str());
  controls = std::move(world.controls);
  sensors = std::move(world.sensors);
  return {std::move(world.scene), std::move(world.state)};
}

/// The world frame must be none of a body's frames: tf would get base_link
/// → base_link, a loop every listener refuses.
void requireOwnWorldFrame(const std::string& world, const std::string& prefix, const core::BodyModel& body) {
  std::vector<std::string> frames{prefix + body.link};
  for (const core::FixedLink& link : body.fixed_links) frames.push_back(prefix + link.name);
  for (const std::string& frame : frames) {
    if (frame == world) {
      throw io::ConfigError("parameter '~world_frame' = '" + world + "': is also a frame of body '" + body.name +
                            "'; tf would publish " + world + " -> " + world + " (name the world frame otherwise)");
    }
  }
}

}  // namespace

SimNode::SimNode(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh)
    : nh_(nh),
      pnh_(private_nh),
      params_(readParams(private_nh)),
      sim_(startOf(loadWorld(params_, nh_), start_controls_, start_sensors_)),
      use_sim_time_(ros::param::param("/use_sim_time", false)),
      time_(model_.dt(), !use_sim_time_) {
  // ROS shut down while the world loaded (rosnode kill; SIGINT ends the
  // process then, interrupt.h): nothing may be advertised or published.
  if (!ros::ok()) return;
  paused_ = settings_.paused;
  clock_.anchor(0, static_cast<int64_t>(ros::WallTime::now().toNSec()));
  publish_every_ = std::max(1LL, std::llround(1.0 / (settings_.publish_rate * model_.dt())));
  body_states_every_ = std::max(1LL, std::llround(1.0 / (settings_.body_states_rate * model_.dt())));
  port_context_ = {
      nh_,
      pnh_,
      settings_.world_frame,
      model_.dt(),
      [this](const std::string& body, const geometry_msgs::WrenchStamped::ConstPtr& m) {
        load_requests_.onWrench(body, m);
      },
      [this](const std::string& body, const geometry_msgs::Twist::ConstPtr& m) { load_requests_.onCmdVel(body, m); }};
  // One body keeps the single-body names; several get theirs under their name.
  const std::size_t bodies = sim_.freeBodyCount();
  const bool several = bodies + sim_.scene.robots().size() > 1;
  const bool all_topics = static_cast<double>(bodies) <= settings_.per_body_topics;
  if (!all_topics) {
    ROS_INFO(
        "sim_node: %zu bodies, more than ~per_body_topics %g: odometry and wrench topics only for bodies with "
        "a device (imu, odom_noise, cmd_vel); ~body_states, /tf and the services carry every body",
        bodies, settings_.per_body_topics);
  }
  for (std::size_t i = 0; i < bodies; ++i) {
    const core::BodyModel& body = model_.body(i);
    requireOwnWorldFrame(settings_.world_frame, several ? body.name + "/" : "", body);
    const io::SimConfig& c = params_.sim;
    // A listed body's entry by its name: robots among the bodies take
    // entries too, so the i-th entry need not be the i-th body (it gave a
    // body after a robot the robot's devices, and lost its own).
    const auto listed =
        std::find_if(c.bodies.begin(), c.bodies.end(), [&](const io::BodyEntry& e) { return e.name == body.name; });
    BodyDevices devices{c.imu, c.odom_noise, c.cmd_vel};
    if (c.bodies_listed) {
      devices =
          listed != c.bodies.end() ? BodyDevices{listed->imu, listed->odom_noise, listed->cmd_vel} : BodyDevices{};
    }
    const BodyPorts& ports =
        ports_.add(openPorts(port_context_, body, several ? body.name + "/" : "", devices, all_topics), body,
                   state_.bodies[i], simTime());
    ROS_INFO("sim_node: body '%s' (frame '%s'), %.6g kg, %zu collision points", body.name.c_str(), ports.frame.c_str(),
             body.mass, body.contact_points.size());
    if (const std::string warning = io::touchesNothing(body); !warning.empty())
      ROS_WARN("sim_node: %s", warning.c_str());
  }
  for (const core::SceneRobot& robot : sim_.scene.robots()) {
    ROS_INFO("sim_node: robot '%s', %d moving joints, %s base", robot.name.c_str(), robot.model.jointCount(),
             robot.model.fixed_base ? "a world-fixed" : "a floating");
  }
  if (model_.bodyCount() == 0) ROS_INFO("sim_node: an empty world (bodies: []); ~spawn_body adds bodies");
  ROS_INFO("sim_node: ~rate %g Hz, ~dt %g s, ~realtime_factor %g, ~publish_rate %g Hz (every %lld steps)",
           settings_.rate, model_.dt(), settings_.realtime_factor, settings_.publish_rate, publish_every_);
  ROS_INFO("sim_node: ~world_frame '%s', ~publish_tf %s, ~wrench_timeout %g s, ~covariance %g, /use_sim_time %s",
           settings_.world_frame.c_str(), settings_.publish_tf ? "true" : "false", settings_.wrench_timeout,
           settings_.covariance, use_sim_time_ ? "true" : "false");
  ROS_INFO("sim_node: ~body_states at ~body_states_rate %g Hz (every %lld steps), twists in %s axes",
           settings_.body_states_rate, body_states_every_,
           settings_.body_states_twist_in_world ? "the world's" : "each body's");
  YAML::Emitter sim;
  sim << YAML::Flow << params_.sim_yaml;
  const std::string listed =
      params_.sim.bodies_listed ? ", and a bodies list of " + std::to_string(params_.sim.bodies.size()) : "";
  ROS_INFO("sim_node: simulation keys given: %s%s (others at config/default.yaml's defaults)", sim.c_str(),
           listed.c_str());

  publisher_.emplace(nh_, pnh_, settings_, use_sim_time_);
  // Each robot's controllers and joint_states: under its gazebo_ros_control
  // robotNamespace, else as its other topics.
  std::vector<std::string> control_prefixes;
  start_controls_.resize(sim_.scene.robots().size());
  start_sensors_.resize(sim_.scene.robots().size());
  for (std::size_t r = 0; r < sim_.scene.robots().size(); ++r) {
    const std::string& name = sim_.scene.robots()[r].name;
    control_prefixes.push_back(robotTopicPrefix(start_controls_[r].robot_namespace, several ? name + "/" : ""));
    // One topic, one publisher: checked before anything is advertised.
    const std::vector<TopicClaims::Claim> topics =
        robotTopics(several ? name + "/" : "", control_prefixes.back(), start_sensors_.at(r), start_controls_[r]);
    if (const std::string problem = topic_claims_.problem(topics); !problem.empty()) {
      throw io::ConfigError("robot '" + name + "': " + problem);
    }
    topic_claims_.take(name, topics);
  }
  commands_.emplace(nh_, std::move(start_controls_), sim_, time_, control_prefixes);
  commands_->setTimeline(params_.sim.timeline, [this](const std::string& body) -> core::VelocityDriver* {
    const std::optional<int> i = ports_.directory().byName(body);
    if (!i || !ports_[*i].driver) return nullptr;
    return &*ports_[*i].driver;
  });
  robot_publisher_.emplace(nh_, sim_.scene, control_prefixes, settings_.world_frame, model_.dt(),
                           settings_.publish_rate, [this](std::size_t r) { return commands_->jointStateRate(r); });
  checkRobotFrames(robot_publisher_->robots(), settings_.world_frame, ports_.frames());
  link_sensors_.emplace(nh_, model_.dt(), settings_.publish_rate, settings_.world_frame);
  for (std::size_t r = 0; r < sim_.scene.robots().size(); ++r) {
    const std::string& name = sim_.scene.robots()[r].name;
    const std::string prefix = several ? name + "/" : "";
    const std::string& frame_prefix = robot_publisher_->robots()[r].frame_prefix;
    link_sensors_->addRobot(sim_, r, prefix, frame_prefix, start_sensors_[r]);
    leaveBase(r);
  }
  start_sensors_.clear();
  services_ = {
      pnh_.advertiseService("apply_wrench", &LoadRequests::applyWrench, &load_requests_),
      pnh_.advertiseService("apply_impulse", &LoadRequests::applyImpulse, &load_requests_),
      pnh_.advertiseService("clear_wrenches", &LoadRequests::clearWrenches, &load_requests_),
      pnh_.advertiseService("get_state", &StateRequests::getState, &state_requests_),
      pnh_.advertiseService("set_state", &StateRequests::setState, &state_requests_),
      pnh_.advertiseService("reset", &StateRequests::reset, &state_requests_),
      pnh_.advertiseService("pause", &SimNode::pause, this),
      pnh_.advertiseService("unpause", &SimNode::unpause, this),
      pnh_.advertiseService("step", &SimNode::step, this),
      pnh_.advertiseService("delete_body", &WorldEdits::deleteBody, &world_edits_),
      pnh_.advertiseService("set_model_configuration", &JointRequests::setModelConfiguration, &joint_requests_),
      pnh_.advertiseService("get_joint_properties", &JointRequests::getJointProperties, &joint_requests_),
      pnh_.advertiseService("apply_joint_effort", &JointRequests::applyJointEffort, &joint_requests_),
      pnh_.advertiseService("clear_joint_forces", &JointRequests::clearJointForces, &joint_requests_)};
  ros::NodeHandle spawn_nh(pnh_);
  spawn_nh.setCallbackQueue(&spawn_queue_);
  spawn_service_ = spawn_nh.advertiseService("spawn_body", &SimNode::spawnBody, this);
  spawn_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &spawn_queue_);
  spawn_spinner_->start();
  startReconfigure();
  markers_.emplace(pnh_, sceneMarkers(model_.scene(), settings_.world_frame, settings_.scene_size),
                   bodyMarkers(model_, ports_.frames(), ports_.colours()));
  publisher_->fixedFrames(model_, ports_, stamp());
  publisher_->clock(stamp());
  publish();
}

// Each edit touches what the body it adds or removes has: a spawn at
// N = 1000 rebuilt every body's markers and names, and opened its topics
// (round trips to the master), and cost the loop 5-6 ms (bench/spawn_memory.sh).
void SimNode::afterSpawn() {
  const std::size_t last = sim_.freeBodyCount() - 1;
  markers_->added(model_.body(last), ports_[last].frame, ports_[last].colour);
  publisher_->fixedFrames(model_, ports_, stamp(), last);
}

void SimNode::afterRobotSpawn(SpawnQueue::Spawn& spawn) {
  const std::size_t r = sim_.scene.robots().size() - 1;
  const std::string& prefix = spawn.sensor_prefix;
  const std::string& control_prefix = spawn.control_prefix;
  io::RobotControls& controls = spawn.controls;
  const double hz = controls.joint_state_rate > 0.0 ? controls.joint_state_rate : settings_.publish_rate;
  robot_publisher_->addRobot(sim_.scene.robots()[r], control_prefix, hz, spawn.frame_prefix);
  commands_->addRobot(sim_, r, control_prefix, spawn.frame_prefix, std::move(controls));
  link_sensors_->addRobot(sim_, r, prefix, spawn.frame_prefix, spawn.sensors);
  leaveBase(r);
}

void SimNode::leaveBase(std::size_t r) {
  // A frame has one parent: a drive's or a base plugin's odom -> base takes world -> base's place.
  std::vector<std::string> frames = commands_->odometryFrames(r);
  for (std::string& frame : link_sensors_->tfFrames(r)) frames.push_back(std::move(frame));
  robot_publisher_->leaveBase(r, frames);
}

void SimNode::afterRobotDelete(std::size_t r, const std::string& name) {
  robot_publisher_->removeRobot(r);
  commands_->removeRobot(r);
  link_sensors_->removeRobot(r);
  robots_speed_limited_.erase(name);
}

void SimNode::afterDelete(const std::string& name) {
  markers_->removed(name);
  publisher_->fixedFrames(model_, ports_, stamp());
}

SimNode::~SimNode() {
  spawns_.stop();
  if (spawn_spinner_) spawn_spinner_->stop();
}

}  // namespace rigid_body_sim::node
