// A wheeled base under ros_controllers' DiffDriveController in the node:
// urdf/diff_drive.urdf under config/diff_drive_controller.yaml
// (base_controller.test). What a subscriber receives: the odometry on
// /base_controller/odom and odom -> base_link on tf, against the ground
// truth on ~body_states, while geometry_msgs/Twist commands arrive on
// /base_controller/cmd_vel; and the base's own odometry (odom_noise):
// /ground_truth exact, /odom scattered about it.
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/BodyStates.h"

namespace {

using namespace rbs_test;

double yawOf(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

class BaseController : public Node {
 protected:
  void SetUp() override {
    Node::SetUp();
    odom_sub_ = nh_.subscribe<nav_msgs::Odometry>(
        "/base_controller/odom", 1000, [this](const nav_msgs::Odometry::ConstPtr& m) { odom_.push_back(*m); });
    truth_sub_ = nh_.subscribe<rigid_body_sim::BodyStates>(
        "/sim_node/body_states", 1000, [this](const rigid_body_sim::BodyStates::ConstPtr& m) { truth_.push_back(*m); });
    tf_sub_ = nh_.subscribe<tf2_msgs::TFMessage>("/tf", 1000, [this](const tf2_msgs::TFMessage::ConstPtr& m) {
      for (const auto& t : m->transforms) {
        if (t.child_frame_id == "base_link") base_parents_.push_back(t.header.frame_id);
      }
    });
    ground_truth_sub_ = nh_.subscribe<nav_msgs::Odometry>(
        "/ground_truth", 1000, [this](const nav_msgs::Odometry::ConstPtr& m) { ground_truth_.push_back(*m); });
    noisy_sub_ = nh_.subscribe<nav_msgs::Odometry>(
        "/odom", 1000, [this](const nav_msgs::Odometry::ConstPtr& m) { noisy_.push_back(*m); });
    cmd_vel_ = nh_.advertise<geometry_msgs::Twist>("/base_controller/cmd_vel", 10);
    ASSERT_TRUE(spinUntil([&] { return !odom_.empty() && !truth_.empty(); }, 30.0));
    ASSERT_TRUE(spinUntil([&] { return cmd_vel_.getNumSubscribers() > 0; }, 30.0));  // the controller listens
  }

  /// Sends (v, ω) every 20 ms of wall time (the test sets the timeout to 2 s of sim time, 0.5 s of wall time at 4×) for
  /// `seconds` of sim time.
  void drive(double v, double w, double seconds) {
    geometry_msgs::Twist twist;
    twist.linear.x = v;
    twist.angular.z = w;
    const double until = simNow(odom_.back().header.stamp.toSec()) + seconds;
    while (ros::ok() && odom_.back().header.stamp.toSec() < until) {
      cmd_vel_.publish(twist);
      spinUntil([] { return false; }, 0.02);
    }
  }

  std::vector<nav_msgs::Odometry> odom_, ground_truth_, noisy_;
  std::vector<rigid_body_sim::BodyStates> truth_;
  std::vector<std::string> base_parents_;

 private:
  ros::Subscriber odom_sub_, truth_sub_, tf_sub_, ground_truth_sub_, noisy_sub_;
  ros::Publisher cmd_vel_;
};

/// The means of the truth's forward speed and yaw rate (in the base's axes) over its last `span` s.
void truthOver(const std::vector<rigid_body_sim::BodyStates>& truth, double span, double& v, double& w) {
  const double end = truth.back().header.stamp.toSec();
  v = w = 0.0;
  int n = 0;
  for (const rigid_body_sim::BodyStates& s : truth) {
    if (end - s.header.stamp.toSec() > span) continue;
    v += s.twists.at(0).linear.x;
    w += s.twists.at(0).angular.z;
    ++n;
  }
  v /= n;
  w /= n;
}

// Commanded 0.5 m/s and 0.3 rad/s, within its acceleration limits: the base
// drives at them within 3 % (the bound; 1 %: the rims bear on their
// outer edges in a turn, docs/physics.md §11.12), and so does its odometry,
// whose pose follows the truth from where the base started.
TEST_F(BaseController, DrivesAtTheCommandedTwistAndItsOdometryFollowsTheTruth) {
  drive(0.5, 0.3, 4.0);
  ASSERT_EQ(truth_.back().names.at(0), "diff_drive");
  EXPECT_EQ(truth_.back().twist_frames.at(0), "base_link");
  double v = 0.0, w = 0.0;
  truthOver(truth_, 1.5, v, w);
  EXPECT_NEAR(v, 0.5, 0.03 * 0.5);
  EXPECT_NEAR(w, 0.3, 0.03 * 0.3);
  // The latest odometry a body_states shares a stamp with (each topic has
  // its own connection, and either may lag the other by a message).
  const rigid_body_sim::BodyStates* at = nullptr;
  auto last = odom_.rbegin();
  for (; last != odom_.rend() && at == nullptr; ++last) {
    for (const rigid_body_sim::BodyStates& s : truth_) {
      if (s.header.stamp == last->header.stamp) at = &s;
    }
  }
  ASSERT_NE(at, nullptr) << "no body_states stamped as an odometry";
  const nav_msgs::Odometry& o = *std::prev(last);
  EXPECT_EQ(o.header.frame_id, "odom");
  EXPECT_EQ(o.child_frame_id, "base_link");
  EXPECT_NEAR(o.twist.twist.linear.x, 0.5, 0.03 * 0.5);
  EXPECT_NEAR(o.twist.twist.angular.z, 0.3, 0.03 * 0.3);
  EXPECT_EQ(o.pose.covariance[0], 0.001);
  EXPECT_EQ(o.pose.covariance[35], 0.03);
  EXPECT_EQ(o.twist.covariance[14], 1e6);
  // The truth at the odometry's stamp, against the odometry (the base started at the world's origin, facing x).
  const geometry_msgs::Pose& truth = at->poses.at(0);
  const double travelled = std::hypot(truth.position.x, truth.position.y);
  EXPECT_GT(travelled, 1.0);
  EXPECT_NEAR(o.pose.pose.position.x, truth.position.x, 0.03 * travelled);
  EXPECT_NEAR(o.pose.pose.position.y, truth.position.y, 0.03 * travelled);
  EXPECT_NEAR(std::remainder(yawOf(o.pose.pose.orientation) - yawOf(truth.orientation), 2.0 * M_PI), 0.0, 0.01);
  std::printf(
      "base_controller: truth v %.4f m/s, w %.4f rad/s; odometry v %.4f, w %.4f; pose (%.4f, %.4f) against "
      "(%.4f, %.4f)\n",
      v, w, o.twist.twist.linear.x, o.twist.twist.angular.z, o.pose.pose.position.x, o.pose.pose.position.y,
      truth.position.x, truth.position.y);
  // tf has base_link under odom alone: the node leaves world -> base_link to the odometry.
  ASSERT_FALSE(base_parents_.empty());
  for (const std::string& parent : base_parents_) EXPECT_EQ(parent, "odom");
}

// No command for longer than cmd_vel_timeout: the base brakes to a stop.
TEST_F(BaseController, StopsWhenTheCommandsStop) {
  drive(0.5, 0.0, 1.5);
  ASSERT_GT(odom_.back().twist.twist.linear.x, 0.4);
  const double sent = odom_.back().header.stamp.toSec();
  ASSERT_TRUE(spinUntil([&] { return odom_.back().header.stamp.toSec() > sent + 5.0; },
                        30.0));  // 2 s timeout, 0.5 s braking, late commands
  EXPECT_NEAR(odom_.back().twist.twist.linear.x, 0.0, 0.01);
  double v = 0.0, w = 0.0;
  truthOver(truth_, 0.5, v, w);
  EXPECT_NEAR(v, 0.0, 0.01);
}

// The base's own odometry (odom_noise on a robot, as on a body): the exact
// pose and twist on /ground_truth, the twist in the base's axes as
// nav_msgs/Odometry says; /odom the same with 1 cm of noise on the position.
TEST_F(BaseController, ItsBaseOdometryIsTheTruthAndItsNoisyOdomScattersAboutIt) {
  drive(0.5, 0.3, 2.0);
  ASSERT_FALSE(ground_truth_.empty());
  ASSERT_FALSE(noisy_.empty());
  // The latest stamp all three topics carry: each comes on its own
  // connection with a queue of 10, so under a sanitizer's stalls one may
  // lag or drop the newest (CI at 7f2e477 found no /odom at the newest).
  const nav_msgs::Odometry* exact = nullptr;
  const nav_msgs::Odometry* noisy = nullptr;
  const rigid_body_sim::BodyStates* at = nullptr;
  for (auto g = ground_truth_.rbegin(); g != ground_truth_.rend() && noisy == nullptr; ++g) {
    at = nullptr;
    for (const rigid_body_sim::BodyStates& s : truth_) {
      if (s.header.stamp == g->header.stamp) at = &s;
    }
    if (at == nullptr) continue;
    for (const nav_msgs::Odometry& n : noisy_) {
      if (n.header.stamp == g->header.stamp) noisy = &n, exact = &*g;
    }
  }
  ASSERT_NE(noisy, nullptr) << "no ground_truth stamped as both a body_states and an /odom";
  EXPECT_EQ(exact->header.frame_id, at->header.frame_id);  // the world frame
  EXPECT_EQ(exact->child_frame_id, "base_link");
  EXPECT_NEAR(exact->pose.pose.position.x, at->poses.at(0).position.x, 1e-9);
  EXPECT_NEAR(exact->pose.pose.position.y, at->poses.at(0).position.y, 1e-9);
  EXPECT_NEAR(yawOf(exact->pose.pose.orientation), yawOf(at->poses.at(0).orientation), 1e-9);
  EXPECT_NEAR(exact->twist.twist.linear.x, at->twists.at(0).linear.x, 1e-9);  // both in base_link's axes
  EXPECT_NEAR(exact->twist.twist.angular.z, at->twists.at(0).angular.z, 1e-9);
  EXPECT_GT(exact->twist.twist.linear.x, 0.4);
  const double off = std::hypot(noisy->pose.pose.position.x - exact->pose.pose.position.x,
                                noisy->pose.pose.position.y - exact->pose.pose.position.y);
  EXPECT_GT(off, 1e-6);  // σ = 1 cm per axis
  EXPECT_LT(off, 0.06);
  EXPECT_NEAR(noisy->pose.covariance[0], 1e-4, 1e-12);
  EXPECT_EQ(noisy->twist.twist.linear.x, exact->twist.twist.linear.x);  // no twist noise asked
}

}  // namespace
