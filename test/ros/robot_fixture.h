// The fixture of the robot rostests (robot_test.cpp, diff_drive_test.cpp,
// trajectory_test.cpp): the node's fixture, the joint_states received,
// waiting in sim time, and two controllers' Float64 commands.
#pragma once

#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Float64.h>

#include <string>
#include <vector>

#include "node_fixture.h"

namespace rbs_test {

class RobotNode : public Node {
 protected:
  /// Subscribes /joint_states (every message to `seen_` too) and waits for the first.
  void listen() {
    joints_ = nh_.subscribe<sensor_msgs::JointState>("/joint_states", 1000,
                                                     [this](const sensor_msgs::JointState::ConstPtr& m) {
                                                       last_ = *m;
                                                       seen_.push_back(*m);
                                                     });
    ASSERT_TRUE(spinUntil([&] { return !last_.name.empty(); }, 30.0));
  }
  /// listen(), and `first`, `second`: the two controllers command() addresses.
  void start(const std::string& first, const std::string& second) {
    first_ = nh_.advertise<std_msgs::Float64>(first, 1, true);
    second_ = nh_.advertise<std_msgs::Float64>(second, 1, true);
    listen();
  }
  /// The two controllers' commands.
  void command(double first, double second) {
    std_msgs::Float64 a, b;
    a.data = first;
    b.data = second;
    first_.publish(a);
    second_.publish(b);
  }
  /// Waits `seconds` of sim time (the stamps of joint_states).
  void wait(double seconds) {
    const double until = last_.header.stamp.toSec() + seconds;
    ASSERT_TRUE(spinUntil([&] { return last_.header.stamp.toSec() >= until; }, 60.0));
  }
  sensor_msgs::JointState last_;
  std::vector<sensor_msgs::JointState> seen_;  ///< every joint_states received

 private:
  ros::Publisher first_, second_;
  ros::Subscriber joints_;
};

}  // namespace rbs_test
