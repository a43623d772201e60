// A robot in the node, as its users meet it: joint_states received, the tf
// robot_state_publisher makes of them, controllers commanded on their
// topics. pendulum.test runs the rod pendulum of urdf/pendulum.urdf
// released from 0.3 rad; arm.test the two-link arm of urdf/arm2.urdf under
// config/arm2.yaml's position controllers.
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Trigger.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "rigid_body_sim/ApplyJointEffort.h"
#include "rigid_body_sim/ClearJointForces.h"
#include "rigid_body_sim/GetJointProperties.h"
#include "rigid_body_sim/SetModelConfiguration.h"
#include "robot_fixture.h"

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

// apply_joint_effort acts for its duration (joint_states reports it as the
// effort applied, on the steps it covers), until cleared when the duration
// is negative; what it refuses changes nothing.
TEST_F(RodPendulum, ApplyJointEffortActsForItsDurationOrUntilCleared) {
  std::vector<sensor_msgs::JointState> got;
  const ros::Subscriber sub = nh_.subscribe<sensor_msgs::JointState>(
      "/joint_states", 10000, [&](const sensor_msgs::JointState::ConstPtr& m) { got.push_back(*m); });
  ASSERT_TRUE(spinUntil([&] { return !got.empty(); }, 30.0));
  rigid_body_sim::ApplyJointEffort e;
  e.request.joint_name = "pivot";
  e.request.effort = 0.7;
  // A second ahead: the request must arrive before its start (one that
  // starts in the past acts from its arrival).
  e.request.start_time = got.back().header.stamp + ros::Duration(1.0);
  e.request.duration = ros::Duration(0.5);
  e = call("apply_joint_effort", e);
  ASSERT_TRUE(e.response.success) << e.response.status_message;
  const double start = e.request.start_time.toSec();
  ASSERT_TRUE(spinUntil([&] { return got.back().header.stamp.toSec() > start + 1.0; }, 30.0));
  // Each joint_states reports the effort of the step just before its stamp.
  for (const sensor_msgs::JointState& m : got) {
    const double t = m.header.stamp.toSec();
    if (t <= start - 1e-9 || (t > start + 1e-9 && t < start + 0.5 - 1e-9) || t > start + 0.5 + 1e-9) {
      // (a step's share is its overlap over h, to rounding)
      EXPECT_NEAR(m.effort[0], (t > start && t < start + 0.5) ? 0.7 : 0.0, 1e-12) << "at t = " << t;
    }
  }
  // Until cleared, then nothing.
  e.request.start_time = ros::Time(0);
  e.request.duration = ros::Duration(-1.0);
  ASSERT_TRUE(call("apply_joint_effort", e).response.success);
  // (messages published before the answer may still be on their way: the
  // effort is waited for, then must stay, in 30 messages and more)
  const auto from = [&](double effort, const std::string& what) {
    ASSERT_TRUE(spinUntil([&] { return std::abs(got.back().effort[0] - effort) < 1e-12; }, 30.0)) << what;
    const std::size_t on = got.size();
    ASSERT_TRUE(spinUntil([&] { return got.size() > on + 30; }, 30.0));
    for (std::size_t k = on; k < got.size(); ++k) {
      EXPECT_NEAR(got[k].effort[0], effort, 1e-12) << what << ", at t = " << got[k].header.stamp.toSec();
    }
  };
  from(0.7, "the effort until cleared");
  rigid_body_sim::ClearJointForces clear;
  clear.request.joint_name = "pendulum/pivot";
  clear = call("clear_joint_forces", clear);
  ASSERT_TRUE(clear.response.success) << clear.response.status_message;
  EXPECT_EQ(clear.response.status_message, "1 efforts on joint 'pivot' cleared");
  from(0.0, "no effort once cleared");
  // Refused: NaN, duration 0, an unknown joint.
  const struct {
    std::string joint;
    double effort, duration;
    std::string expected;
  } bad[] = {{"pivot", std::nan(""), 1.0, "effort: nan"},
             {"pivot", 1.0, 0.0, "duration 0 applies nothing"},
             {"hinge", 1.0, 1.0, "joint_name: no robot has a moving joint 'hinge'"}};
  for (const auto& b : bad) {
    rigid_body_sim::ApplyJointEffort r;
    r.request.joint_name = b.joint;
    r.request.effort = b.effort;
    r.request.duration = ros::Duration(b.duration);
    r = call("apply_joint_effort", r);
    EXPECT_FALSE(r.response.success);
    EXPECT_NE(r.response.status_message.find(b.expected), std::string::npos) << r.response.status_message;
  }
  const std::size_t after = got.size();
  ASSERT_TRUE(spinUntil([&] { return got.size() > after + 20; }, 30.0));
  EXPECT_EQ(got.back().effort[0], 0.0);
}

// ------------------------------------------------------------------ the arm under position controllers

