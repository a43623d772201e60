// The pile of issue 16, at the settings the established engines were
// measured with: the many-bodies scene (box_grid.h: N boxes of 0.2 × 0.1 ×
// 0.05 m half extents, 1 kg, on a grid 0.6 m apart, dropped from 0.5–1.5 m
// with random orientations) with restitution 0.5 and friction 0.5, Δt = 1 ms.
// Per run it prints one line: the time per body-step over the first 2 s;
// the share at rest at 2 s by the sleep rule (core::atRest: asleep, or
// below the sleep speeds for the sleep time) and by the peers' rule
// (|v| < 0.01 m/s and |ω| < 0.1 rad/s at that instant), the same two at
// 3 s, the deepest penetration over the 3 s, and the process's peak
// resident memory. bullet_pile prints the same line for Bullet.
// Usage: pile_bench N [runs] [restitution]; RBS_THREADS=k limits the step
//        to k threads; restitution (default 0.5) is for measuring the pile
//        at the bounce Bullet actually gives (bullet_bounce, bench/README.md);
//        RBS_PILE_SEED=s draws another pile (box_grid.h).
//        pile_bench --yaml N URDF: the same scene as an rbsim world config on
//        stdout (every box from URDF), to measure rbsim on it.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "box_grid.h"
#include "rigid_body_sim/core/step/diagnostics.h"

using namespace rigid_body_sim::core;

namespace {

struct Shares {
  double sleep_rule = 0.0, peers_rule = 0.0;  // %
};

Shares atRestShares(const Model& model, const State& s) {
  int asleep = 0, slow = 0;
  for (const BodyState& b : s.bodies) {
    asleep += atRest(model, b);
    slow += b.v_WB.norm() < 0.01 && b.w_B.norm() < 0.1;  // |ω| is the same in any axes
  }
  const double n = static_cast<double>(s.bodies.size());
  return {100.0 * asleep / n, 100.0 * slow / n};
}

}  // namespace

/// The scene as rbsim's world config: the settings, then one entry per box.
void printWorld(int n, const char* urdf) {
  const auto scene = rigid_body_sim::bench::boxGrid(n, {}, rigid_body_sim::bench::pileSeed());
  std::printf("contact: {restitution: 0.5, friction: 0.5}\nbodies:\n");
  for (int i = 0; i < n; ++i) {
    const LinkState l = linkState(scene.model.body(i), scene.start.bodies[i]);
    std::printf(
        "  - {name: box%d, urdf: %s, initial: {position: [%.17g, %.17g, %.17g], quaternion: [%.17g, %.17g, %.17g, "
        "%.17g]}}\n",
        i, urdf, l.p_WL.x(), l.p_WL.y(), l.p_WL.z(), l.q_WL.x(), l.q_WL.y(), l.q_WL.z(), l.q_WL.w());
  }
}

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == "--yaml") {
    printWorld(std::atoi(argv[2]), argv[3]);
    return 0;
  }
  const int n = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 1;
  ContactSettings contact;
  contact.restitution = argc > 3 ? std::atof(argv[3]) : 0.5;
  contact.friction = 0.5;
  const auto scene = rigid_body_sim::bench::boxGrid(n, contact, rigid_body_sim::bench::pileSeed());
  for (int r = 0; r < runs; ++r) {
    State s = scene.start;
    Workspace ws;
    if (const char* t = std::getenv("RBS_THREADS")) ws.threads = std::atoi(t);
    double deepest = 0.0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < 2000; ++k) {
      step(scene.model, s, {}, &ws);
      deepest = std::max(deepest, ws.deepest_penetration);
    }
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
    const Shares two = atRestShares(scene.model, s);
    for (int k = 0; k < 1000; ++k) {
      step(scene.model, s, {}, &ws);
      deepest = std::max(deepest, ws.deepest_penetration);
    }
    const Shares three = atRestShares(scene.model, s);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf(
        "engine rbs N %d ns_per_body_step %.1f rest2_sleep %.1f rest2_peers %.1f rest3_sleep %.1f rest3_peers %.1f "
        "deepest_mm %.3f peak_rss_kb %ld\n",
        n, ns / 2000.0 / n, two.sleep_rule, two.peers_rule, three.sleep_rule, three.peers_rule, 1e3 * deepest,
        usage.ru_maxrss);
    std::fflush(stdout);
  }
}
