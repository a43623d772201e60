// The world's edits on the loop (no master): a spawn with a taken name or
// an absurd twist is refused and changes nothing; one that fits joins the
// simulation, the ports and the names together, posed in the frame it
// names; a delete takes a body out of all of them and the later ones move
// down; the node hears of each edit once. A robot's topics are claimed
// once each (TopicClaims).
#include "rigid_body_sim/ros/world_edits.h"

#include <gtest/gtest.h>

#include <vector>

#include "node_parts.h"

namespace rigid_body_sim::node {
namespace {

using test::Quat;
using test::Vec3;

/// Bodies a and b (b at x = 1 m, turned a quarter about z), their edits,
/// and what the edits told the node.
struct Edits : test::PartsWorld {
  Edits() : PartsWorld({"a", "b"}) {}
  NodeSettings settings;
  NodeTime time{1e-3, false};
  Pacer pacer;
  std::vector<std::string> told;
  std::optional<RobotPublisher> robots;
  TopicClaims topics{[](const std::string& t) { return t; }};
  WorldEdits edits{
      sim,
      ports,
      robots,
      address,
      settings,
      time,
      pacer,
      topics,
      {[this] { told.push_back("added"); }, [this](const std::string& n) { told.push_back("removed " + n); },
       [this](SpawnQueue::Spawn& s) { told.push_back("robot added " + s.request.name); },
       [this](std::size_t, const std::string& n) { told.push_back("robot removed " + n); }}};

