#include "rigid_body_sim/ros/sim_node.h"

#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>
#include <sys/prctl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <thread>

#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/markers.h"

namespace rigid_body_sim::node {
namespace {

using core::Quat;
using core::Vec3;

// What a request may ask for at most: beyond these it is refused as absurd.
constexpr double kMaxForce = 1e6;         // N
constexpr double kMaxTorque = 1e6;        // N·m
constexpr double kMaxImpulse = 1e5;       // N·s and N·m·s
constexpr double kMaxPosition = 1e6;      // m, also for points of application
constexpr double kMaxSpeed = 1e4;         // m/s
constexpr double kMaxAngularSpeed = 1e4;  // rad/s
constexpr int kMaxSteps = 1000000;        // per ~step call
constexpr double kMaxLeadTime = 1e6;      // s, how far ahead a start_time may be
constexpr int kMaxStepsPerTick = 1000;    // beyond this the loop gives up catching up

/// "" if v is finite and |v| ≤ limit, else why not.
std::string checkVector(const Vec3& v, double limit, const std::string& what, const std::string& unit) {
  std::ostringstream os;
  if (!v.allFinite()) {
    os << what << " is not finite: [" << v.x() << ", " << v.y() << ", " << v.z() << "]";
  } else if (v.norm() > limit) {
    os << what << " is absurd: |" << what << "| = " << v.norm() << " " << unit << " > " << limit << " " << unit;
  }
  return os.str();
}

/// The first non-empty complaint, or "".
std::string firstProblem(std::initializer_list<std::string> problems) {
  for (const std::string& p : problems) {
    if (!p.empty()) return p;
  }
  return {};
}

/// The bodies: robot_description for one body, or the config's `bodies`,
/// each urdf naming a parameter that holds a URDF or else a file
/// (package://, absolute, or relative to ~config_file's folder).
io::World loadWorld(const NodeParams& params, const ros::NodeHandle& nh) {
  if (params.sim.bodies.empty()) {
    std::string xml;
    if (!nh.getParam("robot_description", xml)) {
      throw std::runtime_error("parameter '" + nh.resolveName("robot_description") +
                               "' is not set: load the body's URDF there (launch/sim.launch does), or list "
                               "bodies in ~bodies");
    }
    io::World world{io::buildModel(params.sim, io::loadUrdfString(xml, nh.resolveName("robot_description"))), {}};
    world.state.bodies = {core::bodyStateFromLink(world.model.body(0), params.sim.initial)};
    return world;
  }
  return io::buildWorld(params.sim, [&](const io::BodyEntry& entry) {
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

}  // namespace

SimNode::SimNode(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh)
    : nh_(nh),
      pnh_(private_nh),
      params_(readParams(private_nh)),
      world_(loadWorld(params_, nh_)),
      use_sim_time_(ros::param::param("/use_sim_time", false)),
      clock_(model_.dt(), !use_sim_time_) {
  initial_ = state_;
  clock_.anchor(0, static_cast<int64_t>(ros::WallTime::now().toNSec()));
  publish_every_ = std::max(1LL, std::llround(1.0 / (settings_.publish_rate * model_.dt())));
  // One body keeps the single-body names; several get theirs under their name.
  const bool several = model_.bodyCount() > 1;
  held_wrenches_.resize(model_.bodyCount());
  for (std::size_t i = 0; i < model_.bodyCount(); ++i) {
    const core::BodyModel& body = model_.body(i);
    const std::string prefix = several ? body.name + "/" : "";
    frames_.push_back(prefix + body.link);
    odom_pubs_.push_back(nh_.advertise<nav_msgs::Odometry>(prefix + "odom", 10));
    const int index = static_cast<int>(i);
    wrench_subs_.push_back(pnh_.subscribe<geometry_msgs::WrenchStamped>(
        prefix + "wrench", 10, [this, index](const geometry_msgs::WrenchStamped::ConstPtr& m) { onWrench(index, m); }));
    ROS_INFO("sim_node: body '%s' (frame '%s'), %.6g kg, %zu collision points", body.name.c_str(),
             frames_.back().c_str(), body.mass, body.contact_points.size());
  }
  ROS_INFO("sim_node: ~rate %g Hz, ~dt %g s, ~realtime_factor %g, ~publish_rate %g Hz (every %lld steps)",
           settings_.rate, model_.dt(), settings_.realtime_factor, settings_.publish_rate, publish_every_);
  ROS_INFO("sim_node: ~world_frame '%s', ~wrench_timeout %g s, ~covariance %g, /use_sim_time %s",
           settings_.world_frame.c_str(), settings_.wrench_timeout, settings_.covariance,
           use_sim_time_ ? "true" : "false");
  YAML::Emitter sim;
  sim << YAML::Flow << params_.sim_yaml;
  ROS_INFO("sim_node: simulation keys given: %s (others at config/default.yaml's defaults)", sim.c_str());

  // Latched markers, sent again to late subscribers once they have seen tf
  // for a while (resendMarkersIfDue).
  const auto on_subscriber = [this](const ros::SingleSubscriberPublisher&) {
    markers_resend_ = MarkersResend{ros::WallTime::now(), 0};
  };
  scene_markers_ = sceneMarkers(model_.scene(), settings_.world_frame, settings_.scene_size);
  body_markers_ = bodyMarkers(model_, frames_);
  scene_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("scene_markers", 1, on_subscriber, {}, {}, true);
  body_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("body_markers", 1, on_subscriber, {}, {}, true);
  if (use_sim_time_) clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  services_ = {pnh_.advertiseService("apply_wrench", &SimNode::applyWrench, this),
               pnh_.advertiseService("apply_impulse", &SimNode::applyImpulse, this),
               pnh_.advertiseService("clear_wrenches", &SimNode::clearWrenches, this),
               pnh_.advertiseService("get_state", &SimNode::getState, this),
               pnh_.advertiseService("set_state", &SimNode::setState, this),
               pnh_.advertiseService("reset", &SimNode::reset, this),
               pnh_.advertiseService("pause", &SimNode::pause, this),
               pnh_.advertiseService("unpause", &SimNode::unpause, this),
               pnh_.advertiseService("step", &SimNode::step, this)};
  scene_pub_.publish(scene_markers_);
  body_pub_.publish(body_markers_);
  publishFixedFrames();
  publishClock();
  publish();
}

// ------------------------------------------------------------------ stepping

void SimNode::stepOnce() {
  const double t = simTime(), h = model_.dt();
  schedule_.loadsFor(model_, state_, t, h, loads_);
  for (std::size_t i = 0; i < held_wrenches_.size(); ++i) {
    std::optional<HeldWrench>& held = held_wrenches_[i];
    if (!held) continue;
    if (settings_.wrench_timeout > 0.0 && t - held->received > settings_.wrench_timeout) {
      held.reset();
    } else {
      if (loads_.empty()) loads_.resize(model_.bodyCount());
      const core::Wrench& w = held->wrench;
      core::addWrench(model_.body(i), loads_[i],
                      held->axes.other < 0 ? w : core::inWorldAxes(w, orientationOf(held->axes, i)));
    }
  }
  core::step(model_, state_, loads_, &workspace_);
  ++steps_;
  state_.time = simTime();  // the node's clock: exact multiples of Δt, never reset
  schedule_.dropFinished(simTime());
  if (steps_ % publish_every_ == 0) {
    publishClock();
    publish();
  }
}

void SimNode::publishClock() {
  if (!use_sim_time_) return;
  rosgraph_msgs::Clock clock;
  clock.clock = stamp();
  clock_pub_.publish(clock);
}

void SimNode::publish() {
  const ros::Time now = stamp();
  // Never the same stamp twice (tf2 would warn of repeated data) and never
  // an older one: on sim time a paused set_state waits for the next step.
  if (!last_published_.isZero() && now <= last_published_) return;
  last_published_ = now;
  for (std::size_t i = 0; i < model_.bodyCount(); ++i) {
    const core::BodyModel& body = model_.body(i);
    const core::LinkState link = core::linkState(body, state_.bodies[i]);
    geometry_msgs::TransformStamped tf;
    tf.header.stamp = now;
    tf.header.frame_id = settings_.world_frame;
    tf.child_frame_id = frames_[i];
    tf.transform = toTransform(link.p_WL, link.q_WL);
    tf_.sendTransform(tf);

    nav_msgs::Odometry odom;
    odom.header = tf.header;
    odom.child_frame_id = frames_[i];  // the twist is in this frame (nav_msgs/Odometry)
    odom.pose.pose = toPose(link.p_WL, link.q_WL);
    const Quat q_LW = link.q_WL.conjugate();
    odom.twist.twist.linear = toVector3(q_LW * link.v_WL);
    odom.twist.twist.angular = toVector3(q_LW * link.w_W);
    for (int k = 0; k < 6; ++k) {
      odom.pose.covariance[k * 7] = settings_.covariance;
      odom.twist.covariance[k * 7] = settings_.covariance;
    }
    odom_pubs_[i].publish(odom);
  }
  resendMarkersIfDue();
}

void SimNode::resendMarkersIfDue() {
  // rviz passes each marker through a tf2 MessageFilter. A marker stamped 0
  // that arrives before its frame's first transform is failed for good when
  // that transform is stamped more than the buffer's 10 s after 0 (always
  // on the wall-anchored clock, after 10 s on sim time), and the latched
  // copy a new subscriber gets on connecting can beat tf. So the markers go
  // again once the subscriber has had tf for a second: by then rviz knows
  // every frame, and a marker for a known frame passes at once.
  if (!markers_resend_ || ++markers_resend_->publishes < 2 ||
      (ros::WallTime::now() - markers_resend_->connected).toSec() < 1.0) {
    return;
  }
  markers_resend_.reset();
  scene_pub_.publish(scene_markers_);
  body_pub_.publish(body_markers_);
}

void SimNode::publishFixedFrames() {
  // Links fixed to a body: their frames under the body's prefix, as
  // robot_state_publisher publishes them for one robot (static: they never move).
  std::vector<geometry_msgs::TransformStamped> fixed;
  for (std::size_t i = 0; i < model_.bodyCount(); ++i) {
    const core::BodyModel& body = model_.body(i);
    // frames_[i] is the body's prefix ("NAME/" or "") followed by its root link.
    const std::string prefix = frames_[i].substr(0, frames_[i].size() - body.link.size());
    for (const core::FixedLink& link : body.fixed_links) {
      geometry_msgs::TransformStamped tf;
      tf.header.stamp = stamp();
      tf.header.frame_id = prefix + link.parent;
      tf.child_frame_id = prefix + link.name;
      tf.transform = toTransform(link.X_PK.translation, link.X_PK.rotation);
      fixed.push_back(tf);
    }
  }
  if (!fixed.empty()) static_tf_.sendTransform(fixed);
}

double SimNode::rebaseClock() {
  const int64_t lead = paused_ ? 0 : clock_.anchor(steps_, static_cast<int64_t>(ros::WallTime::now().toNSec()));
  ref_wall_ = std::chrono::steady_clock::now() + std::chrono::nanoseconds(lead);
  ref_sim_ = simTime();
  return 1e-9 * static_cast<double>(lead);
}

void SimNode::run() {
  using Clock = std::chrono::steady_clock;
  // Linux lets a sleeping thread wake up to 50 us late by default (timer
  // slack); at 1 kHz that is the step-period jitter. Ask for 1 us.
  prctl(PR_SET_TIMERSLACK, 1000UL, 0UL, 0UL, 0UL);
  const auto tick = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / settings_.rate));
  rebaseClock();
  auto next_tick = Clock::now();
  auto last_tick = next_tick;
  const double rtf = settings_.realtime_factor;
  if (settings_.report_timing) tick_periods_.reserve(1 << 20);
  while (ros::ok()) {
    const auto tick_start = Clock::now();
    if (settings_.report_timing) tick_periods_.push_back(std::chrono::duration<double>(tick_start - last_tick).count());
    last_tick = tick_start;
    if (!paused_ && rtf > 0.0) {
      // Step until sim time reaches wall time × realtime factor.
      const double target = ref_sim_ + std::chrono::duration<double>(tick_start - ref_wall_).count() * rtf;
      int n = 0;
      while (simTime() + 0.5 * model_.dt() <= target && n < kMaxStepsPerTick) {
        stepOnce();
        ++n;
      }
      if (n == kMaxStepsPerTick) {
        ROS_WARN_THROTTLE(5.0, "sim_node: cannot keep up with realtime_factor %g; slowing down", rtf);
        rebaseClock();
      }
    } else if (!paused_) {
      // As fast as possible: steps in slices of about a millisecond, then callbacks.
      const auto slice_end = tick_start + std::chrono::milliseconds(1);
      do {
        for (int k = 0; k < 64; ++k) stepOnce();
      } while (Clock::now() < slice_end);
    }
    ros::spinOnce();
    if (rtf > 0.0 || paused_) {
      next_tick += tick;
      const auto now = Clock::now();
      if (next_tick < now) next_tick = now;  // late: do not try to make up ticks
      std::this_thread::sleep_until(next_tick);
    }
  }
  if (settings_.report_timing && tick_periods_.size() > 10) {
    std::vector<double> d(tick_periods_.begin() + 1, tick_periods_.end());
    for (double& x : d) x = std::abs(x - 1.0 / settings_.rate);
    std::sort(d.begin(), d.end());
    // Plain stdout: ROS logging is already shut down once ros::ok() is false.
    std::printf(
        "sim_node: timing: %zu ticks, |period - %.6g s| p50 %.1f us, p99 %.1f us, max %.1f us; sim time %.3f s\n",
        d.size(), 1.0 / settings_.rate, 1e6 * d[d.size() / 2], 1e6 * d[d.size() * 99 / 100], 1e6 * d.back(), simTime());
    std::fflush(stdout);
  }
}

// ------------------------------------------------------------------ requests

std::optional<int> SimNode::findBody(const std::string& name, std::string& error) const {
  if (name.empty() && model_.bodyCount() == 1) return 0;
  std::string names;
  for (std::size_t i = 0; i < model_.bodyCount(); ++i) {
    if (model_.body(i).name == name) return static_cast<int>(i);
    names += (i ? ", '" : "'") + model_.body(i).name + "'";
  }
  error = name.empty() ? "there are several bodies: give body (" + names + ")"
                       : "unknown body '" + name + "' (the bodies: " + names + ")";
  return std::nullopt;
}

std::optional<SimNode::Axes> SimNode::findFrame(const std::string& frame, int body, std::string& error) const {
  if (frame.empty() || frame == settings_.world_frame || frame == "world") return Axes{};
  if (frame == frames_[body] || frame == model_.body(body).link) return Axes{core::Frame::kBody, -1};
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    if (frame == frames_[i]) return Axes{core::Frame::kWorld, static_cast<int>(i)};
  }
  error = "unknown frame '" + frame + "' (use '" + settings_.world_frame + "', the body's frame '" + frames_[body] +
          "'" + (frames_.size() > 1 ? " or another body's tf frame" : "") + ")";
  return std::nullopt;
}

core::Quat SimNode::orientationOf(const Axes& axes, int body) const {
  const int owner = axes.other >= 0 ? axes.other : axes.frame == core::Frame::kBody ? body : -1;
  if (owner < 0) return Quat::Identity();
  return core::linkState(model_.body(owner), state_.bodies[owner]).q_WL;
}

BodyState SimNode::bodyState(int body, const Axes& axes) const {
  const core::BodyModel& b = model_.body(body);
  const core::LinkState link = core::linkState(b, state_.bodies[body]);
  BodyState msg;
  msg.body = b.name;
  msg.stamp = stamp();
  msg.pose = toPose(link.p_WL, link.q_WL);
  msg.twist_frame = axes.other >= 0                    ? frames_[axes.other]
                    : axes.frame == core::Frame::kBody ? frames_[body]
                                                       : settings_.world_frame;
  const Quat q = orientationOf(axes, body).conjugate();
  msg.twist.linear = toVector3(q * link.v_WL);
  msg.twist.angular = toVector3(q * link.w_W);
  return msg;
}

std::optional<SimNode::Target> SimNode::findTarget(const std::string& body_name, const std::string& frame_name,
                                                   std::string& error) const {
  const auto body = findBody(body_name, error);
  if (!body) return std::nullopt;
  const auto frame = findFrame(frame_name, *body, error);
  if (!frame) return std::nullopt;
  return Target{*body, *frame};
}

bool SimNode::applyWrench(ApplyWrench::Request& req, ApplyWrench::Response& res) {
  res.success = false;
  const auto target = findTarget(req.body, req.frame, res.message);
  if (!target) return true;
  const auto [body, axes] = *target;
  const Vec3 force = fromVector3(req.force), torque = fromVector3(req.torque), point = fromPoint(req.point);
  res.message =
      firstProblem({checkVector(force, kMaxForce, "force", "N"), checkVector(torque, kMaxTorque, "torque", "N*m"),
                    checkVector(point, kMaxPosition, "point", "m")});
  if (!res.message.empty()) return true;
  const double duration = req.duration.toSec();
  if (duration == 0.0) {
    res.message =
        "duration 0 applies nothing: give duration > 0 (for that long), < 0 (until clear_wrenches), "
        "or call apply_impulse for an instantaneous push";
    return true;
  }
  // start_time is on the node's clock (the stamps of /odom and tf): 0 or
  // the past means now, the next step; far ahead is another clock's reading.
  double start = simTime();
  std::string when = "from now (t = " + now() + ")";
  if (!req.start_time.isZero()) {
    const int64_t asked = static_cast<int64_t>(req.start_time.toNSec());
    const double at = clock_.simTimeAt(asked), lead = at - simTime();
    if (lead > kMaxLeadTime) {
      res.message = "start_time " + formatStamp(asked) + " s is " + std::to_string(lead) +
                    " s ahead of this node's clock (now " + now() +
                    "): is it on another clock? Stamps of odom and tf are on this one; 0 means now";
      return true;
    }
    if (lead > 0.0) {
      start = at;
      when = "from t = " + formatStamp(asked) + " s";
    } else if (lead < 0.0) {
      when = "from now (start_time " + formatStamp(asked) + " s is past; t = " + now() + ")";
    }
  }
  const double end = duration > 0.0 ? start + duration : core::WrenchSchedule::kForever;
  schedule_.add(body, {force, torque, point, axes.frame}, start, end, axes.other);
  res.success = true;
  std::ostringstream os;
  os << "wrench on '" << model_.body(body).name << "' " << when << " "
     << (duration > 0.0 ? "for " + std::to_string(duration) + " s" : std::string("until cleared"));
  res.message = os.str();
  return true;
}

bool SimNode::applyImpulse(ApplyImpulse::Request& req, ApplyImpulse::Response& res) {
  res.success = false;
  const auto target = findTarget(req.body, req.frame, res.message);
  if (!target) return true;
  const auto [body, axes] = *target;
  const Vec3 linear = fromVector3(req.linear), angular = fromVector3(req.angular), point = fromPoint(req.point);
  res.message = firstProblem({checkVector(linear, kMaxImpulse, "linear", "N*s"),
                              checkVector(angular, kMaxImpulse, "angular", "N*m*s"),
                              checkVector(point, kMaxPosition, "point", "m")});
  if (!res.message.empty()) return true;
  core::BodyState after = state_.bodies[body];
  core::Impulse impulse{linear, angular, point, axes.frame};
  if (axes.other >= 0) impulse = core::inWorldAxes(impulse, orientationOf(axes, body));
  core::applyImpulse(model_.body(body), after, impulse);
  const std::string speed = checkVector(after.v_WB, kMaxSpeed, "resulting velocity", "m/s");
  const std::string spin = checkVector(after.w_B, kMaxAngularSpeed, "resulting angular velocity", "rad/s");
  if (!speed.empty() || !spin.empty()) {
    res.message = speed.empty() ? spin : speed;
    return true;
  }
  state_.bodies[body] = after;
  res.success = true;
  res.message = "impulse applied to '" + model_.body(body).name + "'";
  return true;
}

bool SimNode::clearWrenches(ClearWrenches::Request& req, ClearWrenches::Response& res) {
  int body = -1;
  if (!req.body.empty()) {
    const auto found = findBody(req.body, res.message);
    if (!found) {
      res.success = false;
      return true;
    }
    body = *found;
  }
  schedule_.clear(body);
  for (std::size_t i = 0; i < held_wrenches_.size(); ++i) {
    if (body < 0 || static_cast<int>(i) == body) held_wrenches_[i].reset();
  }
  res.success = true;
  res.message = "wrenches cleared";
  return true;
}

bool SimNode::getState(GetState::Request& req, GetState::Response& res) {
  res.success = false;
  const auto target = findTarget(req.body, req.frame, res.message);
  if (!target) return true;
  const auto [body, axes] = *target;
  res.state = bodyState(body, axes);
  res.success = true;
  return true;
}

bool SimNode::setState(SetState::Request& req, SetState::Response& res) {
  res.success = false;
  const auto target = findTarget(req.body.empty() ? req.state.body : req.body, req.state.twist_frame, res.message);
  if (!target) return true;
  const auto [body, axes] = *target;
  const Vec3 p = fromPoint(req.state.pose.position);
  const Vec3 v = fromVector3(req.state.twist.linear), w = fromVector3(req.state.twist.angular);
  const geometry_msgs::Quaternion& mq = req.state.pose.orientation;
  const Quat q(mq.w, mq.x, mq.y, mq.z);  // geometry_msgs is (x, y, z, w); Eigen takes (w, x, y, z)
  res.message =
      firstProblem({checkVector(p, kMaxPosition, "position", "m"), checkVector(v, kMaxSpeed, "linear velocity", "m/s"),
                    checkVector(w, kMaxAngularSpeed, "angular velocity", "rad/s")});
  if (!res.message.empty()) return true;
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-3) {
    std::ostringstream os;
    os << "orientation is not a unit quaternion (norm " << q.norm() << "; the identity is x=0 y=0 z=0 w=1)";
    res.message = os.str();
    return true;
  }
  core::LinkState link;
  link.p_WL = p;
  link.q_WL = q.normalized();
  // The twist's axes: the new pose's own, or another body's as it is now.
  const Quat q_frame = axes.frame == core::Frame::kBody ? link.q_WL : orientationOf(axes, body);
  link.v_WL = q_frame * v;
  link.w_W = q_frame * w;
  state_.bodies[body] = core::bodyStateFromLink(model_.body(body), link);
  state_.contact_impulses.clear();  // nothing carries over to a new pose
  res.success = true;
  res.message = "state set";
  publish();
  return true;
}

