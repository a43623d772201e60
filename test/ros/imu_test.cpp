// The IMU through the node (issue 15), as a subscriber sees it: imu.test's
// box rests on the ground with an IMU tilted 0.3 rad about x; it reads the
// specific force +g up in its own axes, at its rate, in its own frame,
// which /tf_static places on the body.
#include <sensor_msgs/Imu.h>
#include <tf2_msgs/TFMessage.h>

#include <cmath>
#include <vector>

#include "node_fixture.h"

namespace rbs_test {
namespace {

class NodeImu : public Node {};

TEST_F(NodeImu, ARestingBodysImuReadsGUpInItsOwnAxesAtItsRate) {
  spinUntil([] { return false; }, 1.0);  // settled on the ground
  std::vector<sensor_msgs::Imu> got;
  const ros::Subscriber sub =
      nh_.subscribe<sensor_msgs::Imu>("/imu", 100, [&](const sensor_msgs::Imu::ConstPtr& m) { got.push_back(*m); });
  ASSERT_TRUE(spinUntil([&] { return got.size() >= 20; }, 10.0));
  const double a = 0.3;
  for (std::size_t k = 1; k < got.size(); ++k) {
    const sensor_msgs::Imu& m = got[k];
    EXPECT_EQ(m.header.frame_id, "imu_link");
    EXPECT_NEAR((m.header.stamp - got[k - 1].header.stamp).toSec(), 0.005, 1e-9);  // 200 Hz of sim time
    EXPECT_NEAR(m.linear_acceleration.x, 0.0, 1e-6);
    EXPECT_NEAR(m.linear_acceleration.y, kG * std::sin(a), 1e-6);
    EXPECT_NEAR(m.linear_acceleration.z, kG * std::cos(a), 1e-6);
    EXPECT_NEAR(std::hypot(m.angular_velocity.x, m.angular_velocity.y, m.angular_velocity.z), 0.0, 1e-9);
    // The sensor frame in the world: tilted 0.3 rad about x.
    EXPECT_NEAR(m.orientation.x, std::sin(a / 2), 1e-6);
    EXPECT_NEAR(m.orientation.w, std::cos(a / 2), 1e-6);
    EXPECT_EQ(m.linear_acceleration_covariance[0], 0.0);  // no noise configured
  }
  bool placed = false;
  const ros::Subscriber tf =
      nh_.subscribe<tf2_msgs::TFMessage>("/tf_static", 10, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
        for (const auto& t : m->transforms) {
          if (t.child_frame_id == "imu_link" && t.header.frame_id == kLink) {
            placed =
                std::abs(t.transform.translation.x - 0.1) < 1e-12 && std::abs(t.transform.translation.z - 0.05) < 1e-12;
          }
        }
      });
  EXPECT_TRUE(spinUntil([&] { return placed; }, 10.0));
}

}  // namespace
}  // namespace rbs_test
