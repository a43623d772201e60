// The node as its users meet it: services called, topics received. Each
// .test in this folder starts sim_node with its own parameters and runs one
// suite of this file (--gtest_filter).
#include <geometry_msgs/WrenchStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <sys/wait.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/ApplyImpulse.h"
#include "rigid_body_sim/ApplyWrench.h"
#include "rigid_body_sim/ClearWrenches.h"
#include "rigid_body_sim/GetState.h"
#include "rigid_body_sim/SetState.h"
#include "rigid_body_sim/Step.h"
#include "rigid_body_sim/core/bodies/sdf.h"

namespace {

using namespace rbs_test;

/// The box of urdf/box.urdf: 1 kg, half extents 0.2 × 0.1 × 0.05 m.
const double kI[3] = {(0.01 + 0.0025) / 3.0, (0.04 + 0.0025) / 3.0, (0.04 + 0.01) / 3.0};

// ------------------------------------------------------------------ free fall (sim time)

class FreeFall : public Node {};

TEST_F(FreeFall, OdometryFollowsTheClosedForm) {
  // Dropped from 50 m at t = 0; stamps are sim times. Euler-Cromer gives
  // z(t) = z₀ − ½ g t (t + Δt): the closed form plus its first-order term.
  std::vector<nav_msgs::Odometry> msgs;
  const ros::Subscriber sub = nh_.subscribe<nav_msgs::Odometry>(
      "/odom", 1000, [&](const nav_msgs::Odometry::ConstPtr& m) { msgs.push_back(*m); });
  ASSERT_TRUE(spinUntil([&] { return msgs.size() >= 60; }, 30.0));
  for (const auto& m : msgs) {
    const double t = m.header.stamp.toSec();
    if (t == 0.0) continue;
    EXPECT_EQ(m.header.frame_id, "world");
    EXPECT_EQ(m.child_frame_id, kLink);
    EXPECT_NEAR(m.pose.pose.position.z, 50.0 - 0.5 * kG * t * (t + kDt), 1e-9) << "t " << t;
    EXPECT_NEAR(m.pose.pose.position.z, 50.0 - 0.5 * kG * t * t, 0.5 * kG * kDt * t + 1e-9);
    EXPECT_NEAR(m.twist.twist.linear.z, -kG * t, 1e-9);  // body frame = world frame here
    EXPECT_DOUBLE_EQ(m.pose.pose.position.x, 0.0);
  }
}

// ------------------------------------------------------------------ tf

class Tf : public Node {};

TEST_F(Tf, LookupEqualsTheOdometryPose) {
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  std::vector<nav_msgs::Odometry> msgs;
  const ros::Subscriber sub = nh_.subscribe<nav_msgs::Odometry>(
      "/odom", 1000, [&](const nav_msgs::Odometry::ConstPtr& m) { msgs.push_back(*m); });
  ASSERT_TRUE(spinUntil([&] { return msgs.size() >= 50; }, 30.0));
  ros::WallDuration(0.2).sleep();
  ros::spinOnce();
  int checked = 0;
  for (const auto& m : msgs) {
    geometry_msgs::TransformStamped tf;
    try {
      tf = buffer.lookupTransform("world", kLink, m.header.stamp);
    } catch (const tf2::TransformException&) {
      continue;  // older than the listener
    }
    ++checked;
    const auto& p = m.pose.pose;
    EXPECT_NEAR(tf.transform.translation.x, p.position.x, 1e-12);
    EXPECT_NEAR(tf.transform.translation.y, p.position.y, 1e-12);
    EXPECT_NEAR(tf.transform.translation.z, p.position.z, 1e-12);
    EXPECT_NEAR(tf.transform.rotation.x, p.orientation.x, 1e-12);
    EXPECT_NEAR(tf.transform.rotation.y, p.orientation.y, 1e-12);
    EXPECT_NEAR(tf.transform.rotation.z, p.orientation.z, 1e-12);
    EXPECT_NEAR(tf.transform.rotation.w, p.orientation.w, 1e-12);
  }
  EXPECT_GT(checked, 20);
}

/// The local address, as /proc/net/tcp writes it (hex, "00000000" for
/// 0.0.0.0), of the IPv4 socket listening on `port`, or "" if none does.
std::string listeningAddress(int port) {
  std::ifstream in("/proc/net/tcp");
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string slot, local, remote, state;
    fields >> slot >> local >> remote >> state;
    const std::size_t colon = local.rfind(':');
    if (state == "0A" && colon != std::string::npos && std::stoi(local.substr(colon + 1), nullptr, 16) == port) {
      return local.substr(0, colon);  // 0A: LISTEN
    }
  }
  return "";
}

