// World edits beside a robot (trajectory.test's node: the two-link arm):
// a body spawned with ~spawn_body falls and lands while the arm's
// joint_states go on; a name a robot has is refused; the body is deleted
// again. A robot spawned with its joints set (spawn_model's -J) publishes
// NAME/joint_states from there and swings; one whose links' frames another
// robot has is refused.
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/JointState.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rigid_body_sim/Contacts.h"
#include "rigid_body_sim/DeleteBody.h"
#include "rigid_body_sim/GetJointProperties.h"
#include "rigid_body_sim/SpawnBody.h"
#include "robot_fixture.h"

namespace rbs_test {
namespace {

using rigid_body_sim::SpawnBody;

class ArmEdits : public RobotNode {
 protected:
  void SetUp() override {
    Node::SetUp();
    listen();
  }
  SpawnBody::Response spawn(const std::string& name, const std::string& urdf) {
    SpawnBody s;
    s.request.name = name;
    s.request.urdf_file = "package://rigid_body_sim/urdf/" + urdf;
    s.request.pose.position.x = 1.5;
    s.request.pose.position.z = 0.5;
    s.request.pose.orientation.w = 1.0;
    EXPECT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
    return call("spawn_body", s).response;
  }
};

TEST_F(ArmEdits, ABodySpawnsBesideTheArmAndIsDeleted) {
  nav_msgs::Odometry crate;
  rigid_body_sim::Contacts contacts;
  ros::Subscriber odom =
      nh_.subscribe<nav_msgs::Odometry>("/crate/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& m) { crate = *m; });
  ros::Subscriber touching = nh_.subscribe<rigid_body_sim::Contacts>(
      "/sim_node/contacts", 10, [&](const rigid_body_sim::Contacts::ConstPtr& m) { contacts = *m; });

  const SpawnBody::Response added = spawn("crate", "box.urdf");
  ASSERT_TRUE(added.success) << added.message;
  wait(2.0);
  ASSERT_TRUE(spinUntil([&] { return !crate.child_frame_id.empty(); }, 10.0));
  EXPECT_NEAR(crate.pose.pose.position.z, 0.05, 0.005) << "the crate did not land (0.1 m high, on its face)";
  EXPECT_NEAR(crate.pose.pose.position.x, 1.5, 1e-3);
  ASSERT_EQ(last_.name.size(), 2u);  // the arm's joint_states go on
  EXPECT_TRUE(std::isfinite(last_.position[0]) && std::isfinite(last_.position[1]));
  bool crate_on_ground = false;
  for (const rigid_body_sim::ContactPair& p : contacts.pairs) {
    crate_on_ground = crate_on_ground || (p.body == "crate" && p.other == "scene[0]");
  }
  EXPECT_TRUE(crate_on_ground);

  const SpawnBody::Response as_robot = spawn("arm2", "ball.urdf");
  EXPECT_FALSE(as_robot.success);
  EXPECT_NE(as_robot.message.find("name 'arm2' is taken by a robot in the world"), std::string::npos)
      << as_robot.message;
  const SpawnBody::Response same_links = spawn("second_arm", "arm2.urdf");  // its links are the arm's
  EXPECT_FALSE(same_links.success);
  EXPECT_NE(same_links.message.find("the robot's link frame 'upper' is a frame of robot 'arm2'"), std::string::npos)
      << same_links.message;

  rigid_body_sim::DeleteBody d;
  d.request.name = "crate";
  d = call("delete_body", d);
  EXPECT_TRUE(d.response.success) << d.response.message;
  const double stamp = last_.header.stamp.toSec();
  wait(0.5);
  EXPECT_GT(last_.header.stamp.toSec(), stamp);
}

// urdf/pendulum.urdf spawned with its pivot at 0.5 rad (spawn_model's -J):
// pend/joint_states starts there, the rod swings under gravity, ~body_states
// has it; a position past a joint's limit or an unknown joint is refused;
// a reset puts it back where it was spawned.
TEST_F(ArmEdits, ARobotSpawnsWithItsJointsSet) {
  sensor_msgs::JointState first;                  // pend/joint_states
  double lowest = INFINITY, highest = -INFINITY;  // of its pivot angle, in every message
  ros::Subscriber pend = nh_.subscribe<sensor_msgs::JointState>("/pend/joint_states", 100,
                                                                [&](const sensor_msgs::JointState::ConstPtr& m) {
                                                                  if (first.name.empty()) first = *m;
                                                                  if (m->position.size() != 1) return;
                                                                  lowest = std::min(lowest, m->position[0]);
                                                                  highest = std::max(highest, m->position[0]);
                                                                });
  SpawnBody s;
  s.request.name = "pend";
  s.request.urdf_file = "package://rigid_body_sim/urdf/pendulum.urdf";
  s.request.pose.position.x = -2.0;
  s.request.pose.position.z = 1.0;
  s.request.pose.orientation.w = 1.0;
  s.request.joint_names = {"nowhere"};
  s.request.joint_positions = {0.5};
  EXPECT_FALSE(call("spawn_body", s).response.success);
  s.request.joint_names = {"pivot"};
  s.request.joint_positions = {0.5, 1.0};
  const SpawnBody::Response wrong = call("spawn_body", s).response;
  EXPECT_FALSE(wrong.success);
  EXPECT_NE(wrong.message.find("joint_positions: 2 values for 1 joint_names"), std::string::npos) << wrong.message;
  s.request.joint_positions = {0.5};
  // Paused, so the joint is read where it was set, however slow the machine.
  ASSERT_TRUE(trigger("pause"));
  const SpawnBody::Response added = call("spawn_body", s).response;
  ASSERT_TRUE(added.success) << added.message;
  const auto pivot = [&] {
    rigid_body_sim::GetJointProperties p;
    p.request.joint_name = "pend/pivot";
    p = call("get_joint_properties", p);
    EXPECT_TRUE(p.response.success) << p.response.status_message;
    return p.response.position.empty() ? NAN : p.response.position[0];
  };
  EXPECT_DOUBLE_EQ(pivot(), 0.5);
  ASSERT_TRUE(trigger("unpause"));
  ASSERT_TRUE(spinUntil([&] { return !first.name.empty(); }, 10.0));
  EXPECT_EQ(first.name, std::vector<std::string>{"pivot"});
  // Undamped, from rest at 0.5 rad, it swings between 0.5 and -0.5 rad with
  // a period of 1.16 s (ω² = m g 0.25 / I = 29.4 /s²). Wait over a period
  // from the first message received (which can come a swing late: the
  // subscriber connects to the new topic while it already swings).
  wait(1.3);
  EXPECT_LT(lowest, -0.45) << "it did not swing down to the other side";
  EXPECT_LT(highest, 0.5 + 1e-3) << "it gained energy";
  ASSERT_TRUE(trigger("pause"));
  ASSERT_TRUE(trigger("reset"));
  EXPECT_DOUBLE_EQ(pivot(), 0.5) << "a reset did not put it back where it was spawned";
  ASSERT_TRUE(trigger("unpause"));
}

}  // namespace
}  // namespace rbs_test
