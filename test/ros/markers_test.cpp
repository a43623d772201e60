// What rviz needs: every body's collision shapes as markers that pass a tf2
// MessageFilter, as rviz's marker display does, even for a listener that
// subscribes late and gets the latched markers before any tf; and the frames
// of links fixed to a body. markers_world.test runs these on a world of four
// bodies (wall-anchored clock), markers_one_body.test on one body
// (sim time, run fast).
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_listener.h>

#include <map>
#include <memory>
#include <set>
#include <vector>

#include "node_fixture.h"

namespace {

using namespace rbs_test;
using visualization_msgs::Marker;

class Markers : public Node {};

TEST_F(Markers, EveryBodysShapesReachAListenerThatSubscribesLate) {
  std::vector<std::string> bodies;
  ASSERT_TRUE(ros::param::get("~bodies", bodies));
  // Past the tf buffer's 10 s from 0, where a marker stamped 0 that comes
  // before its frame is failed for good.
  ASSERT_TRUE(spinUntil([] { return ros::Time::now().toSec() > 11.0; }, 30.0));
  tf2_ros::Buffer buffer;
  tf2_ros::MessageFilter<Marker> filter(buffer, "world", 100, nh_);
  std::map<std::string, int> passed, failed;
  filter.registerCallback([&](const Marker::ConstPtr& m) { ++passed[m->ns]; });
  filter.registerFailureCallback(
      [&](const Marker::ConstPtr& m, tf2_ros::filter_failure_reasons::FilterFailureReason) { ++failed[m->ns]; });
  int arrays = 0;
  const ros::Subscriber sub = nh_.subscribe<visualization_msgs::MarkerArray>(
      "/sim_node/body_markers", 10, [&](const visualization_msgs::MarkerArray::ConstPtr& a) {
        ++arrays;
        for (const Marker& m : a->markers) filter.add(Marker::Ptr(new Marker(m)));  // as rviz does
      });
  ASSERT_TRUE(spinUntil([&] { return arrays > 0; }, 10.0));
  tf2_ros::TransformListener listener(buffer);  // tf only now: the markers came first
  const auto all_passed = [&] {
    for (const std::string& b : bodies) {
      if (passed.count(b) == 0) return false;
    }
    return true;
  };
  EXPECT_TRUE(spinUntil(all_passed, 15.0));
  for (const std::string& b : bodies) {
    EXPECT_GT(passed[b], 0) << "no marker of '" << b << "' passed the filter (" << failed[b] << " failed)";
  }
}

TEST_F(Markers, ShapesAreDrawnAsThemselvesInTheBodysFrame) {
  std::vector<std::string> bodies;
  ASSERT_TRUE(ros::param::get("~bodies", bodies));
  const visualization_msgs::MarkerArray markers = latchedMarkers("/sim_node/body_markers");
  std::set<std::string> seen;
  for (const Marker& m : markers.markers) {
    seen.insert(m.ns);
    EXPECT_TRUE(m.frame_locked);
    EXPECT_TRUE(m.type == Marker::CUBE || m.type == Marker::SPHERE || m.type == Marker::CYLINDER ||
                m.type == Marker::TRIANGLE_LIST)
        << m.ns << " type " << int(m.type);
    if (m.type == Marker::TRIANGLE_LIST) {
      EXPECT_GT(m.points.size(), 30u);
      EXPECT_EQ(m.points.size() % 3, 0u);
    }
  }
  EXPECT_EQ(seen, std::set<std::string>(bodies.begin(), bodies.end()));
}

class FixedFrames : public Node {};

TEST_F(FixedFrames, ALinkFixedToABodyIsATfFrameAtItsJointsOrigin) {
  // urdf/two_boxes.urdf: second_box is fixed 0.2 m along base_link's x.
  std::string parent, child;
  ASSERT_TRUE(ros::param::get("~parent", parent));
  ASSERT_TRUE(ros::param::get("~child", child));
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  ASSERT_TRUE(spinUntil([&] { return buffer.canTransform(parent, child, ros::Time(0)); }, 10.0))
      << "no transform " << parent << " -> " << child;
  const auto t = buffer.lookupTransform(parent, child, ros::Time(0)).transform;
  EXPECT_NEAR(t.translation.x, 0.2, 1e-12);
  EXPECT_NEAR(t.translation.y, 0.0, 1e-12);
  EXPECT_NEAR(t.translation.z, 0.0, 1e-12);
  EXPECT_NEAR(t.rotation.w, 1.0, 1e-12);
  // And through the body's moving frame, from the world.
  ASSERT_TRUE(spinUntil([&] { return buffer.canTransform("world", child, ros::Time(0)); }, 10.0));
}

}  // namespace