TEST_F(Tf, ListensWhereTheReadmesSecurityNoteSays) {
  // docs/ros_api.md, Security: with ROS_HOSTNAME=localhost the master listens on
  // 127.0.0.1, but roscpp's XML-RPC server (where anyone may call shutdown)
  // on every address. It said the opposite once.
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  args[1] = "/sim_node";
  ASSERT_TRUE(ros::master::execute("lookupNode", args, result, payload, true));
  const std::string uri = payload;  // http://localhost:PORT/
  const int port = std::stoi(uri.substr(uri.rfind(':') + 1));
  EXPECT_EQ(listeningAddress(port), "00000000") << uri;
  EXPECT_EQ(listeningAddress(static_cast<int>(ros::master::getPort())), "0100007F");  // 127.0.0.1
}

// ------------------------------------------------------------------ loads (paused, stepped: exact)

class Impulse : public Node {};

TEST_F(Impulse, ChangesTheVelocityByJOverM) {
  ASSERT_TRUE(trigger("pause"));
  const BodyState before = state();
  ASSERT_TRUE(impulse("world", vec(0.3, -0.2, 0.5)).success);
  const BodyState after = state();
  EXPECT_NEAR(after.twist.linear.x - before.twist.linear.x, 0.3, 1e-12);  // M = 1 kg
  EXPECT_NEAR(after.twist.linear.y - before.twist.linear.y, -0.2, 1e-12);
  EXPECT_NEAR(after.twist.linear.z - before.twist.linear.z, 0.5, 1e-12);
  EXPECT_EQ(after.pose.position.z, before.pose.position.z);
  // Off the centre of mass it also turns the body: Δω = I⁻¹ (r × J).
  geometry_msgs::Point r;
  r.x = 0.2;
  ASSERT_TRUE(impulse("world", vec(0, 0, 0.1), r).success);  // r × J = (0, −0.02, 0)
  const BodyState turned = state();
  EXPECT_NEAR(turned.twist.angular.y - after.twist.angular.y, -0.02 / kI[1], 1e-12);
  EXPECT_NEAR(turned.twist.angular.x, 0.0, 1e-12);
}

class WrenchDuration : public Node {};

TEST_F(WrenchDuration, DeliversForceTimesDuration) {
  ASSERT_TRUE(trigger("pause"));
  const BodyState before = state();
  const auto res = wrench("world", vec(2, 0, 0), 0.0123);  // not a whole number of steps
  ASSERT_TRUE(res.success) << res.message;
  ASSERT_TRUE(step(50).success);
  EXPECT_NEAR(state().twist.linear.x - before.twist.linear.x, 2 * 0.0123, 1e-12);
  ASSERT_TRUE(step(50).success);  // and nothing after it ended
  EXPECT_NEAR(state().twist.linear.x - before.twist.linear.x, 2 * 0.0123, 1e-12);
}

class BodyFrameWrench : public Node {};

TEST_F(BodyFrameWrench, PushesAlongTheRotatedAxis) {
  // The body is turned 90° about z: its x axis is world y (gazebo_ros_pkgs #310).
  ASSERT_TRUE(trigger("pause"));
  ASSERT_TRUE(wrench(kLink, vec(1, 0, 0), 0.1).success);
  ASSERT_TRUE(step(200).success);
  const BodyState s = state();
  EXPECT_NEAR(s.twist.linear.x, 0.0, 1e-12);
  EXPECT_NEAR(s.twist.linear.y, 0.1, 1e-12);
  const BodyState in_body = state(kLink);  // and in the body frame it is along x
  EXPECT_NEAR(in_body.twist.linear.x, 0.1, 1e-12);
  // Odometry carries its twist in child_frame_id, the body (not the world, gazebo_ros #1026).
  nav_msgs::Odometry odom;
  bool got = false;
  const ros::Subscriber sub =
      nh_.subscribe<nav_msgs::Odometry>("/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& m) {
        odom = *m;
        got = true;
      });
  ASSERT_TRUE(spinUntil([&] { return sub.getNumPublishers() > 0; }, 10.0));
  ASSERT_TRUE(step(10).success);  // a new stamp to publish at
  ASSERT_TRUE(spinUntil([&] { return got; }, 10.0));
  EXPECT_EQ(odom.child_frame_id, kLink);
  EXPECT_NEAR(odom.twist.twist.linear.x, 0.1, 1e-12);
  EXPECT_NEAR(odom.twist.twist.linear.y, 0.0, 1e-12);
}

class WrenchTopic : public Node {};

