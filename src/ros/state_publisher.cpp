#include "rigid_body_sim/ros/state_publisher.h"

#include <rosgraph_msgs/Clock.h>

#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim::node {

using core::Quat;

nav_msgs::Odometry odometryMessage(const core::OdomReport& r, const std::string& child_frame,
                                   const std_msgs::Header& header, std::optional<double> exact) {
  nav_msgs::Odometry odom;
  odom.header = header;
  odom.child_frame_id = child_frame;  // the twist is in this frame (nav_msgs/Odometry)
  odom.pose.pose = toPose(r.p_WL, r.q_WL);
  odom.twist.twist.linear = toVector3(r.v_L);
  odom.twist.twist.angular = toVector3(r.w_L);
  for (int k = 0; k < 6; ++k) {
    odom.pose.covariance[k * 7] = exact ? *exact : r.pose_variance[k];
    odom.twist.covariance[k * 7] = exact ? *exact : r.twist_variance[k];
  }
  return odom;
}

namespace {

/// One entry of ~body_states: `link`'s pose, its twist in `twist_frame`'s
/// axes (the link's own, or the world's when `in_world`).
void addEntry(BodyStates& msg, const std::string& name, const core::LinkState& link, const std::string& twist_frame,
              bool in_world, bool asleep) {
  const Quat q = in_world ? Quat::Identity() : link.q_WL.conjugate();
  msg.names.push_back(name);
  msg.poses.push_back(toPose(link.p_WL, link.q_WL));
  msg.twist_frames.push_back(in_world ? msg.header.frame_id : twist_frame);
  geometry_msgs::Twist twist;
  twist.linear = toVector3(q * link.v_WL);
  twist.angular = toVector3(q * link.w_W);
  msg.twists.push_back(twist);
  msg.asleep.push_back(asleep);
}

}  // namespace

BodyStates bodyStatesMessage(const core::Model& model, const core::State& state, const PortRegistry& ports,
                             const std_msgs::Header& header, bool in_world) {
  BodyStates msg;
  msg.header = header;
  const std::size_t n = ports.size();  // the free bodies
  msg.names.reserve(n);
  msg.poses.reserve(n);
  msg.twist_frames.reserve(n);
  msg.twists.reserve(n);
  msg.asleep.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    addEntry(msg, model.body(i).name, core::linkState(model.body(i), state.bodies[i]), ports[i].frame, in_world,
             state.bodies[i].asleep);
  }
  return msg;
}

void appendRobotBases(const core::Simulation& sim, bool in_world, BodyStates& msg) {
  const std::vector<core::SceneRobot>& robots = sim.scene.robots();
  for (std::size_t r = 0; r < robots.size(); ++r) {
    const core::ArticulationModel& model = robots[r].model;
    // A fixed base's link is `world`: its twist (zero) in the world's axes.
    addEntry(msg, robots[r].name, core::baseLinkState(sim.robots[r]), model.links[0].name, in_world || model.fixed_base,
             sim.robots[r].asleep);
  }
}

void appendFixedFrames(const core::BodyModel& body, const BodyPorts& ports, const ros::Time& stamp,
                       std::vector<geometry_msgs::TransformStamped>& frames) {
  // Links fixed to a body: their frames under the body's prefix, as
  // robot_state_publisher publishes them for one robot (static: they never move).
  const auto add = [&](const std::string& parent, const std::string& child, const core::Pose& X) {
    geometry_msgs::TransformStamped tf;
    tf.header.stamp = stamp;
    tf.header.frame_id = parent;
    tf.child_frame_id = child;
    tf.transform = toTransform(X.translation, X.rotation);
    frames.push_back(tf);
  };
  for (const core::FixedLink& link : body.fixed_links)
    add(ports.prefix + link.parent, ports.prefix + link.name, link.X_PK);
  if (ports.sensors && ports.sensors->imu()) {  // the IMU's frame, on the root link
    add(ports.frame, ports.imu_frame, ports.sensors->imu()->settings().X_LS);
  }
}