/// The efforts that hold urdf/arm2.urdf still at (q1, q2) against gravity:
/// each link a bar of mass m and length l = 0.4 m along d(q) = (cos q, 0,
/// −sin q), so V = −g [m1 (l/2) sin q1 + m2 (l sin q1 + (l/2) sin(q1 + q2))]
/// and the holding effort is ∂V/∂q.
std::pair<double, double> holdingEfforts(double q1, double q2) {
  const double m1 = 1.5, m2 = 1.0, l = 0.4;
  const double e2 = -kG * m2 * 0.5 * l * std::cos(q1 + q2);
  const double e1 = -kG * (m1 * 0.5 * l * std::cos(q1) + m2 * l * std::cos(q1)) + e2;
  return {e1, e2};
}

class Arm : public RobotNode {
 protected:
  void SetUp() override {
    Node::SetUp();
    start("/shoulder_position_controller/command", "/elbow_position_controller/command");
    ASSERT_EQ(last_.name, (std::vector<std::string>{"shoulder", "elbow"}));
  }
};

// Held at its targets against gravity, within 0.01 rad, by the efforts
// gravity needs there (within the URDF's 40 and 20 N·m); a NaN command and
// a command of the wrong kind change nothing; after a reset the
// controllers hold the start, not the old targets (gazebo_ros_pkgs #1311).
TEST_F(Arm, PositionControllersHoldTargetsAgainstGravity) {
  command(-0.5, 0.8);
  wait(6.0);
  EXPECT_NEAR(last_.position[0], -0.5, 0.01);
  EXPECT_NEAR(last_.position[1], 0.8, 0.01);
  const auto [e1, e2] = holdingEfforts(last_.position[0], last_.position[1]);
  EXPECT_NEAR(last_.effort[0], e1, 0.01 * std::abs(e1)) << "shoulder";
  EXPECT_NEAR(last_.effort[1], e2, 0.01 * std::abs(e2)) << "elbow";
  EXPECT_LE(std::abs(last_.effort[0]), 40.0);
  EXPECT_LE(std::abs(last_.effort[1]), 20.0);
  std::printf("arm held at (%.5f, %.5f) rad for (-0.5, 0.8); efforts (%.4f, %.4f) N m, gravity's (%.4f, %.4f)\n",
              last_.position[0], last_.position[1], last_.effort[0], last_.effort[1], e1, e2);

  command(std::nan(""), 0.8);  // dropped with a warning
  wait(1.0);
  EXPECT_NEAR(last_.position[0], -0.5, 0.01);
  EXPECT_NEAR(last_.position[1], 0.8, 0.01);

  ASSERT_TRUE(trigger("reset"));
  wait(4.0);
  EXPECT_NEAR(last_.position[0], 0.0, 0.01) << "the controllers drove the reset arm back to their old targets";
  EXPECT_NEAR(last_.position[1], 0.0, 0.01);
}

// joint_command (an Isaac Sim style JointState) sets the named joints'
// targets from the field their controllers take; a message naming an
// unknown joint, or giving a position controller a velocity, is dropped
// whole.
TEST_F(Arm, JointCommandSetsTheNamedJoints) {
  ros::Publisher joint_command = nh_.advertise<sensor_msgs::JointState>("/joint_command", 1, true);
  ASSERT_TRUE(spinUntil([&] { return joint_command.getNumSubscribers() > 0; }, 10.0));
  sensor_msgs::JointState m;
  m.name = {"elbow"};
  m.position = {0.6};
  joint_command.publish(m);
  wait(4.0);
  EXPECT_NEAR(last_.position[1], 0.6, 0.01);
  const double shoulder = last_.position[0];
  for (const auto& [names, position, velocity] :
       {std::tuple<std::vector<std::string>, std::vector<double>, std::vector<double>>{
            {"elbow", "wrist"}, {0.0, 0.0}, {}},
        {{"elbow"}, {}, {1.0}},
        {{"elbow"}, {0.1, 0.2}, {}}}) {
    sensor_msgs::JointState bad;
    bad.name = names;
    bad.position = position;
    bad.velocity = velocity;
    joint_command.publish(bad);
  }
  wait(1.0);
  EXPECT_NEAR(last_.position[1], 0.6, 0.01);
  EXPECT_NEAR(last_.position[0], shoulder, 0.01);
}

// A flood of bad commands is warned about at most once a second: each
// dropped message logged its own warning (issue 45: 52,000 lines, a 26 MB
// rosout.log in 9 s). 2,000 messages naming a joint the arm does not have,
// over about 2 s, as the node's /rosout carries them.
TEST_F(Arm, AFloodOfBadCommandsIsWarnedAtMostOnceASecond) {
  int warnings = 0;
  const ros::Subscriber logs =
      nh_.subscribe<rosgraph_msgs::Log>("/rosout", 10000, [&](const rosgraph_msgs::Log::ConstPtr& m) {
        if (m->msg.find("joint_command dropped") != std::string::npos) ++warnings;
      });
  ros::Publisher joint_command = nh_.advertise<sensor_msgs::JointState>("/joint_command", 1000);
  ASSERT_TRUE(spinUntil([&] { return joint_command.getNumSubscribers() > 0 && logs.getNumPublishers() > 0; }, 10.0));
  sensor_msgs::JointState bad;
  bad.name = {"wrist"};
  bad.position = {0.0};
  for (int k = 0; k < 2000; ++k) {
    joint_command.publish(bad);
    if (k % 100 == 99) wait(0.1);
  }
  wait(1.5);
  EXPECT_GE(warnings, 1) << "a bad command is still said";
  EXPECT_LE(warnings, 5) << "2 s of flood, once a second, and the edges";
}

