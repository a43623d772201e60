// The requests that read or set the state (no master): get_state gives the
// twist in the axes asked for; set_state refuses what is not a state and
// changes nothing then, else sets the pose and twist (in the new pose's own
// axes or another body's), drops the warm starts and publishes once; reset
// puts the initial state back at the current sim time.
#include "rigid_body_sim/ros/state_requests.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "node_parts.h"

namespace rigid_body_sim::node {
namespace {

using test::Quat;
using test::Vec3;

/// Bodies a and b (b turned a quarter about z), their state requests, and
/// what the requests asked of the node.
struct States : test::PartsWorld {
  States() : PartsWorld({"a", "b"}) {}
  NodeTime time{1e-3, false};  // sim time: the stamp is steps × dt
  std::vector<std::string> asked;
  StateRequests requests{
      sim, ports, address, time, {[this] { asked.push_back("changed"); }, [this] { asked.push_back("restarted"); }}};
};

TEST(StateRequests, GetStateGivesTheTwistInTheAxesAskedFor) {
  States w;
  w.sim.state.bodies[0].v_WB = Vec3(1, 0, 0);
  w.time.steps = 1500;
  GetState::Request req;
  GetState::Response res;
  req.body = "a";
  req.frame = "b/base";  // b's x axis is the world's y: world x is b's −y
  w.requests.getState(req, res);
  ASSERT_TRUE(res.success) << res.message;
  EXPECT_EQ(res.state.body, "a");
  EXPECT_EQ(res.state.twist_frame, "b/base");
  EXPECT_NEAR(res.state.twist.linear.y, -1.0, 1e-15);
  EXPECT_NEAR(res.state.twist.linear.x, 0.0, 1e-15);
  EXPECT_EQ(res.state.stamp.toSec(), 1.5);
  req.body = "c";
  w.requests.getState(req, res);
  EXPECT_FALSE(res.success);
}

TEST(StateRequests, SetStateRefusesWhatIsNoStateAndSetsTheRest) {
  States w;
  w.sim.state.contact_impulses.push_back(core::ContactImpulse{});
  const core::State before = w.sim.state;
  SetState::Request req;
  SetState::Response res;
  req.body = "a";
  req.state.pose.orientation.w = 2.0;  // not a unit quaternion
  w.requests.setState(req, res);
  EXPECT_FALSE(res.success);
  EXPECT_EQ(res.message.rfind("orientation is not a unit quaternion", 0), 0u) << res.message;
  req.state.pose.orientation.w = 1.0;
  req.state.twist.linear.x = 600.0;  // above limits.max_linear_speed, 500 m/s
  w.requests.setState(req, res);
  EXPECT_FALSE(res.success);
  req.state.twist.linear.x = std::numeric_limits<double>::infinity();
  w.requests.setState(req, res);
  EXPECT_FALSE(res.success);
  EXPECT_TRUE(rigid_body_sim::test::bitIdentical(w.sim.state, before));
  EXPECT_TRUE(w.asked.empty());  // nothing published

  // At (0, 0, 2) turned a quarter about z, moving 1 m/s along its own x.
  req.state.pose.position.z = 2.0;
  req.state.pose.orientation.z = std::sqrt(0.5);
  req.state.pose.orientation.w = std::sqrt(0.5);
  req.state.twist.linear.x = 1.0;
  req.state.twist_frame = "a/base";
  w.requests.setState(req, res);
  ASSERT_TRUE(res.success) << res.message;
  const core::LinkState link = core::linkState(w.sim.model().body(0), w.sim.state.bodies[0]);
  EXPECT_TRUE(link.p_WL.isApprox(Vec3(0, 0, 2)));
  EXPECT_TRUE(link.v_WL.isApprox(Vec3(0, 1, 0), 1e-15));  // its x is the world's y
  EXPECT_TRUE(w.sim.state.contact_impulses.empty());      // no warm start carries over to a new pose
  EXPECT_EQ(w.asked, std::vector<std::string>{"changed"});
}

TEST(StateRequests, ResetPutsTheInitialStateBackAtTheCurrentTime) {
  States w;
  w.sim.state.bodies[1].p_WB = Vec3(9, 9, 9);
  w.sim.schedule.add(1, core::Wrench{}, 0.0, 1.0);
  w.time.steps = 2500;
  std_srvs::Trigger::Request req;
  std_srvs::Trigger::Response res;
  w.requests.reset(req, res);
  EXPECT_TRUE(res.success);
  EXPECT_EQ(res.message, "reset to the initial state at t = 2.500000000 s");
  EXPECT_EQ(w.sim.state.bodies[1].p_WB, w.sim.initial.bodies[1].p_WB);
  EXPECT_EQ(w.sim.state.time, 2.5);  // sim time goes on
  EXPECT_EQ(w.sim.schedule.size(), 0u);
  EXPECT_EQ(w.asked, (std::vector<std::string>{"restarted", "changed"}));
}

}  // namespace
}  // namespace rigid_body_sim::node
