// How fast a node's sim time runs against the wall, read on /clock
// (bench/node_rtf.sh): from the first /clock message past sim time 0 (a
// node started paused publishes 0 until unpaused) until sim time reaches
// UNTIL seconds, prints "sim_s S wall_s W real_time_factor S/W" and exits.
// Exits 1 if no /clock reaches UNTIL within TIMEOUT wall seconds.
// Usage: clock_rtf UNTIL [TIMEOUT]
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>

int main(int argc, char** argv) {
  ros::init(argc, argv, "clock_rtf", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  if (argc < 2) {
    std::fprintf(stderr, "usage: clock_rtf UNTIL [TIMEOUT]\n");
    return 2;
  }
  const double until = std::atof(argv[1]);
  const double timeout = argc > 2 ? std::atof(argv[2]) : 600.0;
  using Clock = std::chrono::steady_clock;
  std::optional<std::pair<double, Clock::time_point>> first;
  bool done = false;
  ros::NodeHandle nh;
  const ros::Subscriber sub =
      nh.subscribe<rosgraph_msgs::Clock>("/clock", 1000, [&](const rosgraph_msgs::Clock::ConstPtr& m) {
        const auto now = Clock::now();
        const double sim = m->clock.toSec();
        if (sim <= 0.0) return;
        if (!first) first = std::make_pair(sim, now);
        if (done || sim < until) return;
        const double wall = std::chrono::duration<double>(now - first->second).count();
        std::printf("sim_s %.6f wall_s %.6f real_time_factor %.4f\n", sim - first->first, wall,
                    (sim - first->first) / wall);
        done = true;
      });
  const auto start = Clock::now();
  while (!done && std::chrono::duration<double>(Clock::now() - start).count() < timeout) {
    ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.01));
  }
  return done ? 0 : 1;
}
