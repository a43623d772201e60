// The floor for the node's CPU share at 1 kHz (issue 4): a roscpp node that
// does nothing but wake every millisecond (with the node's 1 us timer slack)
// and publish one nav_msgs/Odometry on /odom and one transform on /tf, the
// two messages sim_node sends per tick, without any simulation. Measures its
// own CPU time (all threads, roscpp's included) over N ticks after a 2 s
// start during which subscribers connect, and prints the share of one core.
// Usage: publish_baseline [ticks]   (bench/node_bench.sh runs it)
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <tf2_ros/transform_broadcaster.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

namespace {

double cpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "publish_baseline", ros::init_options::AnonymousName);
  const int ticks = argc > 1 ? std::atoi(argv[1]) : 10000;
  ros::NodeHandle nh;
  const ros::Publisher odom_pub = nh.advertise<nav_msgs::Odometry>("/odom", 10);
  tf2_ros::TransformBroadcaster tf;
  prctl(PR_SET_TIMERSLACK, 1000UL, 0UL, 0UL, 0UL);
  nav_msgs::Odometry odom;
  odom.header.frame_id = "world";
  odom.child_frame_id = "base_link";
  odom.pose.pose.orientation.w = 1.0;
  geometry_msgs::TransformStamped t;
  t.header.frame_id = "world";
  t.child_frame_id = "base_link";
  t.transform.rotation.w = 1.0;

  using Clock = std::chrono::steady_clock;
  const int warmup = 2000;  // ticks: 2 s for the subscribers to connect
  auto next = Clock::now();
  const auto wall0 = next;
  double cpu0 = 0.0, wall_start = 0.0;
  for (int i = 0; i < warmup + ticks && ros::ok(); ++i) {
    if (i == warmup) {
      cpu0 = cpuSeconds();
      wall_start = std::chrono::duration<double>(Clock::now() - wall0).count();
    }
    const ros::Time now = ros::Time::now();
    odom.header.stamp = now;
    odom.pose.pose.position.z = 1e-3 * i;
    t.header.stamp = now;
    t.transform.translation.z = 1e-3 * i;
    odom_pub.publish(odom);
    tf.sendTransform(t);
    ros::spinOnce();
    next += std::chrono::microseconds(1000);
    std::this_thread::sleep_until(next);
  }
  const double wall = std::chrono::duration<double>(Clock::now() - wall0).count() - wall_start;
  std::printf("%d ticks, CPU %.2f %% of one core\n", ticks, 100.0 * (cpuSeconds() - cpu0) / wall);
}
