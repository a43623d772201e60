// World edits beside a robot (trajectory.test's node: the two-link arm):
// a body spawned with ~spawn_body falls and lands while the arm's
// joint_states go on; a name a robot has is refused; the body is deleted
// again. A robot spawned with its joints set (spawn_model's -J) publishes
// NAME/joint_states from there and swings; one whose links' frames another
// robot has is refused. A robot spawned with its controllers (from its
// namespace, as a Gazebo user loads them, or from the request) is driven by
// them, and deleted with its topics. A robot described for Gazebo
// (test/ros/gazebo_plugins.urdf) spawns with its markup's IMU, ground truth
// and drive under its name; a copy in its robotNamespace is refused (one
// topic, one publisher). Three hundred spawns and deletes of a robot with
// sensors leave the node's memory flat. Two copies of one URDF run side by
// side under their tf_prefixes (two_copies.test).
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/master.h>
#include <ros/network.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Float64.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "../sanitizers.h"
#include "node_process.h"
#include "rigid_body_sim/Contacts.h"
#include "rigid_body_sim/DeleteBody.h"
#include "rigid_body_sim/GetJointProperties.h"
#include "rigid_body_sim/SpawnBody.h"
#include "robot_fixture.h"
#include "tf2_ros/buffer.h"
#include "tf2_ros/transform_listener.h"

namespace rbs_test {
namespace {

using rigid_body_sim::SpawnBody;

class ArmEdits : public RobotNode {
 protected:
  void SetUp() override {
    Node::SetUp();
    listen();
  }
  /// A spawn of the package's `urdf` as `name` at (x, y, z), upright.
  static SpawnBody request(const std::string& name, const std::string& urdf, double x, double y, double z) {
    SpawnBody s;
    s.request.name = name;
    s.request.urdf_file = "package://rigid_body_sim/urdf/" + urdf;
    s.request.pose.position.x = x;
    s.request.pose.position.y = y;
    s.request.pose.position.z = z;
    s.request.pose.orientation.w = 1.0;
    return s;
  }