TEST_F(WrenchTopic, IsHeldUntilItsTimeout) {
  // ~wrench_timeout is 0.05 s in this test: a message pushes for 50 steps of sim time.
  ASSERT_TRUE(trigger("pause"));
  ros::Publisher pub = nh_.advertise<geometry_msgs::WrenchStamped>("/sim_node/wrench", 1, true);
  ASSERT_TRUE(spinUntil([&] { return pub.getNumSubscribers() > 0; }, 10.0));
  geometry_msgs::WrenchStamped w;
  w.header.frame_id = kLink;  // body frame: the body is not turned here
  w.wrench.force.y = 2.0;
  pub.publish(w);
  ros::WallDuration(0.3).sleep();  // delivered before the steps
  ASSERT_TRUE(step(200).success);
  const BodyState s = state();
  // Exactly 50 steps of 2 N on 1 kg (it acted for one step more: 0.102 m/s).
  EXPECT_NEAR(s.twist.linear.y, 2.0 * 0.05, 1e-12);
  w.header.frame_id = "map";  // an unknown frame is ignored
  pub.publish(w);
  ros::WallDuration(0.3).sleep();
  ASSERT_TRUE(step(100).success);
  EXPECT_EQ(state().twist.linear.y, s.twist.linear.y);
}

class Scene : public Node {};

TEST_F(Scene, MarkersShowTheGroundAndTheRoom) {
  const visualization_msgs::MarkerArray markers = latchedMarkers("/sim_node/scene_markers");
  ASSERT_EQ(markers.markers.size(), 2u);
  const auto& ground = markers.markers[0];
  EXPECT_EQ(ground.type, visualization_msgs::Marker::CUBE);
  EXPECT_EQ(ground.header.frame_id, "world");
  EXPECT_NEAR(ground.pose.position.z, -0.0005, 1e-12);  // a 1 mm slab whose top is z = 0
  const auto& room = markers.markers[1];
  EXPECT_EQ(room.type, visualization_msgs::Marker::TRIANGLE_LIST);
  ASSERT_GT(room.points.size(), 300u);
  EXPECT_EQ(room.points.size() % 3, 0u);
  // Every vertex lies on the room's surface φ = 0 (within one grid cell).
  namespace core = rigid_body_sim::core;
  const core::Sdf room_sdf = core::Sdf::subtract(
      {core::Sdf::box(core::Vec3(6.2, 6.2, 2.2)).transformed({core::Quat::Identity(), core::Vec3(0, 0, 11)}),
       core::Sdf::box(core::Vec3(6.0, 6.0, 3.0)).transformed({core::Quat::Identity(), core::Vec3(0, 0, 11.6)})});
  const double cell = 6.2 * 1.06 / 64;
  for (const auto& p : room.points) EXPECT_LT(std::abs(room_sdf.eval(core::Vec3(p.x, p.y, p.z))), cell) << p;
}

class TwoWrenches : public Node {};

TEST_F(TwoWrenches, AddUpAndClear) {
  ASSERT_TRUE(trigger("pause"));
  ASSERT_TRUE(wrench("world", vec(1, 0, 0), 0.05).success);
  ASSERT_TRUE(wrench("world", vec(0, 2, 0), 0.1).success);
  ASSERT_TRUE(step(200).success);
  BodyState s = state();
  EXPECT_NEAR(s.twist.linear.x, 0.05, 1e-12);
  EXPECT_NEAR(s.twist.linear.y, 0.2, 1e-12);
  // Until cleared: 3 N for exactly ten steps.
  ASSERT_TRUE(wrench("world", vec(0, 0, 3), -1.0).success);
  ASSERT_TRUE(step(10).success);
  rigid_body_sim::ClearWrenches clear;
  ASSERT_TRUE(call("clear_wrenches", clear).response.success);
  ASSERT_TRUE(step(10).success);
  EXPECT_NEAR(state().twist.linear.z, 3 * 10 * kDt, 1e-12);
}

// ------------------------------------------------------------------ time (sim time)

class PauseStep : public Node {};

TEST_F(PauseStep, PausedTimeStandsStepAdvancesByNSteps) {
  ASSERT_TRUE(trigger("pause"));
  const BodyState a = state();
  ros::WallDuration(0.3).sleep();
  const BodyState b = state();
  EXPECT_EQ(a.stamp, b.stamp);
  EXPECT_EQ(a.pose.position.z, b.pose.position.z);
  const auto r = step(25);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ((r.time - b.stamp).toNSec(), 25 * 1000000LL);
  ASSERT_EQ(r.states.size(), 1u);
  EXPECT_EQ(r.states[0].stamp, r.time);
  ASSERT_TRUE(trigger("unpause"));
  EXPECT_FALSE(step(1).success);  // step is for a paused simulation
  ros::WallDuration(0.3).sleep();
  EXPECT_GT(state().stamp, r.time);
}

// launch/sim.launch paused:=true (sim_launch_paused.test: the demo's box),
// as Gazebo's launch files take it: the node starts paused and steps on
// request. The launch file used to have no such argument and ran at once.
class SimLaunchPaused : public Node {};

