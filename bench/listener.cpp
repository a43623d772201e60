// A light subscriber for bench/node_bench.sh and bench/robot_bench.sh: takes
// /odom, /tf and /joint_states so the node really serializes and sends what
// it publishes, and costs little itself.
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "bench_listener", ros::init_options::AnonymousName);
  ros::NodeHandle nh;
  long count = 0;
  const auto odom =
      nh.subscribe<nav_msgs::Odometry>("/odom", 100, [&](const nav_msgs::Odometry::ConstPtr&) { ++count; });
  const auto tf = nh.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr&) { ++count; });
  const auto joints = nh.subscribe<sensor_msgs::JointState>("/joint_states", 100,
                                                            [&](const sensor_msgs::JointState::ConstPtr&) { ++count; });
  ros::spin();
  return count < 0;
}
