// A robot in the node, as its users meet it: joint_states received, and the
// tf robot_state_publisher makes of them. pendulum.test runs the rod
// pendulum of urdf/pendulum.urdf released from 0.3 rad.
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "node_fixture.h"

namespace {

using namespace rbs_test;

/// The arithmetic-geometric mean: K(k) = π / (2 agm(1, √(1 − k²))).
double agm(double a, double b) {
  for (int i = 0; i < 40; ++i) {
    const double m = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = m;
  }
  return a;
}

/// The rod pendulum's period from amplitude θ0: 1 kg, 0.5 m rod about its
/// end, I = m l² / 3, its centre d = l / 2 below the pivot.
/// T = 2π √(I / (m g d)) / agm(1, cos(θ0 / 2)), the exact period of a pendulum.
double rodPeriod(double theta0) {
  const double m = 1.0, l = 0.5, I = m * l * l / 3.0, d = 0.5 * l;
  return 2.0 * M_PI * std::sqrt(I / (m * kG * d)) / agm(1.0, std::cos(0.5 * theta0));
}

struct Sample {
  double t, q, v;
};

class RodPendulum : public Node {
 protected:
  /// joint_states for `seconds` of sim time (its stamps are sim time).
  std::vector<Sample> record(double seconds) {
    std::vector<Sample> samples;
    bool names_ok = true;
    const ros::Subscriber sub =
        nh_.subscribe<sensor_msgs::JointState>("/joint_states", 10000, [&](const sensor_msgs::JointState::ConstPtr& m) {
          names_ok = names_ok && m->name == std::vector<std::string>{"pivot"} && m->position.size() == 1 &&
                     m->velocity.size() == 1 && m->effort == std::vector<double>{0.0};
          if (m->position.size() == 1 && m->velocity.size() == 1)
            samples.push_back({m->header.stamp.toSec(), m->position[0], m->velocity[0]});
        });
    spinUntil([&] { return samples.size() > 1 && samples.back().t - samples.front().t >= seconds; }, 60.0);
    EXPECT_TRUE(names_ok) << "a joint_states message named other joints, or lacked a field";
    return samples;
  }
};

// The period from the times q crosses 0 going down (interpolated between the
// two samples around it, where q is nearly linear), over ten periods.
TEST_F(RodPendulum, JointStatesGiveTheClosedFormPeriod) {
  const std::vector<Sample> s = record(13.0);
  std::vector<double> crossings;
  for (std::size_t i = 1; i < s.size(); ++i) {
    ASSERT_GT(s[i].t, s[i - 1].t) << "stamps go forward";
    if (s[i - 1].q > 0.0 && s[i].q <= 0.0) {
      crossings.push_back(s[i - 1].t + (s[i].t - s[i - 1].t) * s[i - 1].q / (s[i - 1].q - s[i].q));
    }
  }
  ASSERT_GE(crossings.size(), 11u);
  const double measured = (crossings[10] - crossings[0]) / 10.0;
  const double expected = rodPeriod(0.3);
  std::printf("rod pendulum from 0.3 rad: period %.6f s from joint_states, %.6f s closed form\n", measured, expected);
  EXPECT_NEAR(measured, expected, 0.002 * expected)
      << "measured " << measured << " s, closed form " << expected << " s";
  // The amplitude stays 0.3 rad (the step keeps the energy).
  double top = 0.0;
  for (const Sample& x : s) top = std::max(top, x.q);
  EXPECT_NEAR(top, 0.3, 1e-3);
}

// robot_state_publisher's tf of the rod (on /tf, stamped as the
// joint_states it came from; it skips some, at its publish_frequency) is the
// rotation by that message's angle about y.
TEST_F(RodPendulum, RobotStatePublisherTfFollowsTheJointStates) {
  std::map<double, double> angle_at;  // joint_states: stamp -> q
  std::vector<geometry_msgs::TransformStamped> rods;
  const ros::Subscriber joints =
      nh_.subscribe<sensor_msgs::JointState>("/joint_states", 1000, [&](const sensor_msgs::JointState::ConstPtr& m) {
        if (m->position.size() == 1) angle_at[m->header.stamp.toSec()] = m->position[0];
      });
  const ros::Subscriber tf =
      nh_.subscribe<tf2_msgs::TFMessage>("/tf", 1000, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
        for (const auto& t : m->transforms) {
          if (t.child_frame_id == "rod") rods.push_back(t);
        }
      });
  ASSERT_TRUE(spinUntil([&] { return rods.size() >= 20; }, 30.0));
  int matched = 0;
  for (const geometry_msgs::TransformStamped& t : rods) {
    const auto q = angle_at.find(t.header.stamp.toSec());
    if (q == angle_at.end()) continue;  // its joint_states came before we subscribed
    EXPECT_EQ(t.header.frame_id, "world");
    const auto& r = t.transform.rotation;
    EXPECT_NEAR(r.x, 0.0, 1e-12);
    EXPECT_NEAR(r.z, 0.0, 1e-12);
    EXPECT_NEAR(2.0 * std::atan2(r.y, r.w), q->second, 1e-9);  // a rotation about y by q
    EXPECT_NEAR(t.transform.translation.z, 1.0, 1e-12);        // the pivot
    ++matched;
  }
  EXPECT_GE(matched, 15);
}

}  // namespace
