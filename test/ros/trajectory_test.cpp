// The two-link arm under config/arm2_trajectory.yaml's trajectory
// controller, as a subscriber of joint_states sees it: the arm is at each
// waypoint at its time; bad trajectories change nothing; an empty one
// stops the arm where it is; a reset ends the trajectory.
#include <gtest/gtest.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "robot_fixture.h"

namespace rbs_test {
namespace {

trajectory_msgs::JointTrajectoryPoint point(double time, std::vector<double> q, std::vector<double> v = {}) {
  trajectory_msgs::JointTrajectoryPoint p;
  p.time_from_start = ros::Duration(time);
  p.positions = std::move(q);
  p.velocities = std::move(v);
  return p;
}

class ArmTrajectory : public RobotNode {
 protected:
  void SetUp() override {
    Node::SetUp();
    trajectories_ = nh_.advertise<trajectory_msgs::JointTrajectory>("/arm_controller/command", 1, true);
    joint_command_ = nh_.advertise<sensor_msgs::JointState>("/joint_command", 1, true);
    listen();
    ASSERT_EQ(last_.name, (std::vector<std::string>{"shoulder", "elbow"}));
    // Each test from the start (the suites share one node), the hold
    // settled: gravity sags the arm until the integral takes the error away.
    ASSERT_TRUE(trigger("reset"));
    wait(3.0);
    seen_.clear();
  }
  /// Sends points for (shoulder, elbow), from `stamp` (0: now).
  void send(std::vector<trajectory_msgs::JointTrajectoryPoint> points, ros::Time stamp = ros::Time(),
            std::vector<std::string> names = {"shoulder", "elbow"}) {
    trajectory_msgs::JointTrajectory t;
    t.header.stamp = stamp;
    t.joint_names = std::move(names);
    t.points = std::move(points);
    trajectories_.publish(t);
  }
  /// The joint_states stamped `t` (s of the node's clock), or nullptr.
  const sensor_msgs::JointState* at(double t) const {
    for (const sensor_msgs::JointState& m : seen_) {
      if (std::abs(m.header.stamp.toSec() - t) < 1e-6) return &m;
    }
    return nullptr;
  }
  /// Expects the arm near (q1, q2), within `tol` rad.
  void expectAt(double q1, double q2, double tol, const std::string& why) {
    EXPECT_NEAR(last_.position[0], q1, tol) << why;
    EXPECT_NEAR(last_.position[1], q2, tol) << why;
  }
  ros::Publisher trajectories_, joint_command_;
};

// Three waypoints (the first with velocities: cubic, then linear pieces)
// from a stamp half a second ahead: at each point's time, joint_states
// stamped then has the arm there within 0.01 rad, against gravity.
TEST_F(ArmTrajectory, ReachesItsPointsAtTheirTimes) {
  const ros::Time start = last_.header.stamp + ros::Duration(0.5);
  const std::vector<trajectory_msgs::JointTrajectoryPoint> points{
      point(1.0, {-0.3, 0.5}, {-0.3, 0.2}), point(2.0, {-0.6, 0.9}, {0.0, 0.0}), point(3.0, {-0.2, 0.3})};
  send(points, start);
  wait(5.0);
  for (const trajectory_msgs::JointTrajectoryPoint& p : points) {
    const double t = (start + p.time_from_start).toSec();
    const sensor_msgs::JointState* m = at(t);
    ASSERT_NE(m, nullptr) << "no joint_states stamped " << t;
    EXPECT_NEAR(m->position[0], p.positions[0], 0.01) << "shoulder at " << p.time_from_start.toSec() << " s";
    EXPECT_NEAR(m->position[1], p.positions[1], 0.01) << "elbow at " << p.time_from_start.toSec() << " s";
    EXPECT_LE(std::abs(m->effort[0]), 40.0);
    EXPECT_LE(std::abs(m->effort[1]), 20.0);
    std::printf("trajectory point at %.1f s: (%.5f, %.5f) rad for (%.2f, %.2f)\n", p.time_from_start.toSec(),
                m->position[0], m->position[1], p.positions[0], p.positions[1]);
  }
  // Before the start it held where it was (the start: 0, 0).
  const sensor_msgs::JointState* before = at(start.toSec() - 0.1);
  ASSERT_NE(before, nullptr);
  EXPECT_NEAR(before->position[0], 0.0, 0.01);
  EXPECT_NEAR(before->position[1], 0.0, 0.01);
  expectAt(-0.2, 0.3, 0.005, "held at the last point");
}

// A trajectory naming a joint it does not have, with a NaN, with times
// going back, or for one joint only, is dropped whole; so is a
// joint_command for its joints. The arm stays held at the start.
TEST_F(ArmTrajectory, BadTrajectoriesChangeNothing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  send({point(1.0, {0.5, 0.5})}, ros::Time(), {"shoulder", "wrist"});
  wait(0.2);
  send({point(1.0, {0.5, nan})});
  wait(0.2);
  send({point(1.0, {0.5, 0.5}), point(0.5, {0.2, 0.2})});
  wait(0.2);
  send({point(1.0, {0.5})}, ros::Time(), {"shoulder"});
  wait(0.2);
  send({point(1.0, {0.5, 0.5})}, ros::Time(1e9));  // another clock's stamp
  sensor_msgs::JointState js;
  js.name = {"shoulder"};
  js.position = {0.5};
  joint_command_.publish(js);
  wait(2.0);
  expectAt(0.0, 0.0, 0.01, "a bad trajectory moved the arm");
}

// An empty trajectory stops the arm where it is; a reset ends a trajectory
// and the controller holds the reset arm (gazebo_ros_pkgs #1311).
TEST_F(ArmTrajectory, AnEmptyTrajectoryStopsAndAResetEndsIt) {
  // It stops where it is when the empty trajectory arrives, some time after
  // it is sent: it must have passed where it was when sent, stop well short
  // of the end, and stay.
  send({point(4.0, {0.8, -0.8})});
  wait(1.0);
  const double q1 = last_.position[0];
  ASSERT_GT(q1, 0.1) << "not under way";
  send({});
  wait(1.5);
  const double held1 = last_.position[0], held2 = last_.position[1];
  EXPECT_GT(held1, q1 - 0.02) << "went back";
  EXPECT_LT(held1, 0.7) << "went on to the old trajectory's end";
  EXPECT_NEAR(held2, -held1, 0.05) << "the joints did not stop together";
  wait(1.5);
  std::printf("stopped at (%.5f, %.5f) rad, sent at %.5f; 1.5 s later (%.5f, %.5f)\n", held1, held2, q1,
              last_.position[0], last_.position[1]);
  expectAt(held1, held2, 0.01, "did not stay where it stopped");

  send({point(3.0, {0.8, 0.8})});
  wait(1.0);
  ASSERT_TRUE(trigger("reset"));
  wait(4.0);
  expectAt(0.0, 0.0, 0.01, "the trajectory went on after the reset");
}

}  // namespace
}  // namespace rbs_test
