// A static mesh in the scene through the node (issue 14): meshes/ramp.obj is
// drawn on ~scene_markers, and the box slides down it as the incline's
// closed form says, read with get_state.
#include <cmath>

#include "node_fixture.h"
#include "rigid_body_sim/SetState.h"

namespace rbs_test {
namespace {

class SceneMeshNode : public Node {};

TEST_F(SceneMeshNode, TheRampIsDrawnAndABoxSlidesDownIt) {
  const double slope = 20.0 * M_PI / 180.0, c = std::cos(slope), s = std::sin(slope);
  // Drawn: its surface as triangles, inside the wedge's box, many on the slope z = x tan 20°.
  const visualization_msgs::MarkerArray markers = latchedMarkers("/sim_node/scene_markers");
  ASSERT_EQ(markers.markers.size(), 1u);
  const auto& ramp = markers.markers[0];
  EXPECT_EQ(ramp.type, visualization_msgs::Marker::TRIANGLE_LIST);
  ASSERT_GT(ramp.points.size(), 300u);
  int on_slope = 0;
  const double cell = 3.0 * 1.06 / 64;  // the marker surface's grid cell
  for (const auto& p : ramp.points) {
    EXPECT_TRUE(p.x > -cell && p.x < 3 + cell && std::abs(p.y) < 1 + cell && p.z > -cell && p.z < 3 * s / c + cell)
        << p;
    on_slope += std::abs(p.z - p.x * s / c) * c < cell;
  }
  EXPECT_GT(on_slope, 50);
  // The box (scene_mesh.test: friction 0.2 < tan 20°) put on the slope slides at g (sin θ − μ cos θ).
  ASSERT_TRUE(trigger("pause"));
  rigid_body_sim::SetState set;
  const double along = 1.6 / c, lift = 0.05;  // its centre above the slope at x = 1.6 m
  set.request.state.pose.position.x = along * c - lift * s;
  set.request.state.pose.position.z = along * s + lift * c;
  set.request.state.pose.orientation.y = std::sin(-slope / 2);
  set.request.state.pose.orientation.w = std::cos(-slope / 2);
  set = call("set_state", set);
  ASSERT_TRUE(set.response.success) << set.response.message;
  const BodyState before = state();
  ASSERT_TRUE(step(500).success);
  const BodyState after = state();
  const double moved =
      -((after.pose.position.x - before.pose.position.x) * c + (after.pose.position.z - before.pose.position.z) * s);
  const double expected = 0.5 * kG * (s - 0.2 * c) * 0.5 * 0.5;
  EXPECT_NEAR(moved, expected, 0.02 * expected);
}

}  // namespace
}  // namespace rbs_test