TEST_F(SimLaunchPaused, StartsPausedAndSteps) {
  const BodyState a = state();
  ros::WallDuration(0.5).sleep();
  const BodyState b = state();
  EXPECT_EQ(a.stamp, b.stamp);
  EXPECT_EQ(a.pose.position.z, 1.0);  // config/demo.yaml's start, untouched
  const auto r = step(10);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ((r.time - b.stamp).toNSec(), 10 * 1000000LL);  // demo.yaml: dt 1 ms
  ASSERT_EQ(r.states.size(), 1u);
  EXPECT_LT(r.states[0].pose.position.z, 1.0);  // falling, once stepped
}

class Reset : public Node {};

TEST_F(Reset, ReturnsToTheStartWithTimeMovingOn) {
  std::vector<ros::Time> stamps;
  const ros::Subscriber sub = nh_.subscribe<nav_msgs::Odometry>(
      "/odom", 1000, [&](const nav_msgs::Odometry::ConstPtr& m) { stamps.push_back(m->header.stamp); });
  ASSERT_TRUE(spinUntil([&] { return stamps.size() >= 30; }, 30.0));
  ASSERT_TRUE(trigger("pause"));
  const BodyState moved = state();
  EXPECT_LT(moved.pose.position.z, 0.99);
  ASSERT_TRUE(trigger("reset"));
  const BodyState back = state();
  EXPECT_EQ(back.pose.position.x, 0.0);  // the initial pose of this test's config, exactly
  EXPECT_EQ(back.pose.position.z, 1.0);
  EXPECT_EQ(back.twist.linear.z, 0.0);
  EXPECT_EQ(back.stamp, moved.stamp);  // reset does not touch time
  ASSERT_TRUE(trigger("unpause"));
  const std::size_t seen = stamps.size();
  ASSERT_TRUE(spinUntil([&] { return stamps.size() >= seen + 30; }, 30.0));
  EXPECT_GT(state().stamp, moved.stamp);
  for (std::size_t i = 1; i < stamps.size(); ++i) EXPECT_GT(stamps[i], stamps[i - 1]) << "message " << i;
}

// ------------------------------------------------------------------ set / get

class SetGetState : public Node {};

