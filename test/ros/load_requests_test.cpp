// The requests that push bodies (no master): each refuses a bad field by
// name and changes nothing then; a wrench or an impulse given in another
// body's axes acts along that body's axes now; start_time is read on the
// node's clock; ~wrench and cmd_vel drop what is not finite.
#include "rigid_body_sim/ros/load_requests.h"

#include <gtest/gtest.h>

#include <boost/make_shared.hpp>
#include <limits>

#include "node_parts.h"

namespace rigid_body_sim::node {
namespace {

using test::Vec3;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int64_t kAnchorNs = 1000'000'000'000;  ///< the clock reads 1000 s at step 0

/// Bodies a and b (b turned a quarter about z), and their load requests.
struct Loads : test::PartsWorld {
  Loads() : PartsWorld({"a", "b"}) {
    ros::Time::init();  // the throttled warnings read ros::Time, here the wall clock
    time.clock.anchor(0, kAnchorNs);
  }
  NodeSettings settings;
  NodeTime time{1e-3, true};
  LoadRequests requests{sim, ports, address, settings, time};
};

geometry_msgs::Vector3 vector(double x, double y, double z) {
  geometry_msgs::Vector3 v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}

TEST(LoadRequests, AWrenchIsCheckedThenScheduledOnTheNodesClock) {
  Loads w;
  ApplyWrench::Request req;
  ApplyWrench::Response res;
  req.body = "a";
  req.duration = ros::Duration(0.5);
  req.force = vector(kNaN, 0, 0);
  w.requests.applyWrench(req, res);
  EXPECT_FALSE(res.success);
  EXPECT_EQ(res.message.rfind("force is not finite", 0), 0u) << res.message;
  req.force = vector(2, 0, 0);
  req.duration = ros::Duration(0);
  w.requests.applyWrench(req, res);
  EXPECT_FALSE(res.success);
  req.duration = ros::Duration(0.5);
  req.start_time.fromNSec(kAnchorNs + 2'000'000'000'000'000);  // 2e6 s ahead: another clock's reading
  w.requests.applyWrench(req, res);
  EXPECT_FALSE(res.success);
  EXPECT_NE(res.message.find("ahead of this node's clock"), std::string::npos) << res.message;
  EXPECT_EQ(w.sim.schedule.size(), 0u);  // nothing refused was kept

  req.start_time.fromNSec(kAnchorNs + 250'000'000);  // sim time 0.25 s
  w.requests.applyWrench(req, res);
  EXPECT_TRUE(res.success) << res.message;
  EXPECT_EQ(res.message, "wrench on 'a' from t = 1000.250000000 s for 0.500000 s");
  core::Loads loads;
  w.sim.schedule.loadsFor(w.sim.model(), w.sim.state, 0.0, 0.25, loads);
  EXPECT_TRUE(loads.empty() || loads[0].force_W.isZero());  // not yet
  w.sim.schedule.loadsFor(w.sim.model(), w.sim.state, 0.25, 0.25, loads);
  ASSERT_EQ(loads.size(), 2u);
  EXPECT_EQ(loads[0].force_W, Vec3(2, 0, 0));
}

TEST(LoadRequests, AnImpulseInAnotherBodysAxesActsAlongThem) {
  Loads w;
  ApplyImpulse::Request req;
  ApplyImpulse::Response res;
  req.body = "a";
  req.frame = "b/base";  // b's x axis is the world's y
  req.linear = vector(2, 0, 0);
  w.requests.applyImpulse(req, res);
  ASSERT_TRUE(res.success) << res.message;
  EXPECT_TRUE(w.sim.state.bodies[0].v_WB.isApprox(Vec3(0, 2, 0), 1e-15));  // Δv = J / m, m = 1 kg
  const core::State before = w.sim.state;
  req.linear = vector(1e3, 0, 0);  // 1000 m/s: above limits.max_linear_speed, 500 m/s
  w.requests.applyImpulse(req, res);
  EXPECT_FALSE(res.success);
  EXPECT_NE(res.message.find("limits.max_linear_speed"), std::string::npos) << res.message;
  req.linear = vector(1, 0, 0);
  req.point.y = kNaN;
  w.requests.applyImpulse(req, res);
  EXPECT_FALSE(res.success);
  EXPECT_EQ(res.message.rfind("point is not finite", 0), 0u) << res.message;
  EXPECT_TRUE(rigid_body_sim::test::bitIdentical(w.sim.state, before));
}

TEST(LoadRequests, ClearingTakesOnlyTheNamedBodysWrenches) {
  Loads w;
  const core::Wrench push{Vec3(1, 0, 0), Vec3::Zero(), Vec3::Zero(), core::Frame::kWorld};
  w.sim.schedule.add(0, push, 0.0, 1.0);
  w.sim.schedule.add(1, push, 0.0, 1.0);
  ClearWrenches::Request req;
  ClearWrenches::Response res;
  req.body = "c";
  w.requests.clearWrenches(req, res);
  EXPECT_FALSE(res.success);
  EXPECT_EQ(res.message, "unknown body 'c' (the bodies: 'a', 'b')");
  EXPECT_EQ(w.sim.schedule.size(), 2u);
  req.body = "b";
  w.requests.clearWrenches(req, res);
  EXPECT_TRUE(res.success);
  EXPECT_EQ(w.sim.schedule.count(0), 1u);
  EXPECT_EQ(w.sim.schedule.count(1), 0u);
}

TEST(LoadRequests, TheTopicsDropWhatIsNotFinite) {
  Loads w;
  auto wrench = boost::make_shared<geometry_msgs::WrenchStamped>();
  wrench->wrench.force = vector(0, kNaN, 0);
  w.requests.onWrench("a", wrench);
  EXPECT_FALSE(w.sim.schedule.holds(0));
  wrench->wrench.force = vector(0, 1, 0);
  wrench->header.frame_id = "nowhere";
  w.requests.onWrench("a", wrench);
  EXPECT_FALSE(w.sim.schedule.holds(0));
  wrench->header.frame_id = "b/base";
  w.requests.onWrench("a", wrench);
  EXPECT_TRUE(w.sim.schedule.holds(0));
  w.requests.onWrench("gone", wrench);  // a deleted body's message, still queued: nothing

  w.ports[1].driver.emplace(core::DriverSettings{});
  auto twist = boost::make_shared<geometry_msgs::Twist>();
  twist->linear = vector(kNaN, 0, 0);
  w.requests.onCmdVel("b", twist);
  EXPECT_FALSE(w.ports[1].driver->active(0.0));
  twist->linear = vector(5, 0, 0);  // above cmd_vel.max_linear_speed, 1 m/s
  w.requests.onCmdVel("b", twist);
  EXPECT_TRUE(w.ports[1].driver->active(0.0));
  EXPECT_TRUE(w.ports[1].clipped);
}

}  // namespace
}  // namespace rigid_body_sim::node
