// What the node publishes: tf and odometry of every body, ~body_states,
// /clock, the fixed links and IMU frames on /tf_static, and the state messages of the services.
#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>

#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {

using core::Quat;

// Every publisher stops once ROS is shutting down (a SIGINT): roscpp aborts
// on a publish after shutdown.
void SimNode::publishClock() {
  if (!use_sim_time_ || !ros::ok()) return;
  rosgraph_msgs::Clock clock;
  clock.clock = stamp();
  clock_pub_.publish(clock);
}

void SimNode::publish() {
  if (!ros::ok()) return;
  const ros::Time now = stamp();
  // Never the same stamp twice (tf2 would warn of repeated data) and never
  // an older one: on sim time a paused set_state waits for the next step.
  if (!last_published_.isZero() && now <= last_published_) return;
  last_published_ = now;
  std_msgs::Header header;
  header.stamp = now;
  header.frame_id = settings_.world_frame;
  // Filled in place: its strings keep their memory from one update to the next.
  tf_batch_.resize(settings_.publish_tf ? model_.bodyCount() : 0);
  for (std::size_t i = 0; i < model_.bodyCount(); ++i) {
    const core::LinkState link = core::linkState(model_.body(i), state_.bodies[i]);
    BodyPorts& p = ports_[i];
    if (settings_.publish_tf) {
      geometry_msgs::TransformStamped& tf = tf_batch_[i];
      tf.header.stamp = header.stamp;
      tf.header.frame_id = header.frame_id;
      tf.child_frame_id = p.frame;
      tf.transform = toTransform(link.p_WL, link.q_WL);
    }
    const auto odometry = [&](const core::OdomReport& r, bool exact) {
      nav_msgs::Odometry odom;
      odom.header = header;
      odom.child_frame_id = p.frame;  // the twist is in this frame (nav_msgs/Odometry)
      odom.pose.pose = toPose(r.p_WL, r.q_WL);
      odom.twist.twist.linear = toVector3(r.v_L);
      odom.twist.twist.angular = toVector3(r.w_L);
      for (int k = 0; k < 6; ++k) {
        odom.pose.covariance[k * 7] = exact ? settings_.covariance : r.pose_variance[k];
        odom.twist.covariance[k * 7] = exact ? settings_.covariance : r.twist_variance[k];
      }
      return odom;
    };
    // Built only for a topic someone listens to (counted_publisher.h); the
    // noise is drawn all the same, so what a subscriber sees does not
    // depend on when others came.
    if (p.odom_noise) {  // noisy odom, the exact state on ground_truth
      const core::OdomReport noisy = p.odom_noise->report(link, simTime() - p.last_odom);
      p.last_odom = simTime();
      if (p.odom.listened()) p.odom.publish(odometry(noisy, false));
      if (p.ground_truth.listened()) p.ground_truth.publish(odometry(core::exactOdom(link), true));
    } else if (p.odom.listened()) {
      p.odom.publish(odometry(core::exactOdom(link), true));
    }
  }
  // One message for all bodies, as robot_state_publisher sends a robot's
  // links: a listener sees every body at one stamp at once, and the node
  // makes one publish() per update, not one per body.
  if (!tf_batch_.empty()) tf_.sendTransform(tf_batch_);
  resendMarkersIfDue();
}

void SimNode::publishBodyStates() {
  if (!ros::ok() || !body_states_pub_.listened()) return;
  BodyStates msg;
  msg.header.stamp = stamp();
  msg.header.frame_id = settings_.world_frame;
  const std::size_t n = model_.bodyCount();
  msg.names.reserve(n);
  msg.poses.reserve(n);
  msg.twist_frames.reserve(n);
  msg.twists.reserve(n);
  msg.asleep.reserve(n);
  const bool in_world = settings_.body_states_twist_in_world;
  for (std::size_t i = 0; i < n; ++i) {
    const core::LinkState link = core::linkState(model_.body(i), state_.bodies[i]);
    const Quat q = in_world ? Quat::Identity() : link.q_WL.conjugate();
    msg.names.push_back(model_.body(i).name);
    msg.poses.push_back(toPose(link.p_WL, link.q_WL));
    msg.twist_frames.push_back(in_world ? settings_.world_frame : ports_[i].frame);
    geometry_msgs::Twist twist;
    twist.linear = toVector3(q * link.v_WL);
    twist.angular = toVector3(q * link.w_W);
    msg.twists.push_back(twist);
    msg.asleep.push_back(state_.bodies[i].asleep);
  }
  body_states_pub_.publish(msg);
}

void SimNode::publishFixedFrames(std::size_t first) {
  if (!ros::ok()) return;
  // Links fixed to a body: their frames under the body's prefix, as
  // robot_state_publisher publishes them for one robot (static: they never move).
  std::vector<geometry_msgs::TransformStamped>& fixed = static_frames_.transforms;
  const bool had = !fixed.empty();
  if (first == 0) fixed.clear();
  const std::size_t before = fixed.size();
  for (std::size_t i = first; i < model_.bodyCount(); ++i) {
    const core::BodyModel& body = model_.body(i);
    const std::string& prefix = ports_[i].prefix;
    for (const core::FixedLink& link : body.fixed_links) {
      geometry_msgs::TransformStamped tf;
      tf.header.stamp = stamp();
      tf.header.frame_id = prefix + link.parent;
      tf.child_frame_id = prefix + link.name;
      tf.transform = toTransform(link.X_PK.translation, link.X_PK.rotation);
      fixed.push_back(tf);
    }
    if (ports_[i].imu) {  // the IMU's frame, fixed to the root link
      const core::Pose& X_LS = ports_[i].imu->settings().X_LS;
      geometry_msgs::TransformStamped tf;
      tf.header.stamp = stamp();
      tf.header.frame_id = ports_[i].frame;
      tf.child_frame_id = ports_[i].imu_frame;
      tf.transform = toTransform(X_LS.translation, X_LS.rotation);
      fixed.push_back(tf);
    }
  }
  // A new set whole (latched: a later subscriber gets it), or fewer frames
  // after a delete; nothing when nothing changed.
  if (fixed.size() > before || (first == 0 && had)) tf_static_pub_.publish(static_frames_);
}

BodyState SimNode::bodyState(int body, const Axes& axes) const {
  const core::BodyModel& b = model_.body(body);
  const core::LinkState link = core::linkState(b, state_.bodies[body]);
  BodyState msg;
  msg.body = b.name;
  msg.stamp = stamp();
  msg.pose = toPose(link.p_WL, link.q_WL);
  msg.twist_frame = axes.other >= 0                    ? ports_[axes.other].frame
                    : axes.frame == core::Frame::kBody ? ports_[body].frame
                                                       : settings_.world_frame;
  const Quat q = orientationOf(axes, body).conjugate();
  msg.twist.linear = toVector3(q * link.v_WL);
  msg.twist.angular = toVector3(q * link.w_W);
  return msg;
}

}  // namespace rigid_body_sim::node