TEST_F(SetGetState, RoundTripInEitherFrame) {
  ASSERT_TRUE(trigger("pause"));
  rigid_body_sim::SetState set;
  set.request.state.pose.position.x = 1;
  set.request.state.pose.position.y = 2;
  set.request.state.pose.position.z = 3;
  set.request.state.pose.orientation.z = std::sqrt(0.5);  // 90° about z, (x, y, z, w)
  set.request.state.pose.orientation.w = std::sqrt(0.5);
  set.request.state.twist.linear = vec(0.1, 0.2, 0.3);
  set.request.state.twist.angular = vec(0.4, 0.5, 0.6);
  ASSERT_TRUE(call("set_state", set).response.success);
  const BodyState w = state();
  EXPECT_NEAR(w.pose.position.y, 2, 1e-12);
  EXPECT_NEAR(w.pose.orientation.z, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(w.twist.linear.x, 0.1, 1e-12);
  EXPECT_NEAR(w.twist.angular.z, 0.6, 1e-12);
  const BodyState b = state(kLink);  // body x = world y: a world (0.1, 0.2) is body (0.2, −0.1)
  EXPECT_EQ(b.twist_frame, kLink);
  EXPECT_NEAR(b.twist.linear.x, 0.2, 1e-12);
  EXPECT_NEAR(b.twist.linear.y, -0.1, 1e-12);
  // Setting the twist in the body frame.
  set.request.state.twist_frame = kLink;
  set.request.state.twist.linear = vec(1, 0, 0);
  set.request.state.twist.angular = vec(0, 0, 0);
  ASSERT_TRUE(call("set_state", set).response.success);
  EXPECT_NEAR(state().twist.linear.y, 1.0, 1e-12);
}

// ------------------------------------------------------------------ refusals

class BadRequests : public Node {};

TEST_F(BadRequests, AreRefusedWithAMessageAndChangeNothing) {
  ASSERT_TRUE(trigger("pause"));
  const BodyState before = state();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  auto refused = [&](bool success, const std::string& message, const std::string& what) {
    EXPECT_FALSE(success) << what;
    EXPECT_FALSE(message.empty()) << what;
    EXPECT_TRUE(plainAscii(message)) << what << ": " << message;
    const BodyState now = state();
    EXPECT_EQ(now.pose, before.pose) << what;
    EXPECT_EQ(now.twist, before.twist) << what;
  };
  auto w = wrench("world", vec(nan, 0, 0), 1.0);
  refused(w.success, w.message, "NaN force");
  EXPECT_NE(w.message.find("not finite"), std::string::npos) << w.message;
  w = wrench("world", vec(0, 0, 0), 1.0, vec(0, inf, 0));
  refused(w.success, w.message, "infinite torque");
  w = wrench("world", vec(1e9, 0, 0), 1.0);
  refused(w.success, w.message, "absurd force");
  w = wrench("map", vec(1, 0, 0), 1.0);
  refused(w.success, w.message, "unknown frame");
  EXPECT_NE(w.message.find("unknown frame 'map'"), std::string::npos) << w.message;
  w = wrench("world", vec(1, 0, 0), 0.0);
  refused(w.success, w.message, "zero duration");
  EXPECT_NE(w.message.find("apply_impulse"), std::string::npos) << w.message;
  rigid_body_sim::ApplyWrench other;
  other.request.body = "robot";
  other.request.duration = ros::Duration(1.0);
  other = call("apply_wrench", other);
  refused(other.response.success, other.response.message, "unknown body");
  auto i = impulse("world", vec(nan, 0, 0));
  refused(i.success, i.message, "NaN impulse");
  i = impulse("world", vec(0, 1e9, 0));
  refused(i.success, i.message, "absurd impulse");
  EXPECT_NE(i.message.find("N*s"), std::string::npos) << i.message;
  i = impulse("odom", vec(0, 1, 0));
  refused(i.success, i.message, "unknown impulse frame");
  rigid_body_sim::SetState set;  // an all-zero quaternion: not an orientation
  set.request.state.pose.position.z = 1;
  set = call("set_state", set);
  refused(set.response.success, set.response.message, "zero quaternion");
  set.request.state.pose.orientation.w = 1;
  set.request.state.pose.position.x = nan;
  set = call("set_state", set);
  refused(set.response.success, set.response.message, "NaN position");
  for (int n : {-1, 0, 2000000}) {
    const auto s = step(n);
    refused(s.success, s.message, "steps " + std::to_string(n));
  }
  // Nothing was scheduled either: stepping on leaves the body where it was
  // (no gravity in this test's config).
  ASSERT_TRUE(step(100).success);
  const BodyState later = state();
  EXPECT_EQ(later.pose, before.pose);
  EXPECT_EQ(later.twist, before.twist);
}

// ------------------------------------------------------------------ bad URDF: the node refuses to start

class BadUrdf : public ::testing::Test {};

/// Starts sim_node in namespace `ns` with `urdf` as its robot_description;
/// returns its exit code and everything it printed.
std::pair<int, std::string> runNode(const std::string& ns, const std::string& urdf, const std::string& extra = "",
                                    int timeout_s = 30) {
  ros::param::set(ns + "/robot_description", urdf);
  const std::string cmd =
      "timeout " + std::to_string(timeout_s) + " " + std::string(RBS_SIM_NODE) + " __ns:=" + ns + " " + extra + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  char buf[512];
  while (pipe != nullptr && fgets(buf, sizeof buf, pipe) != nullptr) out += buf;
  const int status = pipe != nullptr ? pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

const char* kInertia = "<inertia ixx='0.1' iyy='0.1' izz='0.1' ixy='0' ixz='0' iyz='0'/>";
const char* kCollision = "<collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision>";

TEST_F(BadUrdf, NodeExitsNamingTheProblem) {
  const std::string head = "<robot name='r'><link name='base'>";
  const struct {
    std::string name, urdf, expected;
  } cases[] = {
      // Neither a mass nor a <collision> to fill with one (with a <collision>
      // it is given the shape's mass of water: ARepairedUrdfStarts... below).
      {"no_inertial", head + "</link></robot>", "link 'base' has a total mass of 0 kg"},
      {"zero_mass",
       head + "<inertial><mass value='0'/><inertia ixx='0' iyy='0' izz='0' ixy='0' ixz='0' iyz='0'/></inertial>" +
           "</link></robot>",
       "total mass of 0 kg"},
      {"robot_massless_link",  // a robot (a moving joint) is read as one: its only joint moves nothing
       head + "<inertial><mass value='1'/>" + kInertia + "</inertial>" + kCollision +
           "</link><link name='wheel'/><joint name='axle' type='continuous'><parent link='base'/>"
           "<child link='wheel'/><axis xyz='0 0 1'/></joint></robot>",
       "robot 'r' has no revolute, continuous or prismatic joint that moves a mass"},
      {"mass_with_unit",
       head + "<inertial><mass value='1kg'/>" + kInertia + "</inertial>" + kCollision + "</link></robot>",
       "link 'base' <inertial><mass value=\"1kg\">: not a number"},
      {"not_xml", "this is not a robot", "not a valid URDF"},
  };
  for (const auto& c : cases) {
    const auto [code, out] = runNode("/" + c.name, c.urdf);
    EXPECT_EQ(code, 1) << c.name << ": " << out;
    EXPECT_NE(out.find("FATAL"), std::string::npos) << c.name << ": " << out;
    EXPECT_NE(out.find(c.expected), std::string::npos) << c.name << ": " << out;
  }
  // urdf.repair: false refuses what the default repairs, each naming its link.
  const struct {
    std::string name, urdf, expected;
  } strict[] = {
      {"strict_no_inertial", head + kCollision + "</link></robot>", "link 'base' has no <inertial>"},
      {"strict_bad_inertia",
       head + "<inertial><mass value='1'/><inertia ixx='1' iyy='1' izz='3' ixy='0' ixz='0' iyz='0'/></inertial>" +
           kCollision + "</link></robot>",
       "triangle inequality"},
  };
  for (const auto& c : strict) {
    ros::param::set("/" + c.name + "/sim_node/urdf/repair", false);
    const auto [code, out] = runNode("/" + c.name, c.urdf);
    EXPECT_EQ(code, 1) << c.name << ": " << out;
    EXPECT_NE(out.find(c.expected), std::string::npos) << c.name << ": " << out;
  }
  // A bad parameter stops it too, naming the key.
  const std::string good =
      head + "<inertial><mass value='1'/>" + kInertia + "</inertial>" + kCollision + "</link></robot>";
  ros::param::set("/bad_param/sim_node/dt", -0.001);
  const auto [code, out] = runNode("/bad_param", good);
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find("dt = -0.001"), std::string::npos) << out;
}

/// A robot on two wheels with `sensors` in its base's Gazebo markup.
std::string sensorRobot(const std::string& sensors) {
  const std::string inertial = std::string("<inertial><mass value='1'/>") + kInertia + "</inertial>";
  return "<robot name='r'><link name='base'>" + inertial + kCollision +
         "</link><joint name='axle' type='continuous'><parent link='base'/><child link='wheel'/>"
         "<axis xyz='0 1 0'/></joint><link name='wheel'>" +
         inertial + "</link><gazebo reference='base'>" + sensors + "</gazebo></robot>";
}
/// A ray sensor `name` of `fans` fans of 90 rays, on topic 'scan'.
std::string raySensor(const std::string& name, int fans) {
  return "<sensor type='ray' name='" + name +
         "'><ray><scan><horizontal><samples>90</samples><min_angle>-1</min_angle><max_angle>1</max_angle>"
         "</horizontal><vertical><samples>" +
         std::to_string(fans) +
         "</samples></vertical></scan><range><min>0.1</min><max>10</max></range></ray><plugin name='p' "
         "filename='libgazebo_ros_laser.so'><topicName>scan</topicName></plugin></sensor>";
}

// The lidars and cameras beyond devices.memory stop the node naming the
// key, before any is built (40 depth cameras ended it in std::bad_alloc).
TEST_F(BadUrdf, DevicesBeyondTheirMemoryStopTheNodeNamingThem) {
  // One lidar of 90 x 4000 rays (about 28 MiB) over a budget of 1 MiB.
  ros::param::set("/small_memory/sim_node/devices/memory", 1);
  const auto [code, out] = runNode("/small_memory", sensorRobot(raySensor("flat", 4000)));
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find("<sensor name=\"flat\">': the device would hold 28 MiB, and the devices may hold "
                     "devices.memory = 1 MiB in all"),
            std::string::npos)
      << out;
}

