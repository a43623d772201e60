// ~body_states (issue 14): every body on one stamped topic, as a subscriber
// receives it, checked against each body's own odometry at the same stamp;
// and ~publish_tf false, which leaves the world → body transform to the user.
#include <nav_msgs/Odometry.h>
#include <tf2_msgs/TFMessage.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/BodyStates.h"

namespace rbs_test {
namespace {

using rigid_body_sim::BodyStates;

/// The three bodies of body_states*.test, in config order.
const std::vector<std::string> kNames = {"crate", "ball", "top"};

Eigen::Quaterniond quat(const geometry_msgs::Quaternion& q) { return {q.w, q.x, q.y, q.z}; }
Eigen::Vector3d eig(const geometry_msgs::Vector3& v) { return {v.x, v.y, v.z}; }

/// What a subscriber sees of ~body_states and of each body's odometry for
/// `seconds` of wall time (with the node running).
struct Received {
  std::vector<BodyStates> states;
  std::map<std::string, std::map<ros::Time, nav_msgs::Odometry>> odom;  ///< per body, by stamp
  std::vector<std::string> tf_children;                                 ///< child frames seen on /tf
};

Received receive(ros::NodeHandle& nh, double seconds) {
  Received r;
  std::vector<ros::Subscriber> subs;
  subs.push_back(nh.subscribe<BodyStates>("/sim_node/body_states", 1000,
                                          [&](const BodyStates::ConstPtr& m) { r.states.push_back(*m); }));
  for (const std::string& name : kNames) {
    subs.push_back(nh.subscribe<nav_msgs::Odometry>(
        "/" + name + "/odom", 1000,
        [&r, name](const nav_msgs::Odometry::ConstPtr& m) { r.odom[name][m->header.stamp] = *m; }));
  }
  subs.push_back(nh.subscribe<tf2_msgs::TFMessage>("/tf", 1000, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
    for (const auto& t : m->transforms) r.tf_children.push_back(t.child_frame_id);
  }));
  spinUntil([] { return false; }, seconds);
  return r;
}

class BodyStatesTopic : public Node {};

TEST_F(BodyStatesTopic, EveryBodyAtEachStampAsItsOdometrySaysIt) {
  const Received r = receive(nh_, 2.0);
  ASSERT_GT(r.states.size(), 50u);
  int matched = 0;
  for (std::size_t k = 0; k < r.states.size(); ++k) {
    const BodyStates& m = r.states[k];
    EXPECT_EQ(m.header.frame_id, "world");
    ASSERT_EQ(m.names, kNames);
    ASSERT_EQ(m.poses.size(), 3u);
    ASSERT_EQ(m.twists.size(), 3u);
    ASSERT_EQ(m.asleep.size(), 3u);
    EXPECT_EQ(m.twist_frames, (std::vector<std::string>{"crate/base_link", "ball/ball", "top/base_link"}));
    // 100 Hz of sim time: consecutive stamps 10 ms apart.
    if (k > 0) EXPECT_NEAR((m.header.stamp - r.states[k - 1].header.stamp).toSec(), 0.01, 1e-9) << k;
    for (std::size_t i = 0; i < kNames.size(); ++i) {
      const auto& by_stamp = r.odom.at(kNames[i]);
      const auto it = by_stamp.find(m.header.stamp);
      if (it == by_stamp.end()) continue;
      ++matched;
      // The same state as the body's own odometry: pose, and twist in its root link frame.
      EXPECT_EQ(m.poses[i], it->second.pose.pose) << kNames[i];
      EXPECT_EQ(m.twists[i], it->second.twist.twist) << kNames[i];
    }
  }
  EXPECT_GT(matched, 100);
  // The crate rests on the ground (asleep within the run); the top box falls, spinning.
  EXPECT_TRUE(r.states.back().asleep[0]);
  EXPECT_FALSE(r.states.back().asleep[2]);
  EXPECT_GT(std::abs(r.states.back().twists[2].angular.z), 0.5);
}

class BodyStatesWorld : public Node {};

TEST_F(BodyStatesWorld, TwistsInWorldAxesAtItsRateAndNoTfWhenTheUserOwnsIt) {
  const Received r = receive(nh_, 2.0);
  ASSERT_GT(r.states.size(), 20u);
  int matched = 0;
  for (std::size_t k = 0; k < r.states.size(); ++k) {
    const BodyStates& m = r.states[k];
    EXPECT_EQ(m.twist_frames, (std::vector<std::string>{"world", "world", "world"}));
    if (k > 0) EXPECT_NEAR((m.header.stamp - r.states[k - 1].header.stamp).toSec(), 0.02, 1e-9) << k;  // 50 Hz
    for (std::size_t i = 0; i < kNames.size(); ++i) {
      const auto& by_stamp = r.odom.at(kNames[i]);
      const auto it = by_stamp.find(m.header.stamp);
      if (it == by_stamp.end()) continue;
      ++matched;
      // Odometry's twist is in the body's frame: turned into the world's, it is this one.
      const Eigen::Quaterniond q = quat(it->second.pose.pose.orientation);
      EXPECT_LT((q * eig(it->second.twist.twist.linear) - eig(m.twists[i].linear)).norm(), 1e-12) << kNames[i];
      EXPECT_LT((q * eig(it->second.twist.twist.angular) - eig(m.twists[i].angular)).norm(), 1e-12) << kNames[i];
    }
  }
  EXPECT_GT(matched, 50);
  // ~publish_tf false: odometry flows, but no body's transform is on /tf.
  EXPECT_GT(r.odom.at("top").size(), 100u);
  for (const std::string& child : r.tf_children) {
    for (const std::string& name : kNames) EXPECT_NE(child.rfind(name + "/", 0), 0u) << child;
  }
}

}  // namespace
}  // namespace rbs_test