// A target past the URDF's range is held to it (warned once).
TEST_F(Arm, TargetsPastTheRangeAreHeldToIt) {
  command(0.0, 3.0);  // the elbow's upper limit is 2.5
  wait(5.0);
  EXPECT_NEAR(last_.position[1], 2.5, 0.01);
  EXPECT_NEAR(last_.position[0], 0.0, 0.01);
}

// set_model_configuration puts the arm there with its velocities, the
// controllers hold it there (not at their old targets), and what it
// refuses changes nothing; get_joint_properties reads the joint back.
TEST_F(Arm, SetModelConfigurationPlacesTheJointsAndTheControllersStay) {
  command(-0.5, 0.8);
  wait(3.0);
  rigid_body_sim::SetModelConfiguration set;
  set.request.model_name = "arm2";
  set.request.joint_names = {"elbow", "shoulder"};
  set.request.joint_positions = {-0.3, 0.4};
  set.request.joint_velocities = {0.0, 0.5};
  set = call("set_model_configuration", set);
  ASSERT_TRUE(set.response.success) << set.response.status_message;
  // The first joint_states after it: where it was put, at its velocities.
  const double put_at = last_.header.stamp.toSec();
  ASSERT_TRUE(spinUntil([&] { return last_.header.stamp.toSec() >= put_at; }, 10.0));
  rigid_body_sim::GetJointProperties props;
  props.request.joint_name = "shoulder";
  props = call("get_joint_properties", props);
  ASSERT_TRUE(props.response.success) << props.response.status_message;
  EXPECT_EQ(props.response.type, rigid_body_sim::GetJointProperties::Response::REVOLUTE);
  EXPECT_EQ(props.response.damping, std::vector<double>{0.1});
  wait(4.0);
  // The shoulder was set moving at 0.5 rad/s: the controller brings it back
  // to where it was put and holds it there, not at -0.5.
  EXPECT_NEAR(last_.position[0], 0.4, 0.02);
  EXPECT_NEAR(last_.position[1], -0.3, 0.01);

  const struct {
    std::vector<std::string> names;
    std::vector<double> positions, velocities;
    std::string expected;
  } bad[] = {
      {{"elbow"}, {3.0}, {}, "joint_positions[0]: joint 'elbow' = 3 is outside its limits [-2.5, 2.5]"},
      {{"wrist"}, {0.0}, {}, "joint_names[0]: robot 'arm2' has no moving joint 'wrist'"},
      {{"elbow"}, {std::nan("")}, {}, "joint_positions[0]: joint 'elbow' = nan"},
      {{"elbow"}, {0.1}, {9.0}, "joint_velocities[0]: joint 'elbow' = 9 is faster than its velocity limit 4"},
      {{"elbow", "shoulder"}, {0.1}, {}, "joint_positions: 1 values for 2 joint_names"},
      {{"elbow", "elbow"}, {0.1, 0.2}, {}, "joint_names[1]: joint 'elbow' is named twice"},
  };
  for (const auto& b : bad) {
    rigid_body_sim::SetModelConfiguration s;
    s.request.joint_names = b.names;
    s.request.joint_positions = b.positions;
    s.request.joint_velocities = b.velocities;
    s = call("set_model_configuration", s);
    EXPECT_FALSE(s.response.success) << b.expected;
    EXPECT_NE(s.response.status_message.find(b.expected), std::string::npos) << s.response.status_message;
  }
  wait(0.5);  // still held where it was put: a refused request moved nothing, nor any target
  EXPECT_NEAR(last_.position[0], 0.4, 0.01);
  EXPECT_NEAR(last_.position[1], -0.3, 0.01);
  rigid_body_sim::GetJointProperties unknown;
  unknown.request.joint_name = "knee";
  unknown = call("get_joint_properties", unknown);
  EXPECT_FALSE(unknown.response.success);
  EXPECT_NE(unknown.response.status_message.find("joint_name: no robot has a moving joint 'knee'"), std::string::npos)
      << unknown.response.status_message;
}

// launch/sim.launch as a user runs it on their own robot, with no config
// (sim_launch.test, the arm): it used to stop with FATAL for every robot
// fixed to the world, the box demo's spinning start refused.
class SimLaunch : public rbs_test::RobotNode {};

TEST_F(SimLaunch, RunsAWorldFixedRobotWithNoConfig) {
  listen();
  ASSERT_EQ(last_.name, (std::vector<std::string>{"shoulder", "elbow"}));
  const double start = last_.header.stamp.toSec();
  wait(1.0);
  // It hangs from the world and falls from its horizontal start, finite.
  EXPECT_GT(last_.header.stamp.toSec(), start + 0.99);
  EXPECT_GT(last_.position[0], 0.1);  // about y: the upper arm, along x at the start, swings down
  for (const double x : last_.position) EXPECT_TRUE(std::isfinite(x));
}

}  // namespace