  SpawnBody::Response spawn(const std::string& name, const std::string& urdf) {
    SpawnBody s = request(name, urdf, 1.5, 0.0, 0.5);
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

TEST_F(ArmEdits, ARobotDescribedForGazeboSpawnsWithItsMarkupsSensorsAndDrive) {
  std::vector<sensor_msgs::Imu> imu;
  std::vector<nav_msgs::Odometry> odom, truth;
  ros::Subscriber imu_sub = nh_.subscribe<sensor_msgs::Imu>(
      "/rover/imu", 100, [&](const sensor_msgs::Imu::ConstPtr& m) { imu.push_back(*m); });
  ros::Subscriber odom_sub = nh_.subscribe<nav_msgs::Odometry>(
      "/gp/odom", 100, [&](const nav_msgs::Odometry::ConstPtr& m) { odom.push_back(*m); });
  ros::Subscriber truth_sub = nh_.subscribe<nav_msgs::Odometry>(
      "/rover/ground_truth/state", 100, [&](const nav_msgs::Odometry::ConstPtr& m) { truth.push_back(*m); });
  ros::Publisher cmd_vel = nh_.advertise<geometry_msgs::Twist>("/gp/cmd_vel", 10);  // its robotNamespace
  SpawnBody s;
  s.request.name = "rover";
  s.request.urdf_file = "package://rigid_body_sim/test/ros/gazebo_plugins.urdf";
  s.request.pose.position.x = 3.0;
  s.request.pose.position.z = 0.08;
  s.request.pose.orientation.w = 1.0;
  ASSERT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
  const SpawnBody::Response added = call("spawn_body", s).response;
  ASSERT_TRUE(added.success) << added.message;
  // Its IMU (gazebo_ros_imu, 100 Hz) reads +g up once it stands on its wheels.
  ASSERT_TRUE(spinUntil([&] { return imu.size() >= 100 && !truth.empty() && !odom.empty(); }, 30.0));
  EXPECT_EQ(imu.back().header.frame_id, "base_link");
  EXPECT_NEAR(imu.back().linear_acceleration.z, 9.81, 0.1);
  EXPECT_NEAR(truth.back().pose.pose.position.x, 3.0, 0.01);
  ASSERT_TRUE(spinUntil([&] { return cmd_vel.getNumSubscribers() > 0; }, 30.0));  // the drive listens
  // Its gazebo_ros_diff_drive, in its gazebo_ros_control's robotNamespace:
  // 0.3 m/s on /gp/cmd_vel until the base runs at it (under ASan on a busy
  // machine the first commands reach the node late in sim time: a window
  // from the first one sent once left it 0.28 m along, not 0.6), then for
  // 1 s of sim time more, over which it covers 0.3 m.
  geometry_msgs::Twist forward;
  forward.linear.x = 0.3;
  const auto drive = [&](const std::function<bool()>& done) {
    const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(60.0);
    while (ros::ok() && !done() && ros::WallTime::now() < give_up) {
      cmd_vel.publish(forward);
      spinUntil([] { return false; }, 0.02);
    }
    return done();
  };
  ASSERT_TRUE(drive([&] { return truth.back().twist.twist.linear.x > 0.29; }));
  const nav_msgs::Odometry start = truth.back();
  ASSERT_TRUE(drive([&] { return truth.back().header.stamp.toSec() >= start.header.stamp.toSec() + 1.0; }));
  EXPECT_NEAR(truth.back().twist.twist.linear.x, 0.3, 0.03 * 0.3);
  EXPECT_NEAR(odom.back().twist.twist.linear.x, 0.3, 0.03 * 0.3);
  const double along = truth.back().pose.pose.position.x - start.pose.pose.position.x,
               over = (truth.back().header.stamp - start.header.stamp).toSec();
  EXPECT_NEAR(along / over, 0.3, 0.03 * 0.3) << along << " m in " << over << " s";
  // One topic, one publisher: a copy in the same robotNamespace would
  // publish its joint_states and odometry on the first one's topics (the
  // two interleaved without a word): refused, naming both, the world
  // unchanged; once the first is deleted, its topics are free.
  s.request.name = "rover_copy";
  s.request.pose.position.y = 3.0;
  ros::param::set("/rover_copy/tf_prefix", "rover_copy");  // its frames its own: only the topics clash
  const SpawnBody::Response copy = call("spawn_body", s).response;
  EXPECT_FALSE(copy.success);
  EXPECT_NE(copy.message.find("name 'rover_copy': joint_states: topic '/gp/joint_states' is taken by 'rover' "
                              "joint_states (one topic, one publisher"),
            std::string::npos)
      << copy.message;
  // spawn_model's -robot_namespace puts every topic of the copy under it (as
  // Gazebo gives it to each plugin, in place of the markup's), and its
  // controllers are read there (it was refused as an unknown flag).
  SpawnBody b = s;
  b.request.name = "rover_b";
  b.request.robot_namespace = "rover_b";
  ros::param::set("/rover_b/tf_prefix", "rover_b");
  ros::param::set("/rover_b/odd/type", "no_such_controllers/Controller");
  const SpawnBody::Response odd = call("spawn_body", b).response;
  EXPECT_FALSE(odd.success);
  EXPECT_NE(odd.message.find("controllers (the parameters under '/rover_b'): config key '/rover_b.odd.type'"),
            std::string::npos)
      << odd.message;
  ros::param::del("/rover_b/odd");
  const SpawnBody::Response own = call("spawn_body", b).response;
  ASSERT_TRUE(own.success) << own.message;
  EXPECT_NE(own.message.find("'rover_b/joint_states'"), std::string::npos) << own.message;
  EXPECT_TRUE(spinUntil(
      [] {
        return subscribes("/sim_node", "/rover_b/cmd_vel") && advertised("/rover_b/odom") &&
               advertised("/rover_b/imu") && advertised("/rover_b/ground_truth/state") &&
               advertised("/rover_b/joint_states");
      },
      10.0));
  EXPECT_FALSE(advertised("/rover_b/rover_b/imu"));
  // What is no namespace, and a body's, are refused.
  for (const auto& [ns, why] : {std::pair{"~private", "robot_namespace '~private': no ROS namespace"},
                                std::pair{"two words", "robot_namespace 'two words': no ROS namespace"},
                                std::pair{"1st", "robot_namespace '1st': no ROS namespace"}}) {
    SpawnBody bad = b;
    bad.request.name = "rover_c";
    bad.request.robot_namespace = ns;
    const SpawnBody::Response refused = call("spawn_body", bad).response;
    EXPECT_FALSE(refused.success) << ns;
    EXPECT_EQ(refused.message.rfind(why, 0), 0u) << refused.message;
  }
  SpawnBody box = request("crate_ns", "box.urdf", 4.0, 4.0, 0.5);
  box.request.robot_namespace = "crates";
  const SpawnBody::Response crate = call("spawn_body", box).response;
  EXPECT_FALSE(crate.success);
  EXPECT_EQ(crate.message.rfind("robot_namespace: the URDF has no moving joints", 0), 0u) << crate.message;
  rigid_body_sim::DeleteBody d;
  d.request.name = "rover";
  d = call("delete_body", d);
  EXPECT_TRUE(d.response.success) << d.response.message;
  const SpawnBody::Response after = call("spawn_body", s).response;
  EXPECT_TRUE(after.success) << after.message;
  for (const char* name : {"rover_copy", "rover_b"}) {
    d.request.name = name;
    d = call("delete_body", d);
    EXPECT_TRUE(d.response.success) << d.response.message;
  }
}

// A spawn whose cameras would hold more than devices.memory is refused,
// naming the camera, before any is built, and the world does not change: a
// URDF of 400 such cameras once took 5.8 GB for 13 s before answering
// std::bad_alloc.
TEST_F(ArmEdits, ASpawnWhoseDevicesWouldPassTheirMemoryIsRefusedBeforeAnyIsBuilt) {
  std::string xml =
      "<robot name='eyes'><link name='base'><inertial><mass value='1'/><inertia ixx='0.01' iyy='0.01' izz='0.01' "
      "ixy='0' ixz='0' iyz='0'/></inertial><collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision>"
      "</link><joint name='pan' type='continuous'><parent link='base'/><child link='head'/><axis xyz='0 0 1'/>"
      "</joint><link name='head'><inertial><mass value='0.5'/><inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' "
      "ixz='0' iyz='0'/></inertial></link>";
  for (int k = 0; k < 400; ++k) {
    xml += "<gazebo reference='head'><sensor type='depth' name='cam" + std::to_string(k) +
           "'><camera><horizontal_fov>1</horizontal_fov><image><width>2000</width><height>2000</height></image>"
           "</camera><plugin name='k' filename='libgazebo_ros_openni_kinect.so'><cameraName>cam" +
           std::to_string(k) + "</cameraName></plugin></sensor></gazebo>";
  }
  xml += "</robot>";
  SpawnBody s;
  s.request.name = "eyes";
  s.request.urdf_xml = xml;
  s.request.pose.position.x = -2.0;
  s.request.pose.orientation.w = 1.0;
  ASSERT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
  const SpawnBody::Response refused = call("spawn_body", s).response;
  EXPECT_FALSE(refused.success);
  EXPECT_NE(refused.message.find("<sensor name=\"cam3\">': the device would hold 306 MiB, and the devices may "
                                 "hold devices.memory = 1024 MiB in all"),
            std::string::npos)
      << refused.message.substr(0, 400);
  rigid_body_sim::DeleteBody d;
  d.request.name = "eyes";
  EXPECT_FALSE(call("delete_body", d).response.success);  // nothing of it in the world
}

// Spawns and deletes of a robot with sensors and a drive leave the node's
// memory where it was (docs/ros_api.md: within 1 % over 300 cycles). Each
// spawn once left its topics' 264-byte blocks in the node's own
// NodeHandles, 2.5 KB a cycle with no plateau (0.5 MB per 200 cycles of a
// rover with a lidar, a depth camera and a controller); each robot now
// opens them through a handle of its own.
TEST_F(ArmEdits, SpawnsAndDeletesOfARobotWithSensorsLeaveTheNodesMemoryFlat) {
#if defined(RBS_UNDER_ASAN)
  GTEST_SKIP() << "ASan's quarantine holds what is freed: the node's memory says nothing here";
#endif
  const int pid = simNodePid();
  ASSERT_GT(pid, 0);
  SpawnBody s;
  s.request.name = "cycled";
  s.request.urdf_file = "package://rigid_body_sim/urdf/diff_drive_lidar.urdf";
  s.request.pose.position.x = -3.0;
  s.request.pose.position.z = 0.1;
  s.request.pose.orientation.w = 1.0;
  s.request.controllers =
      "{base: {type: diff_drive_controller/DiffDriveController, left_wheel: left_wheel_joint, "
      "right_wheel: right_wheel_joint}}";
  rigid_body_sim::DeleteBody d;
  d.request.name = "cycled";
  ASSERT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
  const auto cycles = [&](int n) {
    for (int k = 0; k < n; ++k) {
      const SpawnBody::Response added = call("spawn_body", s).response;
      ASSERT_TRUE(added.success) << added.message;
      ASSERT_TRUE(call("delete_body", d).response.success);
    }
  };
  cycles(50);  // the allocator's pools and roscpp's caches, once
  const long warm = residentKb(pid);
  cycles(300);
  const long after = residentKb(pid);
  ASSERT_GT(warm, 0);
  // 1 % over all 300 (the leak took about 2 %), room for the allocator's steps.
  EXPECT_LE(after - warm, warm / 100) << "300 cycles: " << warm << " kB, then " << after << " kB";
  RecordProperty("rss_kb_warm", static_cast<int>(warm));
  RecordProperty("rss_kb_after_300", static_cast<int>(after));
}

// The answer says what drives the robot: it said "no controllers:
// apply_joint_effort drives it" of a base its DiffDriveController drove.
TEST_F(ArmEdits, ASpawnsAnswerNamesItsDrivesAndTheirTopics) {
  SpawnBody s = request("rover2", "diff_drive.urdf", -3.0, 3.0, 0.08);
  s.request.controllers =
      "{base: {type: diff_drive_controller/DiffDriveController, left_wheel: left_wheel_joint, "
      "right_wheel: right_wheel_joint}}";
  ASSERT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
  const SpawnBody::Response added = call("spawn_body", s).response;
  ASSERT_TRUE(added.success) << added.message;
  EXPECT_NE(added.message.find("'rover2/joint_states', drives base on 'rover2/base/cmd_vel'"), std::string::npos)
      << added.message;
  EXPECT_EQ(added.message.find("no controllers"), std::string::npos) << added.message;
  EXPECT_TRUE(spinUntil([&] { return subscribes("/sim_node", "/rover2/base/cmd_vel"); }, 10.0));
  rigid_body_sim::DeleteBody d;
  d.request.name = "rover2";
  EXPECT_TRUE(call("delete_body", d).response.success);
}

// Two controllers on one joint (UR's stock YAML): the first runs, the
// second is loaded stopped, said in the answer, and takes no command.
TEST_F(ArmEdits, OfTwoControllersOnAJointTheFirstRunsAndTheAnswerSaysSo) {
  SpawnBody s = request("pend3", "pendulum.urdf", -2.0, -3.0, 1.5);
  s.request.controllers =
      "{hold: {type: effort_controllers/JointPositionController, joint: pivot, pid: {p: 200, d: 5}},"
      " push: {type: effort_controllers/JointEffortController, joint: pivot}}";
  ASSERT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
  const SpawnBody::Response added = call("spawn_body", s).response;
  ASSERT_TRUE(added.success) << added.message;
  EXPECT_NE(added.message.find("1 controller loaded stopped, as controller_manager's spawner leaves a controller "
                               "whose joints another has: 'push' (a joint of 'hold')"),
            std::string::npos)
      << added.message;
  EXPECT_TRUE(spinUntil([&] { return subscribes("/sim_node", "/pend3/hold/command"); }, 10.0));
  EXPECT_FALSE(subscribes("/sim_node", "/pend3/push/command"));
  rigid_body_sim::DeleteBody d;
  d.request.name = "pend3";
  EXPECT_TRUE(call("delete_body", d).response.success);
}

// A robot spawned with cmd_vel (its base driven as a body's), then another
// without, then the first deleted: the second takes its place in the
// world's order of robots and steps on without the first's base wrench
// (which once stopped the step, sized for the other robot's links).
TEST_F(ArmEdits, ADrivenRobotDeletedBeforeAnotherLeavesItNoWrench) {
  SpawnBody sled = request("sled", "diff_drive.urdf", -3.0, 0.0, 0.08);
  sled.request.cmd_vel = "{planar: true, timeout: 0}";
  ASSERT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
  ASSERT_TRUE(call("spawn_body", sled).response.success);
  ros::Publisher cmd_vel = nh_.advertise<geometry_msgs::Twist>("/sled/cmd_vel", 10, true);
  geometry_msgs::Twist slow;
  slow.linear.x = 0.1;
  cmd_vel.publish(slow);
  const SpawnBody::Response other = spawn("other", "pendulum.urdf");
  ASSERT_TRUE(other.success) << other.message;
  wait(0.5);
  rigid_body_sim::DeleteBody d;
  d.request.name = "sled";
  d = call("delete_body", d);
  ASSERT_TRUE(d.response.success) << d.response.message;
  sensor_msgs::JointState pendulum;
  ros::Subscriber sub = nh_.subscribe<sensor_msgs::JointState>(
      "/other/joint_states", 10, [&](const sensor_msgs::JointState::ConstPtr& m) { pendulum = *m; });
  wait(1.0);  // the world steps on: the arm's joint_states advance
  ASSERT_TRUE(spinUntil([&] { return !pendulum.name.empty(); }, 10.0));
  EXPECT_GT(pendulum.header.stamp.toSec(), last_.header.stamp.toSec() - 0.5);
  d.request.name = "other";
  EXPECT_TRUE(call("delete_body", d).response.success);
}

// urdf/pendulum.urdf spawned as a Gazebo user spawns a robot with
// controllers (rosparam load FILE /pend2, then spawn_model): its position
// controller drives it to the commanded angle and its joint_state_controller
// sets its joint_states' rate. Deleted, every topic of it goes (its
// joint_states, its controller's command, its joint_command) and its joints
// with it, while the arm runs on; spawned again, with its controllers given
// in the request this time, it is driven again; deleted again.
TEST_F(ArmEdits, ARobotSpawnsWithItsControllersIsDrivenAndIsDeleted) {
  ros::param::set("/pend2/joint_state_controller/type", std::string("joint_state_controller/JointStateController"));
  ros::param::set("/pend2/joint_state_controller/publish_rate", 50.0);
  ros::param::set("/pend2/pivot_controller/type", std::string("effort_controllers/JointPositionController"));
  ros::param::set("/pend2/pivot_controller/joint", std::string("pivot"));
  ros::param::set("/pend2/pivot_controller/pid/p", 200.0);
  ros::param::set("/pend2/pivot_controller/pid/i", 100.0);
  ros::param::set("/pend2/pivot_controller/pid/d", 5.0);
  ros::param::set("/pend2/robot_description", std::string("not read: not a controller"));
  std::vector<sensor_msgs::JointState> received;
  ros::Subscriber states = nh_.subscribe<sensor_msgs::JointState>(
      "/pend2/joint_states", 100, [&](const sensor_msgs::JointState::ConstPtr& m) { received.push_back(*m); });
  ros::Publisher target = nh_.advertise<std_msgs::Float64>("/pend2/pivot_controller/command", 1, true);
  SpawnBody s;
  s.request.name = "pend2";
  s.request.urdf_file = "package://rigid_body_sim/urdf/pendulum.urdf";
  s.request.pose.position.x = -2.0;
  s.request.pose.orientation.w = 1.0;
  const auto drivenTo = [&](double angle) {
    std_msgs::Float64 command;
    command.data = angle;
    target.publish(command);
    received.clear();
    EXPECT_TRUE(spinUntil([&] { return received.size() > 150; }, 60.0)) << "no joint_states from pend2";  // 3 s
    if (received.size() < 2) return;
    const sensor_msgs::JointState& last = received.back();
    ASSERT_EQ(last.position.size(), 1u);
    EXPECT_NEAR(last.position[0], angle, 0.02) << "the controller did not drive the pivot there";
    const double period = (last.header.stamp - received[received.size() - 2].header.stamp).toSec();
    EXPECT_NEAR(period, 0.02, 1e-6) << "not the joint_state_controller's 50 Hz";
  };
  const auto deleted = [&] {
    rigid_body_sim::DeleteBody d;
    d.request.name = "pend2";
    d = call("delete_body", d);
    EXPECT_TRUE(d.response.success) << d.response.message;
    EXPECT_NE(d.response.message.find("robot 'pend2' deleted"), std::string::npos) << d.response.message;
    EXPECT_TRUE(spinUntil(
        [&] {
          return !advertised("/pend2/joint_states") && !subscribes("/sim_node", "/pend2/pivot_controller/command") &&
                 !subscribes("/sim_node", "/pend2/joint_command");
        },
        10.0))
        << "a topic of the deleted robot is still open";
    rigid_body_sim::GetJointProperties p;
    p.request.joint_name = "pend2/pivot";
    EXPECT_FALSE(call("get_joint_properties", p).response.success);
    const double stamp = last_.header.stamp.toSec();
    wait(0.2);
    EXPECT_GT(last_.header.stamp.toSec(), stamp) << "the arm stopped";
  };

  const SpawnBody::Response added = call("spawn_body", s).response;
  ASSERT_TRUE(added.success) << added.message;
  EXPECT_NE(added.message.find("controllers pivot_controller on 'pend2/CONTROLLER/command'"), std::string::npos)
      << added.message;
  drivenTo(0.6);
  deleted();

  s.request.controllers =
      "{pivot_controller: {type: effort_controllers/JointPositionController, joint: pivot,"
      " pid: {p: 200, i: 100, d: 5}},"
      " joint_state_controller: {type: joint_state_controller/JointStateController, publish_rate: 50}}";
  ros::param::del("/pend2");
  const SpawnBody::Response again = call("spawn_body", s).response;
  ASSERT_TRUE(again.success) << again.message;
  drivenTo(-0.4);
  deleted();

  s.request.controllers = "{pivot_controller: {type: effort_controllers/JointPositionController, joint: pivot}}";
  const SpawnBody::Response no_gains = call("spawn_body", s).response;
  EXPECT_FALSE(no_gains.success);
  EXPECT_NE(no_gains.message.find("controllers: "), std::string::npos) << no_gains.message;
  EXPECT_NE(no_gains.message.find("pivot_controller.pid"), std::string::npos) << no_gains.message;
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

// urdf/four_wheeler.urdf spawned twice, as car_a and car_b, each with its
// tf_prefix set as robot_state_publisher reads it (two_copies.test runs one
// in each namespace): tf carries both, 2 m apart, the node placing each base
// and robot_state_publisher each wheel. A copy without a tf_prefix comes in
// once with the URDF's own names; a second such copy is refused naming the
// frame and the parameter, and comes in once it has one. A deleted copy's
// base is no longer on tf, while the other's goes on.
TEST(TwoCopies, OneUrdfRunsTwiceUnderTheTfPrefixes) {
  ros::NodeHandle nh;
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  ASSERT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
  ros::ServiceClient spawner = nh.serviceClient<SpawnBody>("/sim_node/spawn_body");
  ros::ServiceClient deleter = nh.serviceClient<rigid_body_sim::DeleteBody>("/sim_node/delete_body");
  const auto spawn = [&](const std::string& name, double x) {
    SpawnBody s;
    s.request.name = name;
    s.request.urdf_file = "package://rigid_body_sim/urdf/four_wheeler.urdf";
    s.request.pose.position.x = x;
    s.request.pose.position.y = 3.0;  // clear of the box
    s.request.pose.position.z = 0.1;
    s.request.pose.orientation.w = 1.0;
    EXPECT_TRUE(spawner.call(s));
    return s.response;
  };
  const auto where = [&](const std::string& frame) {
    geometry_msgs::TransformStamped t;
    EXPECT_TRUE(spinUntil([&] { return buffer.canTransform("world", frame, ros::Time(0)); }, 20.0)) << frame;
    if (buffer.canTransform("world", frame, ros::Time(0))) t = buffer.lookupTransform("world", frame, ros::Time(0));
    return t;
  };
  for (const auto& [name, x] : {std::pair<std::string, double>{"car_a", 0.0}, {"car_b", 2.0}}) {
    const SpawnBody::Response added = spawn(name, x);
    ASSERT_TRUE(added.success) << added.message;
  }
  const geometry_msgs::TransformStamped a = where("car_a/front_left_wheel"), b = where("car_b/front_left_wheel");
  EXPECT_NEAR(b.transform.translation.x - a.transform.translation.x, 2.0, 0.01);
  EXPECT_NEAR(a.transform.translation.y, 3.25, 0.01);  // the wheel 0.25 m left of the chassis
  EXPECT_NEAR(b.transform.translation.y, 3.25, 0.01);

  ASSERT_TRUE(spawn("car_c", 4.0).success);  // no tf_prefix: the URDF's names, nobody's yet
  // Its base, which the node places (no robot_state_publisher runs for it).
  where("chassis");
  const SpawnBody::Response twice = spawn("car_d", 6.0);
  EXPECT_FALSE(twice.success);
  EXPECT_NE(twice.message.find("the robot's link frame 'chassis' is a frame of robot 'car_c'"), std::string::npos)
      << twice.message;
  EXPECT_NE(twice.message.find("set car_d/tf_prefix"), std::string::npos) << twice.message;
  ros::param::set("/car_d/tf_prefix", std::string("car_d"));
  const SpawnBody::Response prefixed = spawn("car_d", 6.0);
  EXPECT_TRUE(prefixed.success) << prefixed.message;

  rigid_body_sim::DeleteBody d;
  d.request.name = "car_a";
  ASSERT_TRUE(deleter.call(d));
  ASSERT_TRUE(d.response.success) << d.response.message;
  ros::WallDuration(0.3).sleep();  // what was on its way before the delete
  const ros::Time gone = where("car_a/chassis").header.stamp, on = where("car_b/chassis").header.stamp;
  ros::WallDuration(1.0).sleep();
  EXPECT_EQ(where("car_a/chassis").header.stamp, gone) << "the deleted copy's base is still on tf";
  EXPECT_GT(where("car_b/chassis").header.stamp, on) << "the other copy's base stopped";
}

}  // namespace
}  // namespace rbs_test
