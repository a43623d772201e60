// Steered bases (ackermann.test, tricycle.test): ros_controllers'
// ackermann_steering_controller on a car (test/ros/ackermann_base.urdf, its
// rear wheels driven, its knuckles linked) and gazebo_ros_tricycle_drive
// on a tricycle (test/ros/tricycle_base.urdf, its front wheel steered and
// driven): each holds still at zero command, drives at the commanded speed
// forward and backward, and turns at the rate its steering angle gives,
// v tan δ / L from the rear axle or v sin δ / L from the steered wheel
// (docs/physics.md §11.14), as the truth and its own odometry say.
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <cmath>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/BodyStates.h"

namespace {

using namespace rbs_test;

constexpr double kWheelbase = 0.6;  // m, both URDFs'

/// The base's mean forward speed and yaw rate (truth) and the odometry's,
/// over the last `seconds` of `seconds_total` s commanding `cmd` on `topic`.
struct Averages {
  double speed = 0.0, yaw_rate = 0.0, odom_speed = 0.0, odom_yaw_rate = 0.0;
};

class SteeredBase {
 public:
  SteeredBase(const std::string& command_topic, const std::string& odom_topic) {
    odom_sub_ = nh_.subscribe<nav_msgs::Odometry>(
        odom_topic, 1000, [this](const nav_msgs::Odometry::ConstPtr& m) { odom_.push_back(*m); });
    truth_sub_ = nh_.subscribe<rigid_body_sim::BodyStates>(
        "/sim_node/body_states", 1000, [this](const rigid_body_sim::BodyStates::ConstPtr& m) { truth_.push_back(*m); });
    cmd_ = nh_.advertise<geometry_msgs::Twist>(command_topic, 10);
  }
  bool ready() {
    return spinUntil([&] { return cmd_.getNumSubscribers() > 0 && !odom_.empty() && !truth_.empty(); }, 30.0);
  }
  double simTime() const { return truth_.back().header.stamp.toSec(); }
  /// Commands (v, δ) for `seconds`, averaging over its last `last` s.
  Averages drive(double v, double delta, double seconds, double last) {
    geometry_msgs::Twist cmd;
    cmd.linear.x = v;
    cmd.angular.z = delta;
    const double from = simNow(simTime());
    EXPECT_TRUE(spinUntil(
        [&] {
          cmd_.publish(cmd);
          return simTime() >= from + seconds;
        },
        90.0));
    Averages r;
    int n = 0, m = 0;
    for (const auto& s : truth_) {
      if (s.header.stamp.toSec() < from + seconds - last) continue;
      r.speed += s.twists.at(0).linear.x;
      r.yaw_rate += s.twists[0].angular.z;
      ++n;
    }
    for (const auto& o : odom_) {
      if (o.header.stamp.toSec() < from + seconds - last) continue;
      r.odom_speed += o.twist.twist.linear.x;
      r.odom_yaw_rate += o.twist.twist.angular.z;
      ++m;
    }
    EXPECT_GT(n, 10);
    EXPECT_GT(m, 10);
    r.speed /= std::max(n, 1);
    r.yaw_rate /= std::max(n, 1);
    r.odom_speed /= std::max(m, 1);
    r.odom_yaw_rate /= std::max(m, 1);
    return r;
  }

 private:
  ros::NodeHandle nh_;
  std::vector<nav_msgs::Odometry> odom_;
  std::vector<rigid_body_sim::BodyStates> truth_;
  ros::Subscriber odom_sub_, truth_sub_;
  ros::Publisher cmd_;
};

TEST(SteeredBases, AnAckermannCarDrivesAndTurnsAsItsSteeringAngleSays) {
  SteeredBase car("/ackermann_controller/cmd_vel", "/ackermann_controller/odom");
  ASSERT_TRUE(car.ready());
  const Averages still = car.drive(0.0, 0.0, 1.0, 0.5);
  EXPECT_LT(std::abs(still.speed), 1e-3);
  EXPECT_LT(std::abs(still.yaw_rate), 1e-3);
  for (const double v : {0.5, -0.5}) {
    const Averages straight = car.drive(v, 0.0, 2.0, 1.0);
    EXPECT_NEAR(straight.speed, v, 0.01 * std::abs(v)) << v;
    EXPECT_LT(std::abs(straight.yaw_rate), 0.01) << v;
    EXPECT_NEAR(straight.odom_speed, straight.speed, 0.01 * std::abs(v)) << v;
  }
  // Steered 0.3 rad at 0.5 m/s (the rear axle's): ω = v tan δ / L.
  const double delta = 0.3, v = 0.5, w = v * std::tan(delta) / kWheelbase;
  // In a turn the rigid rims bear on their outer edges (§11.12), and the
  // base runs 1.5 % faster than its wheels say (0.5077 m/s, 0.2615 rad/s).
  const Averages turn = car.drive(v, delta, 4.0, 2.0);
  EXPECT_NEAR(turn.speed, v, 0.03 * v);
  EXPECT_NEAR(turn.yaw_rate, w, 0.04 * w);
  // The wheels turn as asked: exactly so when only the rear wheels drive
  // (ackermann.test); 0.44 % off in one local steer_bot.test run, whose
  // front wheels, driven too, slip a little as the knuckles turn.
  EXPECT_NEAR(turn.odom_yaw_rate, w, 0.01 * w);
  EXPECT_NEAR(turn.odom_speed, v, 0.01 * v);
}

TEST(SteeredBases, ATricycleDrivesAndTurnsAsItsSteeringAngleSays) {
  SteeredBase tricycle("/cmd_vel", "/odom");
  ASSERT_TRUE(tricycle.ready());
  const Averages still = tricycle.drive(0.0, 0.0, 1.0, 0.5);
  EXPECT_LT(std::abs(still.speed), 1e-3);
  for (const double v : {0.5, -0.5}) {
    const Averages straight = tricycle.drive(v, 0.0, 2.0, 1.0);
    EXPECT_NEAR(straight.speed, v, 0.01 * std::abs(v)) << v;
    EXPECT_LT(std::abs(straight.yaw_rate), 0.01) << v;
  }
  // The front wheel's rim at 0.5 m/s steered 0.4 rad: the rear axle at
  // v cos δ, turning v sin δ / L.
  const double delta = 0.4, v = 0.5, w = v * std::sin(delta) / kWheelbase;
  // The truth 2 % faster than the wheels say, as the car's (0.4695 m/s, 0.3306 rad/s).
  const Averages turn = tricycle.drive(v, delta, 4.0, 2.0);
  EXPECT_NEAR(turn.speed, v * std::cos(delta), 0.03 * v);
  EXPECT_NEAR(turn.yaw_rate, w, 0.04 * w);
  EXPECT_NEAR(turn.odom_yaw_rate, turn.yaw_rate, 0.04 * w);
}

}  // namespace
