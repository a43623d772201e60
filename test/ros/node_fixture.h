// The fixture of the node's rostests: a test node that waits for sim_node's
// services and calls them as a user would.
#pragma once

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "rigid_body_sim/ApplyImpulse.h"
#include "rigid_body_sim/ApplyWrench.h"
#include "rigid_body_sim/GetState.h"
#include "rigid_body_sim/Step.h"

namespace rbs_test {

using rigid_body_sim::BodyState;

inline constexpr double kG = 9.81;
inline constexpr double kDt = 1e-3;
inline const std::string kLink = "base_link";

inline geometry_msgs::Vector3 vec(double x, double y, double z) {
  geometry_msgs::Vector3 v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}

/// Whether `text` is printable ASCII (rosconsole shows other bytes as '?',
/// rosservice as escapes).
inline bool plainAscii(const std::string& text) {
  for (const unsigned char c : text) {
    if (c < 0x20 || c >= 0x7f) return false;
  }
  return true;
}

/// Whether the master lists `topic` as published by someone.
inline bool advertised(const std::string& topic) {
  ros::master::V_TopicInfo topics;
  ros::master::getTopics(topics);
  for (const auto& t : topics) {
    if (t.name == topic) return true;
  }
  return false;
}

/// Whether the master lists node `node` as a subscriber of `topic`.
inline bool subscribes(const std::string& node, const std::string& topic) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", args, result, payload, true)) return false;
  XmlRpc::XmlRpcValue& subscribers = payload[1];  // [[topic, [node, ...]], ...]
  for (int i = 0; i < subscribers.size(); ++i) {
    if (static_cast<std::string>(subscribers[i][0]) != topic) continue;
    for (int k = 0; k < subscribers[i][1].size(); ++k) {
      if (static_cast<std::string>(subscribers[i][1][k]) == node) return true;
    }
  }
  return false;
}

/// The least time between two consecutive stamps of `messages` (s): a
/// topic's period, whatever a busy machine dropped (it never adds one).
template <typename Message>
double leastSpacing(const std::vector<Message>& messages) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < messages.size(); ++k) {
    least = std::min(least, (messages[k].header.stamp - messages[k - 1].header.stamp).toSec());
  }
  return least;
}

/// The sim time now, as this test node knows it (s): the later of `latest`,
/// the stamp of the newest message a test has taken, and its /clock. A test
/// that falls behind its 1000-message queues on a busy machine (two ASan
/// rostests at once) holds stamps up to a second old, and "from now" dated by
/// them starts a wait before its command was sent. roscpp reads /clock on its
/// own thread and keeps only the newest, so ros::Time::now() is never stale.
/// Only with /use_sim_time: on the wall clock now() is ahead of every stamp.
inline double simNow(double latest) { return std::max(latest, ros::Time::now().toSec()); }

/// Waits (wall time) until `done` or `seconds` pass, spinning callbacks.
inline bool spinUntil(const std::function<bool()>& done, double seconds) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    ros::spinOnce();
    if (done()) return true;
    ros::WallDuration(0.002).sleep();
  }
  return done();
}

class Node : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* s : {"get_state", "set_state", "apply_wrench", "apply_impulse", "clear_wrenches", "step", "pause",
                          "unpause", "reset"}) {
      ASSERT_TRUE(ros::service::waitForService(std::string("/sim_node/") + s, 30000)) << s;
    }
  }

  /// Calls sim_node's service `name` as a user's test should at these rates:
  /// on a persistent connection, one per service. ROS 1's connection per
  /// call loses about one call in 10⁵ in transport, from any server
  /// (bench/service_churn.sh, bench/HISTORY.md), which a test of thousands of calls
  /// meets now and then.
  template <class Srv>
  Srv call(const std::string& name, Srv srv) {
    EXPECT_TRUE(client<Srv>(name).call(srv)) << name;
    return srv;
  }

  bool trigger(const std::string& name) { return call(name, std_srvs::Trigger()).response.success; }

  BodyState state(const std::string& frame = "") {
    rigid_body_sim::GetState s;
    s.request.frame = frame;
    s = call("get_state", s);
    EXPECT_TRUE(s.response.success) << s.response.message;
    return s.response.state;
  }

  /// The message a latched MarkerArray topic holds (empty if none came in 10 s).
  visualization_msgs::MarkerArray latchedMarkers(const std::string& topic) {
    visualization_msgs::MarkerArray markers;
    bool got = false;
    const ros::Subscriber sub = nh_.subscribe<visualization_msgs::MarkerArray>(
        topic, 1, [&](const visualization_msgs::MarkerArray::ConstPtr& m) {
          markers = *m;
          got = true;
        });
    EXPECT_TRUE(spinUntil([&] { return got; }, 10.0)) << topic;  // latched: no need to wait for a change
    return markers;
  }

  rigid_body_sim::Step::Response step(int n) {
    rigid_body_sim::Step s;
    s.request.steps = n;
    return call("step", s).response;
  }

  rigid_body_sim::ApplyWrench::Response wrench(const std::string& frame, const geometry_msgs::Vector3& force,
                                               double duration, const geometry_msgs::Vector3& torque = vec(0, 0, 0)) {
    rigid_body_sim::ApplyWrench w;
    w.request.frame = frame;
    w.request.force = force;
    w.request.torque = torque;
    w.request.duration = ros::Duration(duration);
    return call("apply_wrench", w).response;
  }

  rigid_body_sim::ApplyImpulse::Response impulse(const std::string& frame, const geometry_msgs::Vector3& linear,
                                                 const geometry_msgs::Point& point = geometry_msgs::Point()) {
    rigid_body_sim::ApplyImpulse i;
    i.request.frame = frame;
    i.request.linear = linear;
    i.request.point = point;
    return call("apply_impulse", i).response;
  }

  ros::NodeHandle nh_;

 private:
  /// The persistent client of sim_node's service `name`, made again if its
  /// connection was lost.
  template <class Srv>
  ros::ServiceClient& client(const std::string& name) {
    ros::ServiceClient& c = clients_[name];
    if (!c.isValid()) c = nh_.serviceClient<Srv>("/sim_node/" + name, true);
    return c;
  }

  std::map<std::string, ros::ServiceClient> clients_;
};

}  // namespace rbs_test
