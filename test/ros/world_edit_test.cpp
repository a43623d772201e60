// Spawning and deleting bodies through the node (issue 14), as a subscriber
// and a service client see it: spawn.test (an empty world filled by the
// spawn_body script and the service), names.test (a one-body world gains a
// second), delete.test (a body goes; what rested on it falls; the last one
// leaves an empty world that steps), edit_determinism.test (two nodes, the
// same requests at the same sim times: the same bits).
#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/Imu.h>
#include <tf2_msgs/TFMessage.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/BodyStates.h"
#include "rigid_body_sim/DeleteBody.h"
#include "rigid_body_sim/SetState.h"
#include "rigid_body_sim/SpawnBody.h"

namespace rbs_test {
namespace {

using rigid_body_sim::DeleteBody;
using rigid_body_sim::SpawnBody;

const std::string kBall = "package://rigid_body_sim/urdf/ball.urdf";
const std::string kBox = "package://rigid_body_sim/urdf/box.urdf";

SpawnBody::Request spawnRequest(const std::string& name, const std::string& urdf_file, double x, double y, double z) {
  SpawnBody::Request req;
  req.name = name;
  req.urdf_file = urdf_file;
  req.pose.position.x = x;
  req.pose.position.y = y;
  req.pose.position.z = z;
  req.pose.orientation.w = 1.0;
  return req;
}

/// The first message on `topic` after `trigger` runs (trigger may be empty),
/// waiting up to `seconds` for a publisher and again for the message.
template <class Msg>
Msg nextMessage(ros::NodeHandle& nh, const std::string& topic, const std::function<void()>& trigger = {},
                double seconds = 10.0) {
  Msg msg;
  bool got = false;
  const ros::Subscriber sub = nh.subscribe<Msg>(topic, 10, [&](const typename Msg::ConstPtr& m) {
    msg = *m;
    got = true;
  });
  EXPECT_TRUE(spinUntil([&] { return sub.getNumPublishers() > 0; }, seconds)) << topic;
  if (trigger) trigger();
  EXPECT_TRUE(spinUntil([&] { return got; }, seconds)) << topic;
  return msg;
}

/// Bit-for-bit equality of the doubles of two poses or twists.
bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}
bool sameBits(const geometry_msgs::Pose& a, const geometry_msgs::Pose& b) {
  const auto values = [](const geometry_msgs::Pose& p) {
    return std::vector<double>{p.position.x,    p.position.y,    p.position.z,   p.orientation.x,
                               p.orientation.y, p.orientation.z, p.orientation.w};
  };
  return sameBits(values(a), values(b));
}
bool sameBits(const geometry_msgs::Twist& a, const geometry_msgs::Twist& b) {
  const auto values = [](const geometry_msgs::Twist& t) {
    return std::vector<double>{t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z};
  };
  return sameBits(values(a), values(b));
}

class WorldEdit : public Node {
 protected:
  SpawnBody::Response spawn(const SpawnBody::Request& req) {
    SpawnBody srv;
    srv.request = req;
    EXPECT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
    return call("spawn_body", srv).response;
  }
  DeleteBody::Response remove(const std::string& name) {
    DeleteBody srv;
    srv.request.name = name;
    return call("delete_body", srv).response;
  }
  rigid_body_sim::GetState::Response get(const std::string& body, const std::string& frame = "") {
    rigid_body_sim::GetState srv;
    srv.request.body = body;
    srv.request.frame = frame;
    return call("get_state", srv).response;
  }
  /// ~body_states after a step of the paused node.
  rigid_body_sim::BodyStates bodyStates() {
    return nextMessage<rigid_body_sim::BodyStates>(nh_, "/sim_node/body_states", [&] { step(10); });
  }
  std::vector<std::string> names() { return bodyStates().names; }
  /// The child frames /tf carries over `steps` steps of the paused node.
  std::set<std::string> tfFrames(int steps) {
    std::set<std::string> frames;
    const ros::Subscriber sub =
        nh_.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
          for (const auto& t : m->transforms) frames.insert(t.child_frame_id);
        });
    EXPECT_TRUE(spinUntil([&] { return sub.getNumPublishers() > 0; }, 10.0));
    step(steps);
    spinUntil([] { return false; }, 0.5);
    return frames;
  }
};