// One topic, one publisher: two sensors on one topic stop the node naming
// both (roscpp logged "already advertised", the start-up line still claimed
// the topic, and the second sensor published nothing).
TEST_F(BadUrdf, TwoSensorsOnOneTopicStopTheNodeNamingBoth) {
  // A LaserScan and a PointCloud2 lidar on 'scan'.
  const auto [code, out] = runNode("/two_on_scan", sensorRobot(raySensor("flat", 1) + raySensor("tall", 4)));
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find("robot 'r': <gazebo reference=\"base\"> <sensor name=\"tall\">: topic '/two_on_scan/scan' is "
                     "also its <gazebo reference=\"base\"> <sensor name=\"flat\">'s (one topic, one publisher"),
            std::string::npos)
      << out;
  EXPECT_EQ(out.find("already advertised"), std::string::npos) << out;
}

TEST_F(BadUrdf, ARepairedUrdfStartsAndSaysWhatWasRepairedOnce) {
  // PR2's sensor mount (0.001 + 0.001 < 0.01) and a frame without
  // <inertial>: the node starts (and runs until the timeout ends it),
  // having said both in one warning.
  const std::string urdf =
      "<robot name='r'><link name='base'><inertial><mass value='1'/><inertia ixx='0.001' iyy='0.001' izz='0.01' "
      "ixy='0' ixz='0' iyz='0'/></inertial>" +
      std::string(kCollision) +
      "</link><link name='tool'/><joint name='j' type='fixed'><parent link='base'/><child link='tool'/></joint>"
      "</robot>";
  ros::param::set("/repaired/sim_node/initial/position", std::vector<double>{0.0, 0.0, 1.0});
  const auto [code, out] = runNode("/repaired", urdf, "", 8);
  EXPECT_EQ(code, 124) << out;  // still running when the timeout stopped it
  EXPECT_EQ(out.find("FATAL"), std::string::npos) << out;
  const std::size_t first = out.find("loaded with repairs");
  ASSERT_NE(first, std::string::npos) << out;
  EXPECT_EQ(out.find("loaded with repairs", first + 1), std::string::npos) << "said twice: " << out;
  const std::string line = out.substr(first, out.find('\n', first) - first);
  for (const char* part : {"1 link without <inertial> is a massless frame ('tool')",
                           "'base' [0.001, 0.001, 0.01] -> [0.00367, 0.00367, 0.00733]"}) {
    EXPECT_NE(line.find(part), std::string::npos) << part << " not in: " << line;
  }
}