  /// A spawn of a box named `name` at `z` m above the origin of `frame`, as the spawn thread hands it over.
  SpawnQueue::Spawn spawn(const std::string& name, double z, const std::string& frame) {
    core::BodySpec spec = rigid_body_sim::test::boxBody(Vec3(0.1, 0.1, 0.1));
    spec.name = name;
    spec.link = "base";
    SpawnQueue::Spawn s;
    s.request.name = name;
    s.request.frame = frame;
    s.request.pose.position.z = z;
    s.request.pose.orientation.w = 1.0;
    s.body = sim.model().bodyBuilder().build(spec);
    s.ports = std::make_unique<BodyPorts>();
    s.ports->prefix = name + "/";
    s.ports->frame = name + "/base";
    return s;
  }
};

TEST(WorldEdits, ASpawnThatDoesNotFitChangesNothing) {
  Edits w;
  SpawnQueue::Spawn taken = w.spawn("a", 1.0, "");
  EXPECT_EQ(w.edits.insert(taken).message, "name 'a' is taken by a body in the world");
  SpawnQueue::Spawn fast = w.spawn("c", 1.0, "");
  fast.request.twist.linear.x = 600.0;  // above limits.max_linear_speed, 500 m/s
  const SpawnBody::Response res = w.edits.insert(fast);
  EXPECT_FALSE(res.success);
  EXPECT_EQ(res.message.rfind("twist.linear is above the speed limit", 0), 0u) << res.message;
  SpawnQueue::Spawn nowhere = w.spawn("c", 1.0, "odom");
  EXPECT_FALSE(w.edits.insert(nowhere).success);
  EXPECT_EQ(w.sim.model().bodyCount(), 2u);
  EXPECT_EQ(w.sim.state.bodies.size(), 2u);
  EXPECT_EQ(w.ports.size(), 2u);
  EXPECT_TRUE(w.told.empty());
}

TEST(WorldEdits, ASpawnJoinsEveryTableInTheFrameItNames) {
  Edits w;
  SpawnQueue::Spawn c = w.spawn("c", 2.0, "b/base");  // 2 m above b's origin, turned as b
  const SpawnBody::Response res = w.edits.insert(c);
  ASSERT_TRUE(res.success) << res.message;
  EXPECT_EQ(res.message, "body 'c' added at t = 0.000000000 s: frame 'c/base', topics 'c/odom' and 'c/wrench'");
  ASSERT_EQ(w.sim.model().bodyCount(), 3u);
  EXPECT_EQ(w.sim.initial.bodies.size(), 3u);  // reset puts it back where it was spawned
  EXPECT_EQ(w.ports.directory().byName("c"), 2);
  const core::LinkState link = core::linkState(w.sim.model().body(2), w.sim.state.bodies[2]);
  EXPECT_TRUE(link.p_WL.isApprox(Vec3(1, 0, 2)));
  EXPECT_TRUE((link.q_WL * Vec3::UnitX()).isApprox(Vec3::UnitY(), 1e-15));
  EXPECT_EQ(w.told, std::vector<std::string>{"added"});
}

TEST(WorldEdits, ADeleteTakesTheBodyOutOfEveryTable) {
  Edits w;
  SpawnQueue::Spawn c = w.spawn("c", 2.0, "");
  ASSERT_TRUE(w.edits.insert(c).success);
  DeleteBody::Request req;
  DeleteBody::Response res;
  w.edits.deleteBody(req, res);
  EXPECT_FALSE(res.success);
  req.name = "z";
  w.edits.deleteBody(req, res);
  EXPECT_EQ(res.message, "name: unknown body 'z' (the bodies: 'a', 'b', 'c')");
  req.name = "a";
  w.edits.deleteBody(req, res);
  ASSERT_TRUE(res.success) << res.message;
  EXPECT_EQ(res.message, "body 'a' deleted at t = 0.000000000 s (0 timed wrenches went with it); 2 bodies left");
  ASSERT_EQ(w.sim.model().bodyCount(), 2u);
  EXPECT_EQ(w.sim.model().body(1).name, "c");
  EXPECT_EQ(w.ports[1].frame, "c/base");
  EXPECT_EQ(w.ports.directory().byName("c"), 1);
  EXPECT_FALSE(w.ports.directory().byName("a"));
  EXPECT_EQ(w.sim.initial.bodies.size(), 2u);
  EXPECT_EQ(w.told, (std::vector<std::string>{"added", "removed a"}));
}

// A refusal echoes at most 200 characters of a name it was given: a delete
// once echoed a 100 KB name back in full.
TEST(WorldEdits, ARefusalShowsAtMost200CharactersOfAName) {
  Edits w;
  DeleteBody::Request req;
  DeleteBody::Response res;
  req.name = std::string(100000, 'x');
  req.name[7] = '\n';
  w.edits.deleteBody(req, res);
  EXPECT_FALSE(res.success);
  EXPECT_LT(res.message.size(), 300u) << res.message.size();
  EXPECT_NE(res.message.find("unknown body 'xxxxxxx?xxx"), std::string::npos) << res.message.substr(0, 300);
  EXPECT_NE(res.message.find("... (100000 characters)'"), std::string::npos) << res.message.substr(0, 300);
}

// One topic, one publisher: a robot's topics (as the port classes name
// them) are refused where another robot holds one, or two of its own share
// one (a lidar and a depth camera on 'scan' once started, the second never
// published), naming both; they are free again once their robot is gone.
TEST(TopicClaims, ATakenTopicIsRefusedNamingBothAndFreedWithItsRobot) {
  TopicClaims claims([](const std::string& t) { return t.front() == '/' ? t : "/ns/" + t; });
  io::RobotSensors sensors;
  io::RobotLidar lidar;
  lidar.entry.topic = "/scan";
  lidar.entry.key = "lidar[0]";
  sensors.lidars.push_back(lidar);
  io::RobotCamera camera;
  camera.entry.key = "depth_camera[0]";
  camera.entry.topic = "cam";
  camera.entry.points_topic = "/points";
  sensors.cameras.push_back(camera);
  const io::RobotControls controls;
  const std::vector<TopicClaims::Claim> a = robotTopics("a/", "a/", sensors, controls);
  ASSERT_EQ(a.size(), 5u);  // joint_states, the lidar, the camera's three
  EXPECT_EQ(a[0].topic, "a/joint_states");
  EXPECT_EQ(a[1].topic, "/scan");  // from the root, as given
  EXPECT_EQ(a[2].topic, "a/cam/depth/image_raw");
  EXPECT_EQ(a[3].topic, "a/cam/depth/camera_info");
  EXPECT_EQ(a[4].topic, "/points");
  EXPECT_EQ(claims.problem(a), "");
  claims.take("a", a);
  const std::vector<TopicClaims::Claim> b = robotTopics("b/", "b/", sensors, controls);
  EXPECT_EQ(claims.problem(b),
            "lidar[0]: topic '/scan' is taken by 'a' lidar[0] (one topic, one publisher: name another topic)");
  // Two of one robot's on one topic (resolved alike: 'x' under /ns/ is '/ns/x').
  sensors.lidars[0].entry.topic = "/ns/b/cam/depth/camera_info";
  EXPECT_EQ(claims.problem(robotTopics("b/", "b/", sensors, controls)),
            "depth_camera[0]: topic '/ns/b/cam/depth/camera_info' is also its lidar[0]'s (one topic, one publisher: "
            "name another topic)");
  claims.release("a");
  EXPECT_EQ(claims.problem(b), "");
}

}  // namespace
}  // namespace rigid_body_sim::node