// ------------------------------------------------------------ spawn.test

class NodeSpawn : public WorldEdit {};

TEST_F(NodeSpawn, TheScriptSpawnsAsGazebosSpawnModelDoes) {
  // spawn.test: `spawn_body -urdf -param crate_description -model crate -x 1
  // -y 2 -z 0.5 -Y pi/2 -unpause` into an empty, paused world without
  // gravity. Odometry comes only from steps: it flows once unpaused.
  // (the script spawns it as the test starts: up to 30 s for it to come)
  const auto odom = nextMessage<nav_msgs::Odometry>(nh_, "/crate/odom", {}, 30.0);
  EXPECT_EQ(odom.child_frame_id, "crate/base_link");
  EXPECT_NEAR(odom.pose.pose.position.x, 1.0, 1e-12);
  EXPECT_NEAR(odom.pose.pose.position.y, 2.0, 1e-12);
  EXPECT_NEAR(odom.pose.pose.position.z, 0.5, 1e-12);
  EXPECT_NEAR(odom.pose.pose.orientation.z, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(odom.pose.pose.orientation.w, std::sqrt(0.5), 1e-12);
}

TEST_F(NodeSpawn, TheScriptPutsARobotInItsRobotNamespaceAndReadsItsControllersThere) {
  // spawn.test: in group arm_ns, `spawn_body -urdf -param robot_description
  // -model arm -robot_namespace arm_ns`, the controller `hold` loaded there.
  EXPECT_TRUE(spinUntil(
      [] { return advertised("/arm_ns/joint_states") && subscribes("/sim_node", "/arm_ns/hold/command"); }, 30.0));
  EXPECT_FALSE(advertised("/arm/joint_states"));
}

TEST_F(NodeSpawn, WithoutARobotNamespaceTheScriptGivesARobotItsOwnAsSpawnModelDoes) {
  // spawn.test: at the launch's top, `spawn_body -urdf -param
  // two_link_description -model two_link`, the controller `elbow_hold`
  // loaded at the root, as ur_gazebo's launch spawns a UR arm (Gazebo gives
  // every plugin spawn_model's namespace, /): its topics at the root, its
  // controllers read there.
  EXPECT_TRUE(
      spinUntil([] { return advertised("/joint_states") && subscribes("/sim_node", "/elbow_hold/command"); }, 30.0));
  EXPECT_FALSE(advertised("/two_link/joint_states"));
  // spawn.test's gp_rover, whose markup names /gp for gazebo_ros_control:
  // its joint_states and drive there, as Gazebo keeps a plugin's own
  // robotNamespace; its p3d odometry, whose plugin names none, at the root.
  EXPECT_TRUE(spinUntil(
      [] { return advertised("/gp/joint_states") && advertised("/gp/odom") && advertised("/ground_truth/state"); },
      30.0));
  EXPECT_FALSE(advertised("/gp_rover/joint_states"));
}

TEST_F(NodeSpawn, TheScriptTakesAFileAndRollPitchYawAsUrdfDoes) {
  // spawn.test: `spawn_body -urdf -file package://.../ball.urdf -model rolled
  // -x -3 -R 0.3 -P 0.2 -Y 0.1`: q = Rz(yaw) Ry(pitch) Rx(roll).
  // (the script spawns it as the test starts: up to 30 s for it to come)
  const auto odom = nextMessage<nav_msgs::Odometry>(nh_, "/rolled/odom", {}, 30.0);
  const Eigen::Quaterniond q = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX());
  EXPECT_NEAR(odom.pose.pose.position.x, -3.0, 1e-12);
  EXPECT_NEAR(odom.pose.pose.orientation.x, q.x(), 1e-12);
  EXPECT_NEAR(odom.pose.pose.orientation.y, q.y(), 1e-12);
  EXPECT_NEAR(odom.pose.pose.orientation.z, q.z(), 1e-12);
  EXPECT_NEAR(odom.pose.pose.orientation.w, q.w(), 1e-12);
}