TEST_F(BadUrdf, ARobotHeldByTheSpeedLimitsIsSaidOnce) {
  // The rod pendulum released from 1.5 rad swings at up to 7.7 rad/s
  // (ω² = 2 m g l_c (1 − cos q₀) / I, I = 1/12 + 1/16 kg m² about the
  // pivot); with limits.max_angular_speed 5 rad/s the limits hold it, as a
  // body's, and the node says so once (it said nothing of robots before).
  // urdf/pendulum.urdf: a 0.5 m, 1 kg rod hanging from a pivot 1 m up, about y.
  const std::string pendulum =
      "<robot name='pendulum'><link name='world'/><joint name='pivot' type='continuous'><parent link='world'/>"
      "<child link='rod'/><origin xyz='0 0 1'/><axis xyz='0 1 0'/></joint><link name='rod'><inertial>"
      "<origin xyz='0 0 -0.25'/><mass value='1'/><inertia ixx='0.0208333' iyy='0.0208333' izz='1e-5' ixy='0' "
      "ixz='0' iyz='0'/></inertial></link></robot>";
  ros::param::set("/limited/sim_node/limits/max_angular_speed", 5.0);
  ros::param::set("/limited/sim_node/initial/joint_positions/pivot", 1.5);
  ros::param::set("/limited/sim_node/realtime_factor", 0.0);  // as fast as it goes
  const auto [code, out] = runNode("/limited", pendulum, "", 8);
  EXPECT_EQ(code, 124) << out;  // still running when the timeout stopped it
  EXPECT_EQ(out.find("FATAL"), std::string::npos) << out;
  const std::string said = "robot 'pendulum' reached the speed limits";
  const std::size_t first = out.find(said);
  ASSERT_NE(first, std::string::npos) << out;
  EXPECT_EQ(out.find(said, first + 1), std::string::npos) << "said twice:\n" << out;
}

TEST_F(BadUrdf, BadDevicesStopTheNodeNamingTheKey) {
  // A body's imu, odom_noise and cmd_vel (issue 15): a zero rate, a negative
  // sigma, a sensor frame that is the body's own, an unknown link to mount
  // it on, a zero force limit.
  const std::string good = "<robot name='r'><link name='base'><inertial><mass value='1'/>" + std::string(kInertia) +
                           "</inertial>" + kCollision + "</link></robot>";
  const struct {
    std::string ns, device, key;
    XmlRpc::XmlRpcValue value;
    std::string expected;
  } cases[] = {
      {"/imu_rate", "imu", "rate", 0.0, "imu.rate = 0"},
      {"/imu_slow", "imu", "rate", 1e-300, "imu.rate = 1e-300"},  // it overflowed the step counter
      {"/imu_noise", "imu", "gyro_noise", -0.1, "imu.gyro_noise = -0.1"},
      {"/imu_frame", "imu", "frame_id", "base", "imu.frame_id 'base' of body 'base': is already a frame"},
      {"/imu_link", "imu", "link", "mast", "config key 'imu.link' = 'mast': no such link of body 'base'"},
      {"/odom_sigma", "odom_noise", "position", -1.0, "odom_noise.position = -1"},
      {"/drive", "cmd_vel", "max_force", 0.0, "cmd_vel.max_force = 0"},
  };
  for (const auto& c : cases) {
    ros::param::set(c.ns + "/sim_node/" + c.device + "/" + c.key, c.value);
    const auto [code, out] = runNode(c.ns, good);
    EXPECT_EQ(code, 1) << c.ns << ": " << out;
    EXPECT_NE(out.find(c.expected), std::string::npos) << c.ns << ": " << out;
  }
}

