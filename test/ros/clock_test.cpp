// One clock: what a step returns, the stamps of /odom and tf, and the
// start_time a user gives are all on the node's clock, which a test node can
// compare with its own ros::Time::now(). clock_sim_time.test runs this suite
// with /use_sim_time, clock_wall.test without.
#include <nav_msgs/Odometry.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <vector>

#include "node_fixture.h"

namespace {

using namespace rbs_test;

class Clock : public Node {
 protected:
  void SetUp() override {
    Node::SetUp();
    ASSERT_TRUE(trigger("unpause"));  // whatever the last test left
    odom_sub_ = nh_.subscribe<nav_msgs::Odometry>(
        "/odom", 1000, [this](const nav_msgs::Odometry::ConstPtr& m) { odom_.push_back(*m); });
    ASSERT_TRUE(spinUntil([&] { return !odom_.empty(); }, 30.0));
  }

  /// Steps once and waits for the odometry of that step.
  rigid_body_sim::Step::Response stepAndSee(int n) {
    const auto r = step(n);
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_TRUE(spinUntil([&] { return !odom_.empty() && odom_.back().header.stamp == r.time; }, 10.0))
        << "no odometry stamped " << r.time;
    return r;
  }

  /// |stamp − this node's now()|, s.
  static double offNow(const ros::Time& stamp) { return std::abs((stamp - ros::Time::now()).toSec()); }

  std::vector<nav_msgs::Odometry> odom_;
  ros::Subscriber odom_sub_;
};

TEST_F(Clock, PausedStepsAreExactlyDtApartInResponsesAndOdometry) {
  ASSERT_TRUE(trigger("pause"));
  ros::WallDuration(0.3).sleep();  // let what was published while running arrive
  ros::spinOnce();
  odom_.clear();
  std::vector<ros::Time> times;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) {
      const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(0.5);
      spinUntil([&] { return ros::WallTime::now() >= until; }, 1.0);
    }
    times.push_back(stepAndSee(1).time);
  }
  EXPECT_EQ((times[1] - times[0]).toNSec(), 1000000);  // Δt = 1 ms exactly, though 0.5 s of wall time passed
  EXPECT_EQ((times[2] - times[1]).toNSec(), 1000000);
  ros::WallDuration(0.3).sleep();
  ros::spinOnce();
  ASSERT_EQ(odom_.size(), 3u) << "one odometry message per step, no bursts";
  for (int k = 0; k < 3; ++k) EXPECT_EQ(odom_[k].header.stamp, times[k]);
  EXPECT_EQ(state().stamp, times[2]);  // get_state reads the same clock
}

TEST_F(Clock, ALongStepDeliversEveryOdometryMessageOfIt) {
  // 3000 steps in one call publish 300 /odom messages (100 Hz) at once: all
  // arrive, in order, 10 ms apart (a publisher queue of 10 let 189 of 300 through).
  ASSERT_TRUE(trigger("pause"));
  ros::WallDuration(0.3).sleep();
  ros::spinOnce();
  const ros::Time from = stepAndSee(1).time;
  odom_.clear();
  const auto r = step(3000);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_TRUE(spinUntil([&] { return !odom_.empty() && odom_.back().header.stamp == r.time; }, 30.0));
  ros::WallDuration(0.3).sleep();  // nothing more comes
  ros::spinOnce();
  ASSERT_GE(odom_.size(), 300u);
  EXPECT_LE(odom_.size(), 301u);  // and at the call's end, when that is not on the 10 ms grid
  EXPECT_EQ(odom_.back().header.stamp, r.time);
  ros::Time last = from;
  for (std::size_t k = 0; k < odom_.size(); ++k) {
    const int64_t gap = (odom_[k].header.stamp - last).toNSec();
    ASSERT_GT(gap, 0) << k;
    ASSERT_LE(gap, 10000000) << k << ": one missing";
    last = odom_[k].header.stamp;
  }
}

