// Calls a service from T threads, N times each, and counts the calls that
// fail (bench/service_churn.sh). Usage:
//   service_hammer SERVICE N T [persistent 0|1]
// SERVICE is /sim_node/get_state (rigid_body_sim/GetState, body "box") or a
// std_srvs/Trigger service. Without `persistent` each call opens and closes
// its own TCP connection (a non-persistent ros::ServiceClient, as
// ros::service::call and rosservice use).
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "rigid_body_sim/GetState.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "service_hammer", ros::init_options::AnonymousName);
  if (argc < 4) {
    std::fprintf(stderr, "usage: service_hammer SERVICE N T [persistent 0|1]\n");
    return 2;
  }
  ros::NodeHandle nh;
  const std::string service = argv[1];
  const int calls = std::atoi(argv[2]), threads = std::atoi(argv[3]);
  const bool persistent = argc > 4 && std::atoi(argv[4]) != 0;
  const bool get_state = service.find("get_state") != std::string::npos;
  std::atomic<long> ok{0}, failed{0};
  std::vector<std::thread> pool;
  for (int k = 0; k < threads; ++k) {
    pool.emplace_back([&] {
      ros::ServiceClient client = get_state ? nh.serviceClient<rigid_body_sim::GetState>(service, persistent)
                                            : nh.serviceClient<std_srvs::Trigger>(service, persistent);
      for (int i = 0; i < calls; ++i) {
        bool good;
        if (get_state) {
          rigid_body_sim::GetState srv;
          srv.request.body = "box";
          good = client.call(srv);
        } else {
          std_srvs::Trigger srv;
          good = client.call(srv);
        }
        (good ? ok : failed)++;
      }
    });
  }
  for (std::thread& t : pool) t.join();
  std::printf("roscpp %s %s: %ld ok, %ld failed\n", persistent ? "persistent" : "one connection per call",
              service.c_str(), ok.load(), failed.load());
  return 0;
}