TEST_F(NodeSpawn, ASpawnedBodyExistsFromTheNextStepForEveryTopicAndService) {
  ASSERT_TRUE(spinUntil([] { return advertised("/crate/odom"); }, 30.0));
  ASSERT_TRUE(trigger("pause"));
  // Half a metre ahead of the crate (turned 90 degrees about z, at (1, 2, 0.5)),
  // moving at 1 m/s along the crate's x: in the world (1, 2.5, 0.5) and +y.
  SpawnBody::Request req = spawnRequest("ball", kBall, 0.5, 0.0, 0.0);
  req.frame = "crate/base_link";
  req.twist.linear.x = 1.0;
  req.imu = "{rate: 100}";
  const SpawnBody::Response res = spawn(req);
  ASSERT_TRUE(res.success) << res.message;
  EXPECT_NE(res.message.find("ball/ball"), std::string::npos) << res.message;
  // The response says it exists: every service addresses it at once.
  const auto got = get("ball");
  ASSERT_TRUE(got.success) << got.message;
  EXPECT_NEAR(got.state.pose.position.x, 1.0, 1e-12);
  EXPECT_NEAR(got.state.pose.position.y, 2.5, 1e-12);
  EXPECT_NEAR(got.state.twist.linear.x, 0.0, 1e-12);
  EXPECT_NEAR(got.state.twist.linear.y, 1.0, 1e-12);
  // Its odometry comes with the next step: one step of 1 m/s further.
  const auto odom = nextMessage<nav_msgs::Odometry>(nh_, "/ball/odom", [&] { step(10); });
  EXPECT_EQ(odom.child_frame_id, "ball/ball");
  const double moved = (odom.header.stamp - got.state.stamp).toSec();
  EXPECT_GT(moved, 0.0);
  EXPECT_NEAR(odom.pose.pose.position.y, 2.5 + moved * 1.0, 1e-9);
  EXPECT_EQ(tfFrames(20).count("ball/ball"), 1u);
  // Its IMU, under its name: in free flight without gravity it reads nothing.
  const auto imu = nextMessage<sensor_msgs::Imu>(nh_, "/ball/imu", [&] { step(20); });
  EXPECT_EQ(imu.header.frame_id, "ball/imu_link");
  EXPECT_NEAR(std::hypot(imu.linear_acceleration.x, imu.linear_acceleration.y, imu.linear_acceleration.z), 0.0, 1e-9);
  const auto markers = latchedMarkers("/sim_node/body_markers");
  bool drawn = false;
  for (const auto& m : markers.markers) drawn = drawn || (m.ns == "ball" && m.header.frame_id == "ball/ball");
  EXPECT_TRUE(drawn);
  // Its ~wrench topic pushes it: 2 N on 1 kg for 0.1 s adds 0.2 m/s along x.
  ros::Publisher pub = nh_.advertise<geometry_msgs::WrenchStamped>("/sim_node/ball/wrench", 1);
  ASSERT_TRUE(spinUntil([&] { return pub.getNumSubscribers() > 0; }, 10.0));
  geometry_msgs::WrenchStamped w;
  w.header.frame_id = "world";
  w.wrench.force.x = 2.0;
  pub.publish(w);
  spinUntil([] { return false; }, 0.5);  // for the node to take it in
  step(100);
  const double before = get("ball").state.twist.linear.x;
  EXPECT_NEAR(before, 0.2, 1e-9);
}

/// The child frames of the latched /tf_static a new subscriber gets (none
/// when no body has fixed links: then nothing is latched).
std::set<std::string> staticFrames(ros::NodeHandle& nh) {
  std::set<std::string> frames;
  const ros::Subscriber sub =
      nh.subscribe<tf2_msgs::TFMessage>("/tf_static", 10, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
        for (const auto& t : m->transforms) frames.insert(t.child_frame_id);
      });
  EXPECT_TRUE(spinUntil([&] { return sub.getNumPublishers() > 0; }, 10.0));
  spinUntil([&] { return !frames.empty(); }, 2.0);
  return frames;
}

