// Per-body materials through the node (issue 14): two boxes pushed to the
// same speed on the same ground, one with its own slick surface, stop where
// the combined friction says, as a user reads them with get_state.
#include <cmath>
#include <string>

#include "node_fixture.h"
#include "rigid_body_sim/SetState.h"

namespace rbs_test {
namespace {

class NodeMaterials : public Node {
 protected:
  void push(const std::string& body, double y, double speed) {
    rigid_body_sim::SetState set;
    set.request.body = body;
    set.request.state.pose.position.y = y;
    set.request.state.pose.position.z = 0.05;  // resting on the ground
    set.request.state.pose.orientation.w = 1.0;
    set.request.state.twist.linear.x = speed;
    set = call("set_state", set);
    ASSERT_TRUE(set.response.success) << set.response.message;
  }
  double x(const std::string& body) {
    rigid_body_sim::GetState get;
    get.request.body = body;
    get = call("get_state", get);
    EXPECT_TRUE(get.response.success) << get.response.message;
    return get.response.state.pose.position.x;
  }
};

TEST_F(NodeMaterials, EachBodySlidesAsItsCombinedFrictionSays) {
  // materials.test: the ground's friction 0.8; 'slick' has its own 0.2, and
  // the pair takes the smaller (min, the default rule); 'plain' has the ground's.
  ASSERT_TRUE(trigger("pause"));
  const double v0 = 2.0;
  push("slick", 0.0, v0);
  push("plain", 1.0, v0);
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(step(1000).success);  // 3 s: both have stopped
  const double g = 9.81;
  EXPECT_NEAR(x("slick"), v0 * v0 / (2 * 0.2 * g), 0.02 * v0 * v0 / (2 * 0.2 * g));
  EXPECT_NEAR(x("plain"), v0 * v0 / (2 * 0.8 * g), 0.02 * v0 * v0 / (2 * 0.8 * g));
}

}  // namespace
}  // namespace rbs_test
