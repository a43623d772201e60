// Robots coming and going (churn.test: an empty world on the ground): 200
// robots (40 under ASan), each with a lidar, an IMU and a
// DiffDriveController, spawned and deleted in a random order (seeded), up
// to 24 at once, interleaved with
// cmd_vel on their controllers' topics and service calls on their joints,
// and the same calls on robots already deleted. The node never ends; once
// the last is deleted nothing of any is left: no topic it published or
// subscribed, no service, no parameter, no tf frame, no controller; and
// its resident memory is no higher after the second half of them than
// after the first (issue 57; why not within 5 % of before: at the end).
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>

#include <map>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "../sanitizers.h"
#include "node_fixture.h"
#include "node_process.h"
#include "rigid_body_sim/ApplyJointEffort.h"
#include "rigid_body_sim/DeleteBody.h"
#include "rigid_body_sim/GetJointProperties.h"
#include "rigid_body_sim/SpawnBody.h"

namespace rbs_test {
namespace {

/// A name of one of the churned robots ("r17"), at the start of a topic, service, parameter or frame.
#if defined(RBS_UNDER_ASAN)
constexpr int kRobots = 40;  ///< spawned and deleted: under ASan each spawn takes about a second
#else
constexpr int kRobots = 200;  ///< spawned and deleted
#endif

const std::regex kChurned("^/?r[0-9]+(/|$)");

/// What the master lists of node `node`: the topics it publishes and
/// subscribes to and the services it offers.
std::vector<std::string> masterEntries(const std::string& node) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  std::vector<std::string> out;
  if (!ros::master::execute("getSystemState", args, result, payload, true)) return {"getSystemState failed"};
  for (int kind = 0; kind < 3; ++kind) {  // publishers, subscribers, services: [[name, [node, ...]], ...]
    XmlRpc::XmlRpcValue& entries = payload[kind];
    for (int i = 0; i < entries.size(); ++i) {
      for (int k = 0; k < entries[i][1].size(); ++k) {
        if (static_cast<std::string>(entries[i][1][k]) == node) out.push_back(static_cast<std::string>(entries[i][0]));
      }
    }
  }
  return out;
}

class Churn : public Node {
 protected:
  /// Robot `name` at (x, y) on the ground, its frames under its own name
  /// (NAME/tf_prefix, set as a user sets it for robot_state_publisher).
  rigid_body_sim::SpawnBody::Response spawn(const std::string& name, double x, double y) {
    ros::param::set("/" + name + "/tf_prefix", name);
    rigid_body_sim::SpawnBody s;
    s.request.name = name;
    s.request.urdf_file = "package://rigid_body_sim/urdf/diff_drive_lidar.urdf";
    s.request.pose.position.x = x;
    s.request.pose.position.y = y;
    s.request.pose.position.z = 0.08;
    s.request.pose.orientation.w = 1.0;
    s.request.controllers =
        "{base: {type: diff_drive_controller/DiffDriveController, left_wheel: left_wheel_joint, "
        "right_wheel: right_wheel_joint}}";
    return call("spawn_body", s).response;
  }
  /// Deletes robot `name`, and the tf_prefix this test set for it.
  bool remove(const std::string& name) {
    rigid_body_sim::DeleteBody d;
    d.request.name = name;
    const bool deleted = call("delete_body", d).response.success;
    ros::param::del("/" + name + "/tf_prefix");
    return deleted;
  }
  /// Calls on robot `name`'s joints: whether each answered success.
  bool jointCalls(const std::string& name) {
    rigid_body_sim::GetJointProperties g;
    g.request.joint_name = name + "/left_wheel_joint";
    const bool got = call("get_joint_properties", g).response.success;
    rigid_body_sim::ApplyJointEffort e;
    e.request.joint_name = name + "/right_wheel_joint";
    e.request.effort = 0.01;
    e.request.duration = ros::Duration(0.05);
    const bool applied = call("apply_joint_effort", e).response.success;
    EXPECT_EQ(got, applied) << name;
    return got && applied;
  }
};

TEST_F(Churn, TwoHundredRobotsComeAndGoAndLeaveNothingBehind) {
  ASSERT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
  const int pid = simNodePid();
  ASSERT_GT(pid, 0);
  const long before = residentKb(pid);
  long peak = before, halfway = 0;
  std::mt19937 rng(57);
  std::map<std::string, ros::Publisher> live;  // each live robot's cmd_vel publisher
  std::vector<std::string> gone;
  int spawned = 0;
  const auto pick = [&](const auto& names) {
    auto it = names.begin();
    std::advance(it, std::uniform_int_distribution<std::size_t>(0, names.size() - 1)(rng));
    return it;
  };
  while (spawned < kRobots || !live.empty()) {
    const int action = std::uniform_int_distribution<int>(0, 9)(rng);
    const bool can_spawn = spawned < kRobots && live.size() < 24;
    if (action < 4 && can_spawn) {
      const std::string name = "r" + std::to_string(spawned);
      const rigid_body_sim::SpawnBody::Response r = spawn(name, 1.0 * (spawned % 12), 1.0 * ((spawned / 12) % 12));
      ASSERT_TRUE(r.success) << name << ": " << r.message;
      live[name] = nh_.advertise<geometry_msgs::Twist>("/" + name + "/base/cmd_vel", 1);
      ++spawned;
      peak = std::max(peak, residentKb(pid));
    } else if (action < 7 && !live.empty() && (action < 6 || !can_spawn)) {
      const auto it = pick(live);
      ASSERT_TRUE(remove(it->first)) << it->first;
      gone.push_back(it->first);
      live.erase(it);
      if (gone.size() == kRobots / 2) halfway = residentKb(pid);
    } else if (action < 9 && !live.empty()) {
      const auto it = pick(live);
      geometry_msgs::Twist v;
      v.linear.x = 0.2;
      v.angular.z = 0.5;
      it->second.publish(v);
      EXPECT_TRUE(jointCalls(it->first)) << it->first;
    } else if (!gone.empty()) {  // on one deleted: refused, and the node goes on
      const std::string& name = *pick(gone);
      EXPECT_FALSE(jointCalls(name)) << name;
      EXPECT_FALSE(remove(name)) << name;
    }
    ros::spinOnce();
  }
  EXPECT_EQ(spawned, kRobots);
  EXPECT_EQ(gone.size(), static_cast<std::size_t>(kRobots));
  // The node goes on.
  EXPECT_TRUE(trigger("pause"));
  EXPECT_TRUE(trigger("unpause"));

  // No topic, service or parameter of any is left (the tf_prefixes were this test's, and went with each robot).
  for (const std::string& entry : masterEntries("/sim_node")) {
    EXPECT_FALSE(std::regex_search(entry, kChurned)) << "left on the master: " << entry;
  }
  std::vector<std::string> params;
  ASSERT_TRUE(ros::param::getParamNames(params));
  for (const std::string& p : params) EXPECT_FALSE(std::regex_search(p, kChurned)) << "parameter left: " << p;
  // No tf frame: the latched static frames a new subscriber gets, and 0.5 s of /tf.
  std::vector<std::string> frames;
  bool latched = false;
  const ros::Subscriber statics =
      nh_.subscribe<tf2_msgs::TFMessage>("/tf_static", 10, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
        latched = true;
        for (const auto& t : m->transforms) frames.push_back(t.child_frame_id);
      });
  const ros::Subscriber moving =
      nh_.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
        for (const auto& t : m->transforms) frames.push_back(t.child_frame_id);
      });
  spinUntil([&] { return false; }, 0.5);
  for (const std::string& f : frames) EXPECT_FALSE(std::regex_search(f, kChurned)) << "tf frame left: " << f;
  (void)latched;  // an empty world may have no static frames at all
  // No controller: nothing takes a deleted robot's commands.
  for (const std::string& name : gone) EXPECT_FALSE(subscribes("/sim_node", "/" + name + "/base/cmd_vel")) << name;