TEST_F(NodeSpawn, ASpawnedBodysFixedLinksAreOnTfStaticUntilItIsDeleted) {
  ASSERT_TRUE(spinUntil([] { return advertised("/crate/odom"); }, 30.0));
  ASSERT_TRUE(trigger("pause"));
  // two_boxes.urdf: base_link with second_box fixed to it.
  // An IMU mounted on the fixed link, 0.1 m above its origin (0.2 m along x
  // of the root link): its frame sits at (0.2, 0, 0.1) in the root link.
  SpawnBody::Request req = spawnRequest("pair", "package://rigid_body_sim/urdf/two_boxes.urdf", 0, -3, 0);
  req.imu = "{link: second_box, pose: {position: [0, 0, 0.1]}}";
  const SpawnBody::Response res = spawn(req);
  ASSERT_TRUE(res.success) << res.message;
  EXPECT_EQ(staticFrames(nh_).count("pair/second_box"), 1u);
  bool mounted = false;
  ros::Subscriber sub =
      nh_.subscribe<tf2_msgs::TFMessage>("/tf_static", 10, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
        for (const auto& t : m->transforms) {
          if (t.child_frame_id != "pair/imu_link") continue;
          mounted = t.header.frame_id == "pair/base_link" && std::abs(t.transform.translation.x - 0.2) < 1e-12 &&
                    std::abs(t.transform.translation.z - 0.1) < 1e-12;
        }
      });
  EXPECT_TRUE(spinUntil([&] { return mounted; }, 10.0));
  sub.shutdown();  // (a live subscription would hand a new one its cached latched message)
  ASSERT_TRUE(remove("pair").success);
  EXPECT_EQ(staticFrames(nh_).count("pair/second_box"), 0u);  // a late subscriber no longer gets it
  EXPECT_FALSE(get("pair").success);
}

TEST_F(NodeSpawn, BadRequestsAreRefusedNamingTheFieldAndChangeNothing) {
  ASSERT_TRUE(spinUntil([] { return advertised("/crate/odom"); }, 30.0));
  ASSERT_TRUE(trigger("pause"));
  const std::vector<std::string> before = names();
  const auto refused = [&](SpawnBody::Request req, const std::string& field) {
    const SpawnBody::Response res = spawn(req);
    EXPECT_FALSE(res.success) << field;
    EXPECT_EQ(res.message.rfind(field, 0), 0u) << "'" << res.message << "' should start with " << field;
  };
  const double nan = std::nan("");
  refused(spawnRequest("crate", kBox, 0, 0, 3), "name 'crate' is taken");
  refused(spawnRequest("two words", kBox, 0, 0, 3), "name 'two words'");
  refused(spawnRequest("", kBox, 0, 0, 3), "name is empty");
  SpawnBody::Request two = spawnRequest("extra", kBox, 0, 0, 3);
  two.urdf_param = "crate_description";
  refused(two, "urdf_xml, urdf_param, urdf_file: give exactly one (2 given)");
  refused(spawnRequest("extra", "", 0, 0, 3), "urdf_xml, urdf_param, urdf_file: give exactly one (0 given)");
  SpawnBody::Request xml = spawnRequest("extra", "", 0, 0, 3);
  xml.urdf_xml = "<robot name='r'><link name='l'/></robot>";  // no <inertial>
  refused(xml, "urdf_xml");
  SpawnBody::Request param = spawnRequest("extra", "", 0, 0, 3);
  param.urdf_param = "no_such_param";
  refused(param, "urdf_param '/no_such_param': not set");
  refused(spawnRequest("extra", "package://rigid_body_sim/urdf/none.urdf", 0, 0, 3), "urdf_file");
  refused(spawnRequest("extra", "urdf/box.urdf", 0, 0, 3), "urdf_file 'urdf/box.urdf' is a relative path");
  refused(spawnRequest("extra", kBox, nan, 0, 3), "pose.position is not finite");
  SpawnBody::Request turn = spawnRequest("extra", kBox, 0, 0, 3);
  turn.pose.orientation.w = 0.0;
  refused(turn, "pose.orientation is not a unit quaternion");
  SpawnBody::Request frame = spawnRequest("extra", kBox, 0, 0, 3);
  frame.frame = "nowhere";
  refused(frame, "frame: unknown frame 'nowhere'");
  SpawnBody::Request fast = spawnRequest("extra", kBox, 0, 0, 3);
  fast.twist.linear.x = 1e4;
  refused(fast, "twist.linear is above the speed limit");
  SpawnBody::Request grip = spawnRequest("extra", kBox, 0, 0, 3);
  grip.own_friction = true;
  grip.friction = -1.0;
  refused(grip, "friction = -1");
  SpawnBody::Request bounce = spawnRequest("extra", kBox, 0, 0, 3);
  bounce.own_restitution = true;
  bounce.restitution = nan;
  refused(bounce, "restitution = nan");
  SpawnBody::Request imu = spawnRequest("extra", kBox, 0, 0, 3);
  imu.imu = "{rate: 0}";
  refused(imu, "imu: config key imu.rate = 0");
  imu.imu = "{frame_id: base_link}";
  refused(imu, "imu.frame_id 'base_link' of body 'extra': is already a frame");
  // An IMU on no such link: refused on the spawn thread, where the loop once threw it and ended the node.
  imu.imu = "{link: nope}";
  refused(imu, "config key 'imu.link' = 'nope': no such link of body 'extra'");
  imu.imu = "{rate: 100, rate: 200}";
  refused(imu, "imu: line 1: key 'rate' appears twice in one map");
  EXPECT_EQ(names(), before);
  EXPECT_FALSE(advertised("/extra/odom"));
}

