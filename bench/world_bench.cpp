// Many bodies (issue 5): N boxes (half extents 0.2 × 0.1 × 0.05 m, 1 kg) on a
// grid 0.6 m apart, dropped from 0.5–1.5 m with varied orientations onto the
// ground, 2 s at Δt = 1 ms. Prints, per N, the median over R runs of ns per
// step and per body-step, and (from the last run) the share at rest at the
// end (asleep, or below the sleep speeds for the sleep time: core::atRest),
// the share slower than the sleep speeds at the end, the deepest
// penetration, the lowest centre of mass and a hash of the final state's
// bits (stateHash: equal before and after a refactoring means nothing changed).
// Usage: world_bench [runs] [N ...]; RBS_THREADS=k limits the step to k threads.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "box_grid.h"

using namespace rigid_body_sim::core;
using rigid_body_sim::bench::boxGrid;

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 3;
  std::vector<int> sizes;
  for (int i = 2; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
  if (sizes.empty()) sizes = {1, 10, 100, 1000};
  std::printf("%6s %14s %16s %10s %10s %14s %12s %18s\n", "N", "ns/step", "ns/body-step", "at rest", "slow",
              "deepest (mm)", "lowest z (m)", "state hash");
  for (int n : sizes) {
    const auto scene = boxGrid(n);
    std::vector<double> ns;
    State s;
    double deepest = 0.0;
    for (int r = 0; r < runs; ++r) {
      s = scene.start;
      Workspace ws;
      if (const char* t = std::getenv("RBS_THREADS")) ws.threads = std::atoi(t);
      deepest = 0.0;
      const auto t0 = std::chrono::steady_clock::now();
      for (int k = 0; k < 2000; ++k) {
        step(scene.model, s, {}, &ws);
        deepest = std::max(deepest, ws.deepest_penetration);
      }
      ns.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / 2000);
    }
    std::sort(ns.begin(), ns.end());
    int resting = 0, slow = 0;
    double lowest = 1e9;
    const SleepSettings& sleep = scene.model.sleep();
    for (const BodyState& b : s.bodies) {
      resting += atRest(scene.model, b);
      slow += b.v_WB.norm() < sleep.linear_velocity && b.w_B.norm() < sleep.angular_velocity;
      lowest = std::min(lowest, b.p_WB.z());
    }
    std::printf("%6d %14.0f %16.1f %9.1f%% %9.1f%% %14.4f %12.4f %18llx\n", n, ns[ns.size() / 2], ns[ns.size() / 2] / n,
                100.0 * resting / n, 100.0 * slow / n, 1e3 * deepest, lowest,
                static_cast<unsigned long long>(rigid_body_sim::bench::stateHash(s)));
  }
}
