// The node's set-up: the world (loaded as rbsim loads it), its topics,
// services and first messages. The loop is in pacing.cpp, the messages in
// publishers.cpp and markers.cpp, the services in *_requests.cpp.
#include "rigid_body_sim/ros/sim_node.h"

#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/Imu.h>

#include <algorithm>
#include <boost/make_shared.hpp>
#include <cmath>
#include <filesystem>

#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/io/world.h"
#include "rigid_body_sim/ros/markers.h"

namespace rigid_body_sim::node {
namespace {

/// The bodies: robot_description for one body, or the config's `bodies`,
/// each urdf naming a parameter that holds a URDF or else a file
/// (package://, absolute, or relative to ~config_file's folder); the world
/// itself is set up as rbsim sets it up (io::loadWorld).
io::World loadWorld(const NodeParams& params, const ros::NodeHandle& nh) {
  const auto robot_description = [&] {
    std::string xml;
    if (!nh.getParam("robot_description", xml)) {
      throw std::runtime_error("parameter '" + nh.resolveName("robot_description") +
                               "' is not set: load the body's URDF there (launch/sim.launch does), or list "
                               "bodies in ~bodies");
    }
    return io::loadUrdfString(xml, nh.resolveName("robot_description"));
  };
  ROS_INFO("sim_node: loading the world (a big mesh takes seconds; Ctrl-C stops it)");
  return io::loadWorld(params.sim, robot_description, [&](const io::BodyEntry& entry) {
    std::string xml;
    try {
      if (nh.getParam(entry.urdf, xml)) return io::loadUrdfString(xml, nh.resolveName(entry.urdf));
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
    return io::loadUrdfFile(io::resolveMeshUri(entry.urdf, params.sim.base_dir));
  });
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

/// The pose in the root link frame L of `link` (core::linkPose); another
/// name is refused naming `key`.link and the body's links.
core::Pose mountOf(const core::BodyModel& body, const std::string& link, const std::string& key) {
  if (const std::optional<core::Pose> X_LK = core::linkPose(body, link)) return *X_LK;
  std::string names = "'" + body.link + "'";
  for (const core::FixedLink& f : body.fixed_links) names += ", '" + f.name + "'";
  throw io::ConfigError("config key '" + key + ".link' = '" + link + "': no such link of body '" + body.name +
                        "' (its links: " + names + ")");
}

}  // namespace

SimNode::SimNode(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh)
    : nh_(nh),
      pnh_(private_nh),
      params_(readParams(private_nh)),
      world_(loadWorld(params_, nh_)),
      use_sim_time_(ros::param::param("/use_sim_time", false)),
      clock_(model_.dt(), !use_sim_time_) {
  // ROS shut down while the world loaded (rosnode kill; SIGINT ends the
  // process then, interrupt.h): nothing may be advertised or published.
  if (!ros::ok()) return;
  initial_ = state_;
  paused_ = settings_.paused;
  clock_.anchor(0, static_cast<int64_t>(ros::WallTime::now().toNSec()));
  publish_every_ = std::max(1LL, std::llround(1.0 / (settings_.publish_rate * model_.dt())));
  body_states_every_ = std::max(1LL, std::llround(1.0 / (settings_.body_states_rate * model_.dt())));
  // One body keeps the single-body names; several get theirs under their name.
  const bool several = model_.bodyCount() > 1;
  const bool all_topics = static_cast<double>(model_.bodyCount()) <= settings_.per_body_topics;
  if (!all_topics) {
    ROS_INFO(
        "sim_node: %zu bodies, more than ~per_body_topics %g: odometry and wrench topics only for bodies with "
        "a device (imu, odom_noise, cmd_vel); ~body_states, /tf and the services carry every body",
        model_.bodyCount(), settings_.per_body_topics);
  }
  for (std::size_t i = 0; i < model_.bodyCount(); ++i) {
    const core::BodyModel& body = model_.body(i);
    requireOwnWorldFrame(settings_.world_frame, several ? body.name + "/" : "", body);
    const io::SimConfig& c = params_.sim;
    const BodyDevices devices = c.bodies_listed
                                    ? BodyDevices{c.bodies[i].imu, c.bodies[i].odom_noise, c.bodies[i].cmd_vel}
                                    : BodyDevices{c.imu, c.odom_noise, c.cmd_vel};
    ports_.push_back(openPorts(body, several ? body.name + "/" : "", devices, all_topics));
    startPorts(ports_.back(), state_.bodies[i]);
    ports_.back().colour = bodies_entered_++;
    ROS_INFO("sim_node: body '%s' (frame '%s'), %.6g kg, %zu collision points", body.name.c_str(),
             ports_.back().frame.c_str(), body.mass, body.contact_points.size());
    if (const std::string warning = io::touchesNothing(body); !warning.empty())
      ROS_WARN("sim_node: %s", warning.c_str());
  }
  indexBodies();
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
  ROS_INFO("sim_node: simulation keys given: %s (others at config/default.yaml's defaults)", sim.c_str());

  // Latched markers, sent again to late subscribers once they have seen tf
  // for a while (resendMarkersIfDue).
  const auto on_subscriber = [this](const ros::SingleSubscriberPublisher&) {
    markers_resend_ = MarkersResend{ros::WallTime::now(), 0};
  };
  scene_markers_ = sceneMarkers(model_.scene(), settings_.world_frame, settings_.scene_size);
  body_markers_ = bodyMarkers(model_, frames(), colours());
  scene_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("scene_markers", 1, on_subscriber, {}, {}, true);
  body_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("body_markers", 1, on_subscriber, {}, {}, true);
  if (use_sim_time_) clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  body_states_pub_ = CountedPublisher::advertise<BodyStates>(pnh_, "body_states", 10);
  contacts_pub_ = CountedPublisher::advertise<Contacts>(pnh_, "contacts", 10);
  contact_markers_pub_ = CountedPublisher::advertise<visualization_msgs::MarkerArray>(pnh_, "contact_markers", 10);
  services_ = {pnh_.advertiseService("apply_wrench", &SimNode::applyWrench, this),
               pnh_.advertiseService("apply_impulse", &SimNode::applyImpulse, this),
               pnh_.advertiseService("clear_wrenches", &SimNode::clearWrenches, this),
               pnh_.advertiseService("get_state", &SimNode::getState, this),
               pnh_.advertiseService("set_state", &SimNode::setState, this),
               pnh_.advertiseService("reset", &SimNode::reset, this),
               pnh_.advertiseService("pause", &SimNode::pause, this),
               pnh_.advertiseService("unpause", &SimNode::unpause, this),
               pnh_.advertiseService("step", &SimNode::step, this),
               pnh_.advertiseService("delete_body", &SimNode::deleteBody, this)};
  ros::NodeHandle spawn_nh(pnh_);
  spawn_nh.setCallbackQueue(&spawn_queue_);
  spawn_service_ = spawn_nh.advertiseService("spawn_body", &SimNode::spawnBody, this);
  spawn_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &spawn_queue_);
  spawn_spinner_->start();
  tf_static_pub_ = nh_.advertise<tf2_msgs::TFMessage>("/tf_static", 100, true);
  startReconfigure();
  scene_pub_.publish(scene_markers_);
  body_pub_.publish(body_markers_);
  publishFixedFrames();
  publishClock();
  publish();
}

SimNode::~SimNode() {
  stopping_ = true;
  if (spawn_spinner_) spawn_spinner_->stop();
}

SimNode::BodyPorts SimNode::openPorts(const core::BodyModel& body, const std::string& prefix,
                                      const BodyDevices& devices, bool topics) {
  const auto& [imu, odom_noise, cmd_vel] = devices;
  BodyPorts ports;
  ports.prefix = prefix;
  ports.frame = prefix + body.link;
  // Checked before anything is advertised: a spawn's IMU on no such link is
  // refused with nothing changed (it ended the node once).
  std::optional<core::ImuSettings> imu_settings;
  if (imu) {
    ports.imu_frame = prefix + imu->frame_id;
    bool taken = imu->frame_id == body.link;
    for (const core::FixedLink& link : body.fixed_links) taken = taken || imu->frame_id == link.name;
    if (taken || ports.imu_frame == settings_.world_frame) {
      throw io::ConfigError(imu->key + ".frame_id '" + imu->frame_id + "' of body '" + body.name +
                            "': is already a frame (of the body, or the world); name the sensor's own frame");
    }
    imu_settings = imu->settings;
    imu_settings->X_LS = mountOf(body, imu->link, imu->key) * imu->settings.X_LS;
  }
  const std::string name = body.name;  // by name: a deletion moves the later bodies' indices
  // Through handles of the body's own: a NodeHandle keeps a record of every
  // topic opened through it for as long as it lives (264 bytes each, which
  // the node's own handles kept for every body ever spawned).
  ports.nh = nh_;
  ports.pnh = pnh_;
  if (cmd_vel) {
    ports.driver.emplace(*cmd_vel);
    ports.cmd_vel = ports.nh.subscribe<geometry_msgs::Twist>(
        prefix + "cmd_vel", 10, [this, name](const geometry_msgs::Twist::ConstPtr& m) { onCmdVel(name, m); });
  }
  if (odom_noise) {
    ports.odom_noise = std::make_unique<core::OdomNoise>(*odom_noise);
    ports.ground_truth = CountedPublisher::advertise<nav_msgs::Odometry>(ports.nh, prefix + "ground_truth", 10);
  }
  if (imu_settings) {
    ports.imu = std::make_unique<core::Imu>(*imu_settings, core::BodyState{});  // startPorts() gives it the start
    ports.imu_every = std::max(1LL, std::llround(1.0 / (imu->settings.rate * dt_)));
    ports.imu_pub = CountedPublisher::advertise<sensor_msgs::Imu>(ports.nh, prefix + "imu", 100);
  }
  if (!topics && !cmd_vel && !odom_noise && !imu) return ports;
  ports.odom = CountedPublisher::advertise<nav_msgs::Odometry>(ports.nh, prefix + "odom", 10);
  ports.wrench = ports.pnh.subscribe<geometry_msgs::WrenchStamped>(
      prefix + "wrench", 10, [this, name](const geometry_msgs::WrenchStamped::ConstPtr& m) { onWrench(name, m); });
  return ports;
}

void SimNode::startPorts(BodyPorts& ports, const core::BodyState& start) {
  if (ports.imu) ports.imu->restart(start);
  ports.last_odom = simTime();
}

namespace {

/// Lets what it holds go when the queue calls it, on the queue's thread.
class Release : public ros::CallbackInterface {
 public:
  explicit Release(std::shared_ptr<void> what) : what_(std::move(what)) {}
  CallResult call() override {
    what_.reset();
    return Success;
  }

 private:
  std::shared_ptr<void> what_;
};

}  // namespace

void SimNode::closeLater(BodyPorts&& ports) {
  spawn_queue_.addCallback(boost::make_shared<Release>(std::make_shared<BodyPorts>(std::move(ports))));
}

std::vector<std::size_t> SimNode::colours() const {
  std::vector<std::size_t> colours;
  colours.reserve(ports_.size());
  for (const BodyPorts& p : ports_) colours.push_back(p.colour);
  return colours;
}

std::vector<std::string> SimNode::frames() const {
  std::vector<std::string> frames;
  frames.reserve(ports_.size());
  for (const BodyPorts& p : ports_) frames.push_back(p.frame);
  return frames;
}

}  // namespace rigid_body_sim::node