// ------------------------------------------------------------ names.test

class NodeNames : public WorldEdit {};

TEST_F(NodeNames, AOneBodyWorldsBodyKeepsItsNamesWhenASecondArrives) {
  // names.test: robot_description's box, alone, has the single-body names:
  // frame base_link, /odom, ~wrench. Spawned bodies live under their name.
  ASSERT_TRUE(trigger("pause"));
  ASSERT_TRUE(get("").success);
  const SpawnBody::Response res = spawn(spawnRequest("ball", kBall, 2, 0, 0));
  ASSERT_TRUE(res.success) << res.message;
  EXPECT_EQ(nextMessage<nav_msgs::Odometry>(nh_, "/odom", [&] { step(10); }).child_frame_id, kLink);
  EXPECT_EQ(nextMessage<nav_msgs::Odometry>(nh_, "/ball/odom", [&] { step(10); }).child_frame_id, "ball/ball");
  const std::set<std::string> frames = tfFrames(20);
  EXPECT_EQ(frames.count(kLink), 1u);
  EXPECT_EQ(frames.count("ball/ball"), 1u);
  // "" no longer says which body; the box's name (its root link's) does.
  const auto ambiguous = get("");
  EXPECT_FALSE(ambiguous.success);
  EXPECT_NE(ambiguous.message.find("several bodies"), std::string::npos) << ambiguous.message;
  ASSERT_TRUE(get(kLink).success);
  // The plain ~wrench still pushes the box, not the ball.
  ros::Publisher pub = nh_.advertise<geometry_msgs::WrenchStamped>("/sim_node/wrench", 1);
  ASSERT_TRUE(spinUntil([&] { return pub.getNumSubscribers() > 0; }, 10.0));
  geometry_msgs::WrenchStamped w;
  w.wrench.force.y = 1.0;
  pub.publish(w);
  spinUntil([] { return false; }, 0.5);
  step(100);
  EXPECT_NEAR(get(kLink).state.twist.linear.y, 0.1, 1e-9);
  EXPECT_EQ(get("ball").state.twist.linear.y, 0.0);
  // The ball goes: the box is alone again and keeps its names; a body
  // spawned now still lives under its name.
  ASSERT_TRUE(remove("ball").success);
  ASSERT_TRUE(get("").success);
  ASSERT_TRUE(spawn(spawnRequest("ball2", kBall, -2, 0, 0)).success);
  EXPECT_EQ(nextMessage<nav_msgs::Odometry>(nh_, "/odom", [&] { step(10); }).child_frame_id, kLink);
  EXPECT_EQ(nextMessage<nav_msgs::Odometry>(nh_, "/ball2/odom", [&] { step(10); }).child_frame_id, "ball2/ball");
}

