// The sensors through the node (issue 15), as a subscriber sees them:
// imu.test's box rests on the ground with an IMU tilted 0.3 rad about x; it
// reads the specific force +g up in its own axes, at its rate, in its own
// frame, which /tf_static places on the body. odom_noise.test's box has
// noisy odometry: its difference from ground_truth has the configured σs.
// contacts.test's box rests on the ground: ~contacts says the ground holds
// it up with m g, asleep or not. odom_noise_steps.test: two nodes' noisy
// odometry, stepped in different batches, draws the same noise.
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>
#include <tf2_msgs/TFMessage.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <vector>

#include "../test_util.h"
#include "node_fixture.h"
#include "rigid_body_sim/Contacts.h"

namespace rbs_test {
namespace {

using rigid_body_sim::test::meanAndSigma;

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
  // Without odom_noise: no ground_truth topic, odom exact as ever.
  ros::master::V_TopicInfo topics;
  ros::master::getTopics(topics);
  for (const auto& t : topics) EXPECT_NE(t.name, "/ground_truth");
}

class NodeOdomNoise : public Node {};

TEST_F(NodeOdomNoise, OdomLessGroundTruthHasTheConfiguredSigmasAndCovariances) {
  // 3000 pairs of the same stamp: the σs' sampling error is 1.3 %; within 6 %.
  std::map<ros::Time, nav_msgs::Odometry> noisy, truth;
  const auto keep = [](std::map<ros::Time, nav_msgs::Odometry>& into) {
    return [&into](const nav_msgs::Odometry::ConstPtr& m) { into[m->header.stamp] = *m; };
  };
  const ros::Subscriber a = nh_.subscribe<nav_msgs::Odometry>("/odom", 5000, keep(noisy));
  const ros::Subscriber b = nh_.subscribe<nav_msgs::Odometry>("/ground_truth", 5000, keep(truth));
  std::vector<std::vector<double>> p(3), o(3), v(3), w(3);
  ASSERT_TRUE(spinUntil(
      [&] {
        std::size_t pairs = 0;
        for (const auto& [stamp, m] : noisy) pairs += truth.count(stamp);
        return pairs >= 3000;
      },
      30.0));
  const nav_msgs::Odometry* last = nullptr;
  for (const auto& [stamp, n] : noisy) {
    const auto t = truth.find(stamp);
    if (t == truth.end()) continue;
    const auto& np = n.pose.pose;
    const auto& tp = t->second.pose.pose;
    p[0].push_back(np.position.x - tp.position.x);
    p[1].push_back(np.position.y - tp.position.y);
    p[2].push_back(np.position.z - tp.position.z);
    const Eigen::Quaterniond qn(np.orientation.w, np.orientation.x, np.orientation.y, np.orientation.z);
    const Eigen::Quaterniond qt(tp.orientation.w, tp.orientation.x, tp.orientation.y, tp.orientation.z);
    const Eigen::AngleAxisd tilt(qt.conjugate() * qn);
    for (int i = 0; i < 3; ++i) o[i].push_back(tilt.angle() * tilt.axis()[i]);
    const auto& nt = n.twist.twist;
    const auto& tt = t->second.twist.twist;
    v[0].push_back(nt.linear.x - tt.linear.x);
    v[1].push_back(nt.linear.y - tt.linear.y);
    v[2].push_back(nt.linear.z - tt.linear.z);
    w[0].push_back(nt.angular.x - tt.angular.x);
    w[1].push_back(nt.angular.y - tt.angular.y);
    w[2].push_back(nt.angular.z - tt.angular.z);
    last = &n;
  }
  const auto check = [](const std::vector<double>& x, double sigma, const char* what) {
    const auto [mean, sd] = meanAndSigma(x);
    EXPECT_LT(std::abs(mean), 0.1 * sigma) << what;  // 4.5 standard errors
    EXPECT_NEAR(sd, sigma, 0.06 * sigma) << what;
  };
  for (int i = 0; i < 3; ++i) {
    check(p[i], 0.01, "position");
    check(o[i], 0.02, "orientation");
    check(v[i], 0.03, "linear velocity");
    check(w[i], 0.04, "angular velocity");
  }
  ASSERT_NE(last, nullptr);
  EXPECT_DOUBLE_EQ(last->pose.covariance[0], 0.01 * 0.01);
  EXPECT_DOUBLE_EQ(last->pose.covariance[35], 0.02 * 0.02);
  EXPECT_DOUBLE_EQ(last->twist.covariance[0], 0.03 * 0.03);
  EXPECT_DOUBLE_EQ(last->twist.covariance[35], 0.04 * 0.04);
  EXPECT_EQ(truth.begin()->second.pose.covariance[0], 1e-9);  // ground truth: ~covariance, as odom without noise
}

class NodeContacts : public Node {};

TEST_F(NodeContacts, ARestingBoxIsHeldUpByTheGroundWithItsWeightAsleepOrNot) {
  rigid_body_sim::Contacts last;
  int count = 0;
  const ros::Subscriber sub = nh_.subscribe<rigid_body_sim::Contacts>("/sim_node/contacts", 10,
                                                                      [&](const rigid_body_sim::Contacts::ConstPtr& m) {
                                                                        last = *m;
                                                                        ++count;
                                                                      });
  visualization_msgs::MarkerArray drawn;
  const ros::Subscriber markers = nh_.subscribe<visualization_msgs::MarkerArray>(
      "/sim_node/contact_markers", 10, [&](const visualization_msgs::MarkerArray::ConstPtr& m) { drawn = *m; });
  spinUntil([] { return false; }, 2.0);  // asleep after half a second at rest
  ASSERT_GT(count, 10);
  EXPECT_EQ(last.header.frame_id, "world");
  ASSERT_EQ(last.pairs.size(), 1u);
  const rigid_body_sim::ContactPair& p = last.pairs[0];
  EXPECT_EQ(p.body, kLink);  // robot_description's body is named after its root link
  EXPECT_EQ(p.other, "scene[0]");
  EXPECT_NEAR(p.normal_force.z, kG, 1e-6 * kG);
  EXPECT_NEAR(std::hypot(p.normal_force.x, p.normal_force.y), 0.0, 1e-9);
  EXPECT_NEAR(p.normal.z, 1.0, 1e-9);
  EXPECT_GE(p.points.size(), 3u);
  EXPECT_GE(p.depth, 0.0);
  ASSERT_GE(drawn.markers.size(), 2u);
  EXPECT_EQ(drawn.markers.front().action, visualization_msgs::Marker::DELETEALL);
  EXPECT_EQ(drawn.markers.back().type, visualization_msgs::Marker::SPHERE_LIST);
}

// odom_noise_steps.test: two identical nodes, paused, a box with noisy
// odometry each at publish_rate 100 Hz (every 10 steps); one stepped 10
// steps at a time, the other 3 then 7. Both publish the same reports, to
// the bit, at the same sim times: the noise follows the step count. The
// end of each ~step used to draw a report of its own, so the second node
// published twice as many and its noise ran ahead of the first's.
TEST(NodeOdomNoiseSteps, TheNoiseFollowsTheStepCountNotWhereAStepEnds) {
  ros::NodeHandle nh;
  std::vector<nav_msgs::Odometry> a, b;
  const auto into = [&nh](const std::string& topic, std::vector<nav_msgs::Odometry>& out) {
    return nh.subscribe<nav_msgs::Odometry>(topic, 1000,
                                            [&out](const nav_msgs::Odometry::ConstPtr& m) { out.push_back(*m); });
  };
  const ros::Subscriber sa = into("/a/odom", a), sb = into("/b/odom", b);
  ASSERT_TRUE(spinUntil([&] { return sa.getNumPublishers() > 0 && sb.getNumPublishers() > 0; }, 30.0));
  spinUntil([] { return false; }, 0.3);  // what came at start (or not): not compared
  a.clear();
  b.clear();
  // One persistent connection per node, as Node::call says why: a
  // connection per call now and then loses one in transport.
  ASSERT_TRUE(ros::service::waitForService("/a/sim_node/step", 30000));
  ASSERT_TRUE(ros::service::waitForService("/b/sim_node/step", 30000));
  ros::ServiceClient step_a = nh.serviceClient<rigid_body_sim::Step>("/a/sim_node/step", true);
  ros::ServiceClient step_b = nh.serviceClient<rigid_body_sim::Step>("/b/sim_node/step", true);
  const auto step = [](ros::ServiceClient& client, int n) {
    rigid_body_sim::Step s;
    s.request.steps = n;
    ASSERT_TRUE(client.call(s)) << client.getService();
    ASSERT_TRUE(s.response.success) << s.response.message;
  };
  for (int k = 0; k < 20; ++k) {
    step(step_a, 10);
    step(step_b, 3);
    step(step_b, 7);
  }
  ASSERT_TRUE(spinUntil([&] { return a.size() >= 20 && b.size() >= 20; }, 30.0));
  spinUntil([] { return false; }, 0.5);  // any more on their way
  ASSERT_EQ(a.size(), 20u);
  ASSERT_EQ(b.size(), 20u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const geometry_msgs::Pose &p = a[i].pose.pose, &q = b[i].pose.pose;
    EXPECT_EQ(p.position.x, q.position.x) << i;
    EXPECT_EQ(p.position.y, q.position.y) << i;
    EXPECT_EQ(p.orientation.z, q.orientation.z) << i;
    EXPECT_EQ(a[i].twist.twist.linear.x, b[i].twist.twist.linear.x) << i;
    EXPECT_EQ(a[i].twist.twist.angular.z, b[i].twist.twist.angular.z) << i;
  }
  EXPECT_NE(a[0].pose.pose.position.x, a[1].pose.pose.position.x);  // noisy: each report its own draw
}

}  // namespace
}  // namespace rbs_test
