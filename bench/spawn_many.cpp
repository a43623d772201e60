// Spawns or deletes N bodies through sim_node's services, one call at a
// time, over persistent connections (bench/spawn_memory.sh): "spawn" adds
// NAME0..NAME{N-1} on a square grid 0.6 m apart at height Z, "delete"
// removes them; "cycle" spawns one named r at the origin and deletes it
// again, N times (bench/robot_cycles.sh). Prints the calls' median and
// largest latency, in ms.
// Usage: spawn_many spawn|delete|cycle N URDF_FILE [Z]
#include <ros/ros.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "rigid_body_sim/DeleteBody.h"
#include "rigid_body_sim/SpawnBody.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "spawn_many", ros::init_options::AnonymousName);
  if (argc < 4) {
    std::fprintf(stderr, "usage: spawn_many spawn|delete|cycle N URDF_FILE [Z]\n");
    return 2;
  }
  const std::string what = argv[1];
  const int n = std::atoi(argv[2]);
  const double z = argc > 4 ? std::atof(argv[4]) : 0.5;
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  ros::NodeHandle nh;
  ros::service::waitForService("/sim_node/spawn_body");
  ros::ServiceClient spawn = nh.serviceClient<rigid_body_sim::SpawnBody>("/sim_node/spawn_body", true);
  ros::ServiceClient remove = nh.serviceClient<rigid_body_sim::DeleteBody>("/sim_node/delete_body", true);
  const auto add = [&](const std::string& name, double x, double y, std::string& message) {
    rigid_body_sim::SpawnBody s;
    s.request.name = name;
    s.request.urdf_file = argv[3];
    s.request.pose.position.x = x;
    s.request.pose.position.y = y;
    s.request.pose.position.z = z;
    s.request.pose.orientation.w = 1.0;
    const bool ok = spawn.call(s) && s.response.success;
    message = s.response.message;
    return ok;
  };
  const auto erase = [&](const std::string& name, std::string& message) {
    rigid_body_sim::DeleteBody d;
    d.request.name = name;
    const bool ok = remove.call(d) && d.response.success;
    message = d.response.message;
    return ok;
  };
  std::vector<double> ms;
  for (int i = 0; i < n; ++i) {
    const auto start = std::chrono::steady_clock::now();
    std::string message;
    const std::string name = what == "cycle" ? "r" : "b" + std::to_string(i);
    const bool ok = what == "spawn"    ? add(name, 0.6 * (i % side), 0.6 * (i / side), message)
                    : what == "delete" ? erase(name, message)
                                       : add(name, 0.0, 0.0, message) && erase(name, message);
    if (!ok) {
      std::fprintf(stderr, "%s %s failed: %s\n", what.c_str(), name.c_str(), message.c_str());
      return 1;
    }
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  if (!ms.empty()) {
    std::printf("%s %d: a call's latency median %.3f ms, max %.3f ms\n", what.c_str(), n, ms[ms.size() / 2], ms.back());
  }
  return 0;
}