#if !defined(RBS_UNDER_ASAN)  // ASan's quarantine holds what is freed
  // Memory: no more after the second hundred robots than after the first
  // (a robot's record left behind, ~100 kB with its lidar, would add 10 MB).
  // The figure, within 5 % of before any spawn, is not what a
  // process on glibc gets: the first spawn pages in the loaders' code and
  // caches for good (+1.7 MB), and the peak of 24 robots leaves its heap
  // fragmented (+1.7 MB after malloc_trim, of which 0.5 MB live: the step's
  // buffers sized for the peak) -- 19.8 MB before, 23.1 to 23.4 MB after, measured
  // the same with 100 robots as with 200.
  const long after = residentKb(pid);
  ASSERT_GT(before, 0);
  ASSERT_GT(halfway, 0);
  EXPECT_LE(after - halfway, halfway / 20)
      << "before the spawns " << before << " kB, peak " << peak << " kB, after 100 deleted " << halfway
      << " kB, after 200 " << after << " kB";
  EXPECT_LE(after - before, before / 4) << "before the spawns " << before << " kB, after " << after << " kB";
  RecordProperty("rss_kb_before", static_cast<int>(before));
  RecordProperty("rss_kb_peak", static_cast<int>(peak));
  RecordProperty("rss_kb_halfway", static_cast<int>(halfway));
  RecordProperty("rss_kb_after", static_cast<int>(after));
#endif
}

}  // namespace
}  // namespace rbs_test