// The config file sim.launch loads with <rosparam> (~config_file) is read
// once more as rbsim reads it: the parameter server cannot show a key given
// twice (PyYAML kept the last: {p: 1, p: 2} ran with p = 2) or an alias
// bomb (the server holds it expanded).
TEST_F(BadUrdf, TheConfigFileIsReadAsRbsimReadsIt) {
  const std::string good = "<robot name='r'><link name='base'><inertial><mass value='1'/>" + std::string(kInertia) +
                           "</inertial>" + kCollision + "</link></robot>";
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";  // 10 aliases of 10 of ... : 10^9 nodes
  for (int i = 1; i < 9; ++i) {
    bomb += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) bomb += std::string(k ? ", " : "") + "*a" + std::to_string(i - 1);
    bomb += "]\n";
  }
  const struct {
    std::string ns, yaml, expected;
  } cases[] = {
      {"/twice", "dt: 0.001\nrealtime_factor: 1.0\ndt: 0.002\n", "line 3: key 'dt' appears twice in one map"},
      {"/alias", bomb, "line 5: aliases (*name) repeat more than 100000 nodes"},
  };
  for (const auto& c : cases) {
    const std::string path = ::testing::TempDir() + "rbs_config" + c.ns.substr(1) + ".yaml";
    std::ofstream(path) << c.yaml;
    ros::param::set(c.ns + "/sim_node/config_file", path);
    const auto [code, out] = runNode(c.ns, good);
    EXPECT_EQ(code, 1) << c.ns << ": " << out;
    EXPECT_NE(out.find(c.expected), std::string::npos) << c.ns << ": " << out;
    EXPECT_NE(out.find(path), std::string::npos) << c.ns << ": " << out;
  }
  // The same file written once, as roslaunch would load it, starts.
  const std::string path = ::testing::TempDir() + "rbs_config_once.yaml";
  std::ofstream(path) << "dt: 0.001\n";
  ros::param::set("/once/sim_node/config_file", path);
  ros::param::set("/once/sim_node/dt", 0.001);
  const auto [code, out] = runNode("/once", good, "", 3);
  EXPECT_EQ(code, 124) << "ran until the timeout: " << out;  // timeout(1)'s code
}

TEST_F(BadUrdf, TimingParametersOutOfRangeStopTheNodeNamingTheKey) {
  // Each was accepted: 1e-9 Hz slept 30 years between ticks (no service, no
  // SIGINT), 1e-300 and 1e300 spun at full CPU, wrench_timeout -1 silently
  // meant forever, and a world frame equal to the body's gave tf base → base.
  const std::string good = "<robot name='r'><link name='base'><inertial><mass value='1'/>" + std::string(kInertia) +
                           "</inertial>" + kCollision + "</link></robot>";
  const struct {
    std::string ns, key;
    XmlRpc::XmlRpcValue value;
    std::string expected;
  } cases[] = {
      {"/slow", "rate", 1e-9, "parameter '~rate' = 1e-09: must be within [1, 10000] Hz"},
      {"/tiny", "rate", 1e-300, "parameter '~rate' = 1e-300"},
      {"/fast", "rate", 1e300, "parameter '~rate' = 1e+300"},
      {"/publish", "publish_rate", 1e-300, "parameter '~publish_rate' = 1e-300: must be within [0.01, 10000] Hz"},
      // 1e-300 froze the simulation without a word.
      {"/frozen", "realtime_factor", 1e-300,
       "parameter '~realtime_factor' = 1e-300: must be 0 (as fast as possible) or within [0.001, 1000]"},
      {"/timeout", "wrench_timeout", -1.0, "parameter '~wrench_timeout' = -1: must be within [0, 1e+06]"},
      {"/frame", "world_frame", "base", "parameter '~world_frame' = 'base': is also a frame of body 'base'"},
  };
  for (const auto& c : cases) {
    ros::param::set(c.ns + "/sim_node/" + c.key, c.value);
    const auto [code, out] = runNode(c.ns, good);
    EXPECT_EQ(code, 1) << c.ns << ": " << out;
    EXPECT_NE(out.find(c.expected), std::string::npos) << c.ns << ": " << out;
  }
}

/// Fails loudly when a .test's --gtest_filter names no suite of this file
/// (gtest would otherwise run nothing and report success).
class UnknownSuite : public ::testing::Test {
 public:
  explicit UnknownSuite(std::string filter) : filter_(std::move(filter)) {}
  void TestBody() override { FAIL() << "--gtest_filter=" << filter_ << " selects no test of node_test"; }

 private:
  std::string filter_;
};

void checkFilterSelectsSomething() {
  const std::string filter = ::testing::GTEST_FLAG(filter);
  const std::string suite = filter.substr(0, filter.find('.'));
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  for (int i = 0; i < unit.total_test_suite_count(); ++i) {
    if (filter == "*" || unit.GetTestSuite(i)->name() == suite) return;
  }
  ::testing::RegisterTest("Selection", "UnknownSuite", nullptr, nullptr, __FILE__, __LINE__,
                          [filter]() -> ::testing::Test* { return new UnknownSuite(filter); });
  ::testing::GTEST_FLAG(filter) = "Selection.UnknownSuite";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  checkFilterSelectsSomething();
  ros::init(argc, argv, "node_test", ros::init_options::AnonymousName);
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