TEST_F(Clock, AWrenchAtAnOdometryStampPlusATenthFiresThenAndDeliversForceTimesDuration) {
  ASSERT_TRUE(trigger("pause"));
  stepAndSee(1);
  const ros::Time seen = odom_.back().header.stamp;  // as a user reads it from /odom
  const double v0 = state().twist.linear.x;
  rigid_body_sim::ApplyWrench w;
  w.request.frame = "world";
  w.request.force = vec(2, 0, 0);  // on 1 kg
  w.request.start_time = seen + ros::Duration(0.1);
  w.request.duration = ros::Duration(0.05);
  w = call("apply_wrench", w);
  ASSERT_TRUE(w.response.success) << w.response.message;
  EXPECT_NE(w.response.message.find("from t = "), std::string::npos) << w.response.message;
  ASSERT_TRUE(step(100).success);
  EXPECT_EQ(state().twist.linear.x, v0) << "fired before its start_time";
  ASSERT_TRUE(step(1).success);
  EXPECT_NEAR(state().twist.linear.x - v0, 2.0 * kDt, 1e-12) << "did not fire at its start_time";
  ASSERT_TRUE(step(59).success);
  EXPECT_NEAR(state().twist.linear.x - v0, 2.0 * 0.05, 1e-12);  // force × duration, then nothing
}

TEST_F(Clock, AStartTimeInThePastAppliesAtOnceOneFarAheadIsRefused) {
  ASSERT_TRUE(trigger("pause"));
  const ros::Time now = stepAndSee(1).time;
  const double v0 = state().twist.linear.y;
  rigid_body_sim::ApplyWrench w;
  w.request.force = vec(0, 1, 0);
  w.request.duration = ros::Duration(0.02);
  w.request.start_time = now + ros::Duration(2e6);  // another clock's reading, or a typo
  w = call("apply_wrench", w);
  EXPECT_FALSE(w.response.success);
  EXPECT_NE(w.response.message.find("another clock"), std::string::npos) << w.response.message;
  w.request.start_time = ros::Time(0, 1);  // long past: now, for the whole duration
  w = call("apply_wrench", w);
  ASSERT_TRUE(w.response.success) << w.response.message;
  EXPECT_NE(w.response.message.find("past"), std::string::npos) << w.response.message;
  ASSERT_TRUE(step(30).success);
  EXPECT_NEAR(state().twist.linear.y - v0, 1.0 * 0.02, 1e-12);
}

TEST_F(Clock, RunningStampsAreOnTheCallersClockAndTfNeedNotExtrapolate) {
  ASSERT_TRUE(trigger("unpause"));
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  odom_.clear();
  ASSERT_TRUE(spinUntil([&] { return odom_.size() >= 20; }, 10.0));
  EXPECT_LT(offNow(odom_.back().header.stamp), 0.25)
      << "stamp " << odom_.back().header.stamp << ", now " << ros::Time::now();
  // A listener asking for a moment just past gets it (no extrapolation).
  ASSERT_TRUE(spinUntil([&] { return buffer.canTransform("world", kLink, ros::Time(0)); }, 10.0));
  ros::WallDuration(0.2).sleep();  // the listener has been receiving for a while
  const ros::Time recent = ros::Time::now() - ros::Duration(0.05);
  std::string why;
  EXPECT_TRUE(buffer.canTransform("world", kLink, recent, ros::Duration(2.0), &why)) << why;
  // Paused a while and resumed: stamps pick up this node's clock again.
  ASSERT_TRUE(trigger("pause"));
  ros::WallDuration(1.0).sleep();
  ASSERT_TRUE(trigger("unpause"));
  ros::spinOnce();
  odom_.clear();
  ASSERT_TRUE(spinUntil([&] { return odom_.size() >= 5; }, 10.0));
  EXPECT_LT(offNow(odom_.back().header.stamp), 0.25)
      << "stamp " << odom_.back().header.stamp << ", now " << ros::Time::now();
  for (std::size_t i = 1; i < odom_.size(); ++i) EXPECT_GT(odom_[i].header.stamp, odom_[i - 1].header.stamp);
  // Paused and stepped 2 s at once: the node's clock is ahead of the wall
  // clock; it never goes back, so running waits for the wall clock to catch up.
  ASSERT_TRUE(trigger("pause"));
  const ros::Time ahead = step(2000).time;
  // While paused nothing is published: let what was sent before (and the
  // step's own odometry, stamped `ahead`) arrive, then keep only what the
  // running node sends. (One spinOnce could leave a message in transit.)
  spinUntil([] { return false; }, 0.3);
  odom_.clear();
  ASSERT_TRUE(trigger("unpause"));
  ASSERT_TRUE(spinUntil([&] { return odom_.size() >= 5; }, 10.0));
  EXPECT_GT(odom_.front().header.stamp, ahead);
  EXPECT_LT(offNow(odom_.back().header.stamp), 0.25)
      << "stamp " << odom_.back().header.stamp << ", now " << ros::Time::now();
}

}  // namespace