bool SimNode::reset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  // Back to the initial state; sim time keeps increasing (tf listeners never see it go back).
  state_ = initial_;
  state_.time = simTime();
  schedule_.clear(-1);
  for (auto& held : held_wrenches_) held.reset();
  rebaseClock();
  publish();
  res.success = true;
  res.message = "reset to the initial state at t = " + now();
  return true;
}

bool SimNode::pause(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  paused_ = true;
  res.success = true;
  res.message = "paused at t = " + now();
  return true;
}

bool SimNode::unpause(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  paused_ = false;
  // Do not make up for the paused time; the wall-anchored clock resumes at
  // wall time, or, if steps taken while paused put it ahead, waits for it.
  const double lead = rebaseClock();
  res.success = true;
  res.message = "running from t = " + now();
  if (lead > 0.0 && settings_.realtime_factor > 0.0) {
    res.message += " once the wall clock reaches it, in " + std::to_string(lead) +
                   " s (the steps taken while paused put the clock ahead; /use_sim_time has no such wait)";
  }
  return true;
}

bool SimNode::step(Step::Request& req, Step::Response& res) {
  res.success = false;
  if (!paused_) {
    res.message = "the simulation is running: call pause first (step advances a paused simulation)";
    return true;
  }
  if (req.steps < 1 || req.steps > kMaxSteps) {
    res.message = "steps = " + std::to_string(req.steps) + ": must be within 1 ... " + std::to_string(kMaxSteps);
    return true;
  }
  for (int k = 0; k < req.steps; ++k) stepOnce();
  publishClock();
  publish();
  res.success = true;
  res.message = "stepped " + std::to_string(req.steps) + " steps";
  res.time = stamp();
  for (std::size_t i = 0; i < model_.bodyCount(); ++i) res.states.push_back(bodyState(static_cast<int>(i), Axes{}));
  return true;
}

void SimNode::onWrench(int body, const geometry_msgs::WrenchStamped::ConstPtr& msg) {
  std::string why;
  const auto axes = findFrame(msg->header.frame_id, body, why);
  const Vec3 force = fromVector3(msg->wrench.force), torque = fromVector3(msg->wrench.torque);
  if (why.empty()) why = checkVector(force, kMaxForce, "force", "N");
  if (why.empty()) why = checkVector(torque, kMaxTorque, "torque", "N*m");
  if (!why.empty()) {
    ROS_WARN_THROTTLE(1.0, "sim_node: wrench for '%s' ignored: %s", model_.body(body).name.c_str(), why.c_str());
    return;
  }
  held_wrenches_[body] = HeldWrench{{force, torque, Vec3::Zero(), axes->frame}, simTime(), *axes};
}

}  // namespace rigid_body_sim::node