StatePublisher::StatePublisher(ros::NodeHandle nh, ros::NodeHandle pnh, const NodeSettings& settings, bool use_sim_time)
    : settings_(settings), use_sim_time_(use_sim_time) {
  if (use_sim_time_) clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
  body_states_pub_ = CountedPublisher::advertise<BodyStates>(pnh, "body_states", 10);
  contacts_pub_ = CountedPublisher::advertise<Contacts>(pnh, "contacts", 10);
  contact_markers_pub_ = CountedPublisher::advertise<visualization_msgs::MarkerArray>(pnh, "contact_markers", 10);
  tf_static_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf_static", 100, true);
}

// Every publisher stops once ROS is shutting down (a SIGINT): roscpp aborts
// on a publish after shutdown.
void StatePublisher::clock(const ros::Time& now) {
  if (!use_sim_time_ || !ros::ok()) return;
  rosgraph_msgs::Clock clock;
  clock.clock = now;
  clock_pub_.publish(clock);
}

bool StatePublisher::state(const core::Simulation& sim, PortRegistry& ports, const ros::Time& now, double t,
                           bool on_rate) {
  if (!ros::ok()) return false;
  // On sim time a paused set_state waits for the next step.
  if (!last_published_.isZero() && now <= last_published_) return false;
  last_published_ = now;
  std_msgs::Header header;
  header.stamp = now;
  header.frame_id = settings_.world_frame;
  const core::Model& model = sim.model();
  tf_batch_.resize(settings_.publish_tf ? ports.size() : 0);  // its strings keep their memory
  for (std::size_t i = 0; i < ports.size(); ++i) {            // the free bodies
    const core::LinkState link = core::linkState(model.body(i), sim.state.bodies[i]);
    BodyPorts& p = ports[i];
    if (settings_.publish_tf) {
      geometry_msgs::TransformStamped& tf = tf_batch_[i];
      tf.header.stamp = header.stamp;
      tf.header.frame_id = header.frame_id;
      tf.child_frame_id = p.frame;
      tf.transform = toTransform(link.p_WL, link.q_WL);
    }
    // Built only for a topic someone listens to (counted_publisher.h); the
    // noise is drawn all the same, so what a subscriber sees does not
    // depend on when others came.
    if (p.sensors && p.sensors->noisy()) {  // noisy odom, the exact state on ground_truth
      if (!on_rate) continue;
      const core::OdomReport noisy = p.sensors->report(link, t);
      if (p.odom.listened()) p.odom.publish(odometryMessage(noisy, p.frame, header, std::nullopt));
      if (p.ground_truth.listened()) {
        p.ground_truth.publish(odometryMessage(core::exactOdom(link), p.frame, header, settings_.covariance));
      }
    } else if (p.odom.listened()) {
      p.odom.publish(odometryMessage(core::exactOdom(link), p.frame, header, settings_.covariance));
    }
  }
  // One message for all bodies, as robot_state_publisher sends a robot's
  // links: a listener sees every body at one stamp at once, and the node
  // makes one publish() per update, not one per body.
  if (!tf_batch_.empty()) tf_.sendTransform(tf_batch_);
  return true;
}

void StatePublisher::bodyStates(const core::Simulation& sim, const PortRegistry& ports, const ros::Time& now) {
  if (!ros::ok() || !body_states_pub_.listened()) return;
  std_msgs::Header header;
  header.stamp = now;
  header.frame_id = settings_.world_frame;
  BodyStates msg = bodyStatesMessage(sim.model(), sim.state, ports, header, settings_.body_states_twist_in_world);
  appendRobotBases(sim, settings_.body_states_twist_in_world, msg);
  body_states_pub_.publish(msg);
}

void StatePublisher::fixedFrames(const core::Model& model, const PortRegistry& ports, const ros::Time& now,
                                 std::size_t first) {
  if (!ros::ok()) return;
  std::vector<geometry_msgs::TransformStamped>& fixed = static_frames_.transforms;
  const bool had = !fixed.empty();
  if (first == 0) fixed.clear();
  const std::size_t before = fixed.size();
  for (std::size_t i = first; i < ports.size(); ++i) appendFixedFrames(model.body(i), ports[i], now, fixed);
  // A new set whole (latched: a later subscriber gets it), or fewer frames
  // after a delete; nothing when nothing changed.
  if (fixed.size() > before || (first == 0 && had)) tf_static_pub_.publish(static_frames_);
}

}  // namespace rigid_body_sim::node
