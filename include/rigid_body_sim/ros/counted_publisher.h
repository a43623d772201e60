// A ros::Publisher that counts its own subscribers. roscpp's publish() and
// getNumSubscribers() find their topic by a linear search of every topic the
// process advertises; with one odometry topic per body that is O(N) per
// message and O(N²) per state update (10,000 bodies ran at 2 % of real time,
// bench/HISTORY.md). The count, kept by roscpp's connect and disconnect
// callbacks, tells the node which messages no one would receive, so it
// neither builds nor sends them.
#pragma once

#include <ros/ros.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

namespace rigid_body_sim::node {

/// A handle of its own on `nh`'s namespace, for what one robot opens: a
/// ros::NodeHandle keeps a weak pointer to every publisher and subscriber
/// opened through it for as long as it lives, and with it the 264-byte
/// block each was made in. The node's long-lived handles kept them for
/// every robot ever spawned (2.5 KB a spawn and delete of a rover, no
/// plateau); a robot's own handle goes with it. Bodies' ports hold theirs
/// (BodyPorts::nh).
inline std::shared_ptr<ros::NodeHandle> ownHandle(const ros::NodeHandle& nh) {
  return std::make_shared<ros::NodeHandle>(nh);
}

/// The outgoing queue of one entity's stream (its odometry, joint states,
/// IMU, F/T, contacts, GNSS, range and scan readings): what roscpp holds for
/// a subscriber not yet sent, the oldest dropped beyond it. A `~step` of N
/// steps publishes all of them at once; with a queue of 10 a step of 300
/// delivered 189 of 300 /odom messages. Every message of a 1 kHz topic comes
/// through a `~step` of 1000, and a queue holds memory only while a
/// subscriber lags. What may be large keeps a small queue: point clouds and
/// images, and the world's `~body_states` and `~contacts` (10: a megabyte a
/// message in a world of 10,000 bodies).
inline constexpr std::uint32_t kStreamQueue = 1000;

class CountedPublisher {
 public:
  CountedPublisher() = default;

  /// Advertises `topic` on `nh`, as NodeHandle::advertise<M> does.
  template <class M>
  static CountedPublisher advertise(ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue_size) {
    CountedPublisher p;
    p.subscribers_ = std::make_shared<std::atomic<int>>(0);
    const std::shared_ptr<std::atomic<int>> count = p.subscribers_;  // the callbacks may outlive this object
    p.publisher_ = nh.advertise<M>(
        topic, queue_size, [count](const ros::SingleSubscriberPublisher&) { ++*count; },
        [count](const ros::SingleSubscriberPublisher&) { --*count; });
    return p;
  }

  /// Whether a subscriber is connected (as the callbacks so far have told).
  bool listened() const { return subscribers_ && subscribers_->load(std::memory_order_relaxed) > 0; }

  /// Sends `msg` if anyone listens.
  template <class M>
  void publish(const M& msg) const {
    if (listened()) publisher_.publish(msg);
  }

 private:
  ros::Publisher publisher_;
  std::shared_ptr<std::atomic<int>> subscribers_;
};

}  // namespace rigid_body_sim::node