// ------------------------------------------------------------ delete.test

class NodeDelete : public WorldEdit {};

TEST_F(NodeDelete, ADeletedBodyIsGoneAndWhatRestedOnItFalls) {
  // delete.test, started paused: 'top' rests on 'base'; 'far' rests 5 m away.
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(step(1000).success);  // all at rest, asleep
  const auto settled = bodyStates();
  ASSERT_EQ(settled.names, (std::vector<std::string>{"base", "top", "far"}));
  ASSERT_TRUE(settled.asleep[2]);
  const auto far_before = get("far").state.pose;
  // Each body's colour in rviz, by its marker namespace (its name).
  const auto colours = [](const visualization_msgs::MarkerArray& markers) {
    std::map<std::string, std::vector<float>> out;
    for (const auto& m : markers.markers) {
      if (m.action == visualization_msgs::Marker::ADD) out[m.ns] = {m.color.r, m.color.g, m.color.b, m.color.a};
    }
    return out;
  };
  const auto colours_before = colours(latchedMarkers("/sim_node/body_markers"));
  ASSERT_EQ(colours_before.size(), 3u);
  rigid_body_sim::ApplyWrench hold;
  hold.request.body = "base";
  hold.request.force = vec(0, 0, -1);
  hold.request.duration = ros::Duration(-1.0);
  ASSERT_TRUE(call("apply_wrench", hold).response.success);

  const DeleteBody::Response res = remove("base");
  ASSERT_TRUE(res.success) << res.message;
  EXPECT_NE(res.message.find("1 timed wrenches"), std::string::npos) << res.message;
  const auto after = bodyStates();
  ASSERT_EQ(after.names, (std::vector<std::string>{"top", "far"}));
  EXPECT_FALSE(after.asleep[0]);  // it rested on base: woken
  EXPECT_TRUE(after.asleep[1]);   // far: untouched, still asleep, not a bit moved
  EXPECT_TRUE(sameBits(far_before, get("far").state.pose));
  for (int k = 0; k < 2; ++k) step(500);
  EXPECT_NEAR(get("top").state.pose.position.z, 0.05, 1e-3);  // fell 0.1 m onto the ground

  // Its topics, tf, markers and services are gone.
  EXPECT_TRUE(spinUntil([] { return !advertised("/base/odom"); }, 10.0));
  EXPECT_TRUE(advertised("/top/odom"));
  const std::set<std::string> frames = tfFrames(50);
  EXPECT_EQ(frames.count("base/base_link"), 0u);
  EXPECT_EQ(frames.count("top/base_link"), 1u);
  const auto markers = latchedMarkers("/sim_node/body_markers");
  ASSERT_FALSE(markers.markers.empty());
  EXPECT_EQ(markers.markers.front().action, visualization_msgs::Marker::DELETEALL);
  std::set<std::string> drawn;
  for (std::size_t i = 1; i < markers.markers.size(); ++i) drawn.insert(markers.markers[i].ns);
  EXPECT_EQ(drawn, (std::set<std::string>{"top", "far"}));
  // A body keeps its colour when another leaves (they moved one body along).
  for (const auto& [name, colour] : colours(markers)) EXPECT_EQ(colour, colours_before.at(name)) << name;
  EXPECT_FALSE(get("base").success);
  const DeleteBody::Response again = remove("base");
  EXPECT_FALSE(again.success);
  EXPECT_EQ(again.message.rfind("name: unknown body 'base'", 0), 0u) << again.message;
  EXPECT_FALSE(remove("").success);
}

