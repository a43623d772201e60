// Several bodies in one node: names, frames, topics, loads given in another
// body's axes, their markers, and a config whose relative URDF paths resolve
// from its own folder. world.test and world_config.test run these.
#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <complex>
#include <map>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/BodyStates.h"
#include "rigid_body_sim/ClearWrenches.h"
#include "rigid_body_sim/SetState.h"
#include "rigid_body_sim/SpawnBody.h"

namespace {

using namespace rbs_test;

class World : public Node {};

TEST_F(World, EachBodyHasItsFrameTopicAndName) {
  ASSERT_TRUE(trigger("pause"));
  rigid_body_sim::GetState get;
  get = call("get_state", get);  // no body named: refused, listing them
  EXPECT_FALSE(get.response.success);
  EXPECT_NE(get.response.message.find("'crate', 'ball'"), std::string::npos) << get.response.message;
  get.request.body = "ball";
  get = call("get_state", get);
  ASSERT_TRUE(get.response.success) << get.response.message;
  EXPECT_EQ(get.response.state.body, "ball");
  EXPECT_EQ(get.response.state.pose.position.x, 2.0);
  // An impulse on the ball moves the ball only (M = 1 kg each).
  rigid_body_sim::ApplyImpulse kick;
  kick.request.body = "ball";
  kick.request.frame = "ball/ball";  // the ball's frame, under its name
  kick.request.linear = vec(0, 0.5, 0);
  ASSERT_TRUE(call("apply_impulse", kick).response.success);
  ASSERT_TRUE(step(100).success);
  rigid_body_sim::GetState crate;
  crate.request.body = "crate";
  crate = call("get_state", crate);
  get = call("get_state", get);
  EXPECT_NEAR(get.response.state.twist.linear.y, 0.5, 1e-12);
  EXPECT_NEAR(get.response.state.pose.position.y, 0.05, 1e-12);
  EXPECT_EQ(crate.response.state.twist.linear.y, 0.0);
  // Each has its odometry topic and its tf frame.
  std::map<std::string, nav_msgs::Odometry> odom;
  const ros::Subscriber a = nh_.subscribe<nav_msgs::Odometry>(
      "/crate/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& m) { odom["crate"] = *m; });
  const ros::Subscriber b = nh_.subscribe<nav_msgs::Odometry>(
      "/ball/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& m) { odom["ball"] = *m; });
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  ASSERT_TRUE(spinUntil([&] { return a.getNumPublishers() > 0 && b.getNumPublishers() > 0; }, 10.0));
  ros::WallDuration(0.3).sleep();
  ASSERT_TRUE(trigger("unpause"));
  ASSERT_TRUE(spinUntil([&] { return odom.size() == 2; }, 10.0));
  EXPECT_EQ(odom["crate"].child_frame_id, "crate/base_link");
  EXPECT_EQ(odom["ball"].child_frame_id, "ball/ball");
  ASSERT_TRUE(spinUntil([&] { return buffer.canTransform("world", "ball/ball", ros::Time(0)); }, 10.0));
  EXPECT_NEAR(buffer.lookupTransform("world", "ball/ball", ros::Time(0)).transform.translation.x, 2.0, 1e-12);
}

// Each state update reaches /tf as one message holding every body at one
// stamp, as robot_state_publisher sends a robot's links: a listener never
// holds one body at a newer time than another, and the node makes one
// publish() per update instead of one per body (bench/HISTORY.md, the node
// with N bodies).
TEST_F(World, OneTfMessageCarriesEveryBodyAtOneStamp) {
  std::vector<tf2_msgs::TFMessage> got;
  const ros::Subscriber sub = nh_.subscribe<tf2_msgs::TFMessage>(
      "/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& m) { got.push_back(*m); });
  ASSERT_TRUE(spinUntil([&] { return sub.getNumPublishers() > 0; }, 10.0));
  ASSERT_TRUE(trigger("unpause"));
  ASSERT_TRUE(spinUntil([&] { return got.size() >= 5; }, 10.0));
  for (const tf2_msgs::TFMessage& m : got) {
    ASSERT_EQ(m.transforms.size(), 2u);
    EXPECT_EQ(m.transforms[0].child_frame_id, "crate/base_link");
    EXPECT_EQ(m.transforms[1].child_frame_id, "ball/ball");
    EXPECT_EQ(m.transforms[0].header.stamp, m.transforms[1].header.stamp);
    EXPECT_EQ(m.transforms[0].header.frame_id, "world");
  }
  EXPECT_LT(got.front().transforms[0].header.stamp, got.back().transforms[0].header.stamp);
}

// The node counts each odometry topic's subscribers itself and builds no
// message no one would get (counted_publisher.h). A subscriber who leaves
// and comes back, or a second one beside the first, is counted again.
TEST_F(World, OdomReachesSubscribersThatLeaveAndComeBack) {
  ASSERT_TRUE(trigger("unpause"));
  int first = 0, second = 0;
  for (int round = 0; round < 2; ++round) {
    first = 0;
    ros::Subscriber sub =
        nh_.subscribe<nav_msgs::Odometry>("/ball/odom", 10, [&](const nav_msgs::Odometry::ConstPtr&) { ++first; });
    ASSERT_TRUE(spinUntil([&] { return first >= 3; }, 10.0)) << "round " << round;
    sub.shutdown();
  }
  ros::Subscriber a =
      nh_.subscribe<nav_msgs::Odometry>("/ball/odom", 10, [&](const nav_msgs::Odometry::ConstPtr&) { ++first; });
  ros::Subscriber b =
      nh_.subscribe<nav_msgs::Odometry>("/ball/odom", 10, [&](const nav_msgs::Odometry::ConstPtr&) { ++second; });
  ASSERT_TRUE(spinUntil([&] { return first >= 3 && second >= 3; }, 10.0));
  a.shutdown();  // the other stays: still counted
  second = 0;
  EXPECT_TRUE(spinUntil([&] { return second >= 3; }, 10.0));
}

TEST_F(World, AnotherBodysFrameGivesTheAxesAndTurnsWithIt) {
  ASSERT_TRUE(trigger("pause"));
  // The crate turned a quarter about z, spinning at 2 rad/s about z (a
  // principal axis: the spin stays steady). Its x axis starts along world y.
  const double w = 2.0;
  rigid_body_sim::SetState set;
  set.request.body = "crate";
  set.request.state.pose.position.z = 1.0;
  set.request.state.pose.orientation.z = std::sqrt(0.5);
  set.request.state.pose.orientation.w = std::sqrt(0.5);
  set.request.state.twist.angular = vec(0, 0, w);
  ASSERT_TRUE(call("set_state", set).response.success);
  rigid_body_sim::SetState still;  // the ball at rest, 2 m away (the last test pushed it)
  still.request.body = "ball";
  still.request.state.pose.position.x = 2.0;
  still.request.state.pose.position.z = 1.0;
  still.request.state.pose.orientation.w = 1.0;
  ASSERT_TRUE(call("set_state", still).response.success);
  // An impulse on the ball along the crate's x axis moves it along world y.
  rigid_body_sim::ApplyImpulse kick;
  kick.request.body = "ball";
  kick.request.frame = "crate/base_link";
  kick.request.linear = vec(0.5, 0, 0);
  kick = call("apply_impulse", kick);
  ASSERT_TRUE(kick.response.success) << kick.response.message;
  rigid_body_sim::GetState ball;
  ball.request.body = "ball";
  ball = call("get_state", ball);
  EXPECT_NEAR(ball.response.state.twist.linear.x, 0.0, 1e-12);
  EXPECT_NEAR(ball.response.state.twist.linear.y, 0.5, 1e-12);
  // Its twist read in the crate's axes: along x.
  ball.request.frame = "crate/base_link";
  ball = call("get_state", ball);
  ASSERT_TRUE(ball.response.success) << ball.response.message;
  EXPECT_EQ(ball.response.state.twist_frame, "crate/base_link");
  EXPECT_NEAR(ball.response.state.twist.linear.x, 0.5, 1e-12);
  EXPECT_NEAR(ball.response.state.twist.linear.y, 0.0, 1e-12);
  // 1 N along the crate's x axis for 0.5 s turns with the crate: each step
  // pushes where the crate points at its start, and a step turns the crate
  // by θ = 2 atan(Δt w / 2), so the ball (1 kg) gains
  // Δv = Δt F Σₖ e^{i(π/2 + kθ)} over the 500 steps.
  rigid_body_sim::ApplyWrench push;
  push.request.body = "ball";
  push.request.frame = "crate/base_link";
  push.request.force = vec(1, 0, 0);
  push.request.duration = ros::Duration(0.5);
  push = call("apply_wrench", push);
  ASSERT_TRUE(push.response.success) << push.response.message;
  ASSERT_TRUE(step(510).success);
  ball.request.frame = "";
  ball = call("get_state", ball);
  const double theta = 2.0 * std::atan(0.5 * kDt * w);
  std::complex<double> sum = 0.0;
  for (int k = 0; k < 500; ++k) sum += std::polar(1.0, M_PI / 2 + k * theta);
  EXPECT_NEAR(ball.response.state.twist.linear.x, kDt * sum.real(), 1e-9);
  EXPECT_NEAR(ball.response.state.twist.linear.y - 0.5, kDt * sum.imag(), 1e-9);
  EXPECT_LT(ball.response.state.twist.linear.x, -0.1);  // it turned: a fixed direction would leave x at 0
  // The ball's ~wrench topic takes the crate's frame too: the crate held
  // still with its x axis along world y, 2 N for 100 steps gives 0.2 m/s along y.
  set.request.state.twist.angular = vec(0, 0, 0);
  ASSERT_TRUE(call("set_state", set).response.success);
  ASSERT_TRUE(call("set_state", still).response.success);
  ros::Publisher pub = nh_.advertise<geometry_msgs::WrenchStamped>("/sim_node/ball/wrench", 1, true);
  ASSERT_TRUE(spinUntil([&] { return pub.getNumSubscribers() > 0; }, 10.0));
  geometry_msgs::WrenchStamped held;
  held.header.frame_id = "crate/base_link";
  held.wrench.force.x = 2.0;
  pub.publish(held);
  ros::WallDuration(0.3).sleep();  // delivered before the steps
  ASSERT_TRUE(step(100).success);
  rigid_body_sim::ClearWrenches clear;
  clear.request.body = "ball";
  ASSERT_TRUE(call("clear_wrenches", clear).response.success);
  ball = call("get_state", ball);
  EXPECT_NEAR(ball.response.state.twist.linear.x, 0.0, 1e-12);
  EXPECT_NEAR(ball.response.state.twist.linear.y, 0.2, 1e-12);
  // A frame that is nobody's is refused, naming what is allowed.
  kick.request.frame = "crate/lid";
  kick = call("apply_impulse", kick);
  EXPECT_FALSE(kick.response.success);
  EXPECT_NE(kick.response.message.find("another body's tf frame"), std::string::npos) << kick.response.message;
}

TEST_F(World, MarkersDrawEachBodyInItsOwnFrame) {
  const visualization_msgs::MarkerArray markers = latchedMarkers("/sim_node/body_markers");
  ASSERT_EQ(markers.markers.size(), 2u);
  // The crate's <collision> box, 0.4 × 0.2 × 0.1 m at its link's origin, drawn
  // in its frame; rviz moves it with tf.
  const auto& crate = markers.markers[0];
  EXPECT_EQ(crate.ns, "crate");
  EXPECT_EQ(crate.header.frame_id, "crate/base_link");
  EXPECT_TRUE(crate.frame_locked);
  EXPECT_EQ(crate.type, visualization_msgs::Marker::CUBE);
  EXPECT_NEAR(crate.scale.x, 0.4, 1e-12);
  EXPECT_NEAR(crate.scale.y, 0.2, 1e-12);
  EXPECT_NEAR(crate.scale.z, 0.1, 1e-12);
  EXPECT_NEAR(crate.pose.position.x, 0.0, 1e-12);
  EXPECT_NEAR(crate.pose.position.z, 0.0, 1e-12);
  EXPECT_NEAR(std::abs(crate.pose.orientation.w), 1.0, 1e-12);
  const auto& ball = markers.markers[1];
  EXPECT_EQ(ball.ns, "ball");
  EXPECT_EQ(ball.header.frame_id, "ball/ball");
  EXPECT_EQ(ball.type, visualization_msgs::Marker::SPHERE);
  EXPECT_NEAR(ball.scale.x, 0.2, 1e-12);  // radius 0.1 m
  EXPECT_NEAR(ball.scale.z, 0.2, 1e-12);
}

class ConfigOutside : public Node {};

TEST_F(ConfigOutside, RelativeUrdfPathsResolveFromTheConfigsFolder) {
  // world_config.test launches world.launch with a config written outside
  // the package, next to a urdf/ folder; its crate names "urdf/crate.urdf".
  rigid_body_sim::GetState get;
  get.request.body = "crate";
  get = call("get_state", get);
  ASSERT_TRUE(get.response.success) << get.response.message;
  EXPECT_EQ(get.response.state.pose.position.x, 3.0);  // the config's initial pose
  get.request.body = "ball";                           // and a package:// one beside it
  get = call("get_state", get);
  ASSERT_TRUE(get.response.success) << get.response.message;
}

// A world larger than ~per_body_topics (big_world.test: three bodies, the
// limit two): no odometry or wrench topic for a body without a device, its
// topics for the one with cmd_vel; ~body_states, tf and the services carry
// every body, and a spawned body has its topics.
class BigWorld : public Node {};

TEST_F(BigWorld, OnlyBodiesWithADeviceHaveTheirTopics) {
  ASSERT_TRUE(spinUntil([] { return advertised("/cart/odom"); }, 30.0));
  EXPECT_FALSE(advertised("/crate/odom"));
  EXPECT_FALSE(advertised("/ball/odom"));
  ros::master::V_TopicInfo topics;
  ros::master::getTopics(topics);
  for (const auto& t : topics) EXPECT_EQ(t.name.find("/sim_node/crate/"), std::string::npos) << t.name;
  std::map<std::string, int> seen;
  const ros::Subscriber states = nh_.subscribe<rigid_body_sim::BodyStates>(
      "/sim_node/body_states", 10, [&](const rigid_body_sim::BodyStates::ConstPtr& m) {
        for (const std::string& name : m->names) ++seen[name];
      });
  ASSERT_TRUE(trigger("unpause"));
  ASSERT_TRUE(spinUntil([&] { return seen.size() == 3; }, 10.0));
  rigid_body_sim::ApplyImpulse kick;  // services address every body
  kick.request.body = "crate";
  kick.request.linear = vec(0, 0.5, 0);
  EXPECT_TRUE(call("apply_impulse", kick).response.success);
  rigid_body_sim::SpawnBody spawn;
  spawn.request.name = "probe";
  spawn.request.urdf_file = "package://rigid_body_sim/urdf/ball.urdf";
  spawn.request.pose.position.x = 5.0;
  spawn.request.pose.orientation.w = 1.0;
  spawn = call("spawn_body", spawn);
  ASSERT_TRUE(spawn.response.success) << spawn.response.message;
  EXPECT_TRUE(spinUntil([] { return advertised("/probe/odom"); }, 10.0));
}

}  // namespace
