// Times sim_node's ~spawn_body and ~delete_body as a client sees them, over
// persistent connections (bench/world_edit.sh): ROUNDS spawns of BOX_URDF
// (a file) as "probe", each followed by its delete, then MESH_ROUNDS of
// MESH_URDF (a body whose distance grid is built at spawn), one a second.
// Prints the median, 90th percentile and largest latency of each, in ms.
// Usage: edit_latency BOX_URDF ROUNDS [MESH_URDF MESH_ROUNDS]
#include <ros/ros.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "rigid_body_sim/DeleteBody.h"
#include "rigid_body_sim/SpawnBody.h"

namespace {

using Clock = std::chrono::steady_clock;

void report(const char* what, std::vector<double> ms) {
  if (ms.empty()) return;
  std::sort(ms.begin(), ms.end());
  std::printf("%-12s %4zu calls: median %8.3f ms, p90 %8.3f ms, max %8.3f ms\n", what, ms.size(), ms[ms.size() / 2],
              ms[ms.size() * 9 / 10], ms.back());
}

double since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "edit_latency", ros::init_options::AnonymousName);
  if (argc < 3) {
    std::fprintf(stderr, "usage: edit_latency BOX_URDF ROUNDS [MESH_URDF MESH_ROUNDS]\n");
    return 2;
  }
  ros::NodeHandle nh;
  ros::service::waitForService("/sim_node/spawn_body");
  ros::ServiceClient spawn = nh.serviceClient<rigid_body_sim::SpawnBody>("/sim_node/spawn_body", true);
  ros::ServiceClient remove = nh.serviceClient<rigid_body_sim::DeleteBody>("/sim_node/delete_body", true);
  const auto run = [&](const std::string& urdf, int rounds, std::vector<double>& spawns, std::vector<double>& deletes,
                       double pause) {
    for (int k = 0; k < rounds; ++k) {
      rigid_body_sim::SpawnBody s;
      s.request.name = "probe";
      s.request.urdf_file = urdf;
      s.request.pose.position.x = -5.0;
      s.request.pose.position.y = -5.0;
      s.request.pose.position.z = 0.5;
      s.request.pose.orientation.w = 1.0;
      auto start = Clock::now();
      if (!spawn.call(s) || !s.response.success) {
        std::fprintf(stderr, "spawn failed: %s\n", s.response.message.c_str());
        std::exit(1);
      }
      spawns.push_back(since(start));
      rigid_body_sim::DeleteBody d;
      d.request.name = "probe";
      start = Clock::now();
      if (!remove.call(d) || !d.response.success) {
        std::fprintf(stderr, "delete failed: %s\n", d.response.message.c_str());
        std::exit(1);
      }
      deletes.push_back(since(start));
      if (pause > 0.0) ros::WallDuration(pause).sleep();
    }
  };
  std::vector<double> box_spawns, box_deletes, mesh_spawns, mesh_deletes;
  run(argv[1], std::atoi(argv[2]), box_spawns, box_deletes, 0.01);
  if (argc > 4) run(argv[3], std::atoi(argv[4]), mesh_spawns, mesh_deletes, 1.0);
  report("spawn box", box_spawns);
  report("delete box", box_deletes);
  report("spawn mesh", mesh_spawns);
  report("delete mesh", mesh_deletes);
  return 0;
}