TEST_F(NodeDelete, ASpawnedBodyHasItsOwnSurface) {
  // The ground's friction is 0.5; a box spawned with its own 0.1 slides (min
  // rule) v0^2 / (2 * 0.1 * g), one without as far as 0.5 says.
  SpawnBody::Request slick = spawnRequest("slick", kBox, 0, 3, 0.05);
  slick.own_friction = true;
  slick.friction = 0.1;
  slick.twist.linear.x = 2.0;
  ASSERT_TRUE(spawn(slick).success);
  SpawnBody::Request plain = spawnRequest("plain", kBox, 0, 4, 0.05);
  plain.twist.linear.x = 2.0;
  ASSERT_TRUE(spawn(plain).success);
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(step(1000).success);
  const double v0 = 2.0, slick_x = v0 * v0 / (2 * 0.1 * kG), plain_x = v0 * v0 / (2 * 0.5 * kG);
  EXPECT_NEAR(get("slick").state.pose.position.x, slick_x, 0.02 * slick_x);
  EXPECT_NEAR(get("plain").state.pose.position.x, plain_x, 0.02 * plain_x);
}

TEST_F(NodeDelete, DeletingTheLastBodyLeavesAWorldThatStepsAndPublishesTheClock) {
  for (const std::string& name : names()) ASSERT_TRUE(remove(name).success) << name;
  EXPECT_TRUE(names().empty());
  const auto none = get("");
  EXPECT_FALSE(none.success);
  EXPECT_NE(none.message.find("no bodies"), std::string::npos) << none.message;
  // delete.test runs on /use_sim_time: /clock goes on.
  ASSERT_TRUE(trigger("unpause"));
  const auto first = nextMessage<rosgraph_msgs::Clock>(nh_, "/clock").clock;
  spinUntil([] { return false; }, 0.5);
  const auto later = nextMessage<rosgraph_msgs::Clock>(nh_, "/clock").clock;
  EXPECT_GT((later - first).toSec(), 0.2);
  ASSERT_TRUE(trigger("pause"));
  // And it can be filled again.
  ASSERT_TRUE(spawn(spawnRequest("again", kBox, 0, 0, 0.05)).success);
  EXPECT_EQ(names(), std::vector<std::string>{"again"});
}

// ------------------------------------------------------------ edit_determinism.test

/// One node's run of the same edits at the same sim times (both start paused).
std::vector<BodyState> editedRun(const std::string& node) {
  const auto srv = [&](const std::string& name, auto s) {
    EXPECT_TRUE(ros::service::waitForService(node + "/" + name, 30000)) << name;
    EXPECT_TRUE(ros::service::call(node + "/" + name, s)) << name;
    return s.response;
  };
  const auto steps = [&](int n) {
    rigid_body_sim::Step s;
    s.request.steps = n;
    EXPECT_TRUE(srv("step", s).success);
  };
  steps(200);
  SpawnBody spawn;
  spawn.request = spawnRequest("ball", kBall, 0.05, 0.0, 0.6);
  spawn.request.twist.linear.x = 0.3;
  spawn.request.twist.angular.y = 2.0;
  EXPECT_TRUE(srv("spawn_body", spawn).success);
  steps(300);
  DeleteBody del;
  del.request.name = "base";
  EXPECT_TRUE(srv("delete_body", del).success);
  steps(700);
  std::vector<BodyState> states;
  for (const std::string body : {"top", "ball"}) {
    rigid_body_sim::GetState get;
    get.request.body = body;
    states.push_back(srv("get_state", get).state);
  }
  return states;
}

TEST(NodeEditDeterminism, TheSameEditsAtTheSameSimTimesGiveTheSameBits) {
  const std::vector<BodyState> a = editedRun("/a/sim_node"), b = editedRun("/b/sim_node");
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(sameBits(a[i].pose, b[i].pose)) << a[i].body;
    EXPECT_TRUE(sameBits(a[i].twist, b[i].twist)) << a[i].body;
  }
  EXPECT_LT(a[1].pose.position.z, 0.5);  // the ball has fallen: the run did something
}

}  // namespace
}  // namespace rbs_test
