// The velocity driver through the node (issue 15): cmd_vel.test's box on
// ground with friction, driven by geometry_msgs/Twist on /cmd_vel as a
// planner would: it reaches and holds 0.5 m/s, a command beyond the limit
// is clipped to it, and after the timeout it is no longer driven.
#include <geometry_msgs/Twist.h>

#include "node_fixture.h"

namespace rbs_test {
namespace {

class NodeCmdVel : public Node {
 protected:
  void SetUp() override {
    Node::SetUp();
    pub_ = nh_.advertise<geometry_msgs::Twist>("/cmd_vel", 1);
    ASSERT_TRUE(spinUntil([&] { return pub_.getNumSubscribers() > 0; }, 10.0));
  }
  void command(double vx, double wz) {
    geometry_msgs::Twist t;
    t.linear.x = vx;
    t.angular.z = wz;
    pub_.publish(t);
    spinUntil([] { return false; }, 0.3);  // for the node to take it in (it is paused)
  }
  double speed() {
    const BodyState s = state();
    return std::hypot(s.twist.linear.x, s.twist.linear.y);
  }
  ros::Publisher pub_;
};

TEST_F(NodeCmdVel, ItDrivesToTheCommandClipsItAndStopsAfterTheTimeout) {
  command(0.5, 0.0);
  ASSERT_TRUE(step(1000).success);  // 1 s: reached after about 0.2 s
  EXPECT_NEAR(speed(), 0.5, 0.005);
  EXPECT_NEAR(state().pose.position.x, 0.5 * 1.0, 0.1);  // it moved, not teleported
  command(3.0, 0.0);                                     // beyond max_linear_speed 1: clipped, not refused
  ASSERT_TRUE(step(1500).success);
  EXPECT_NEAR(speed(), 1.0, 0.01);
  ASSERT_TRUE(step(1000).success);  // 2.5 s since the command: past the 2 s timeout, friction stops it
  EXPECT_LT(speed(), 1e-3);
}

}  // namespace
}  // namespace rbs_test
