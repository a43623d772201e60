// World edits beside a robot (trajectory.test's node: the two-link arm):
// a body spawned with ~spawn_body falls and lands while the arm's
// joint_states go on; a name or URDF a robot has is refused; the body is
// deleted again.
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>

#include <cmath>
#include <string>

#include "rigid_body_sim/Contacts.h"
#include "rigid_body_sim/DeleteBody.h"
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
  const SpawnBody::Response robot = spawn("second_arm", "arm2.urdf");  // a robot: not spawned yet
  EXPECT_FALSE(robot.success);
  EXPECT_FALSE(robot.message.empty());

  rigid_body_sim::DeleteBody d;
  d.request.name = "crate";
  d = call("delete_body", d);
  EXPECT_TRUE(d.response.success) << d.response.message;
  const double stamp = last_.header.stamp.toSec();
  wait(0.5);
  EXPECT_GT(last_.header.stamp.toSec(), stamp);
}

}  // namespace
}  // namespace rbs_test
