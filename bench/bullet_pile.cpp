// The pile of issue 16 through Bullet 3.24, so that pile_bench's figures
// have their peer from the same run: the same boxes in the same places and
// orientations (box_grid.h), with Bullet's defaults as a user gets them
// (bullet_world.h: friction and restitution 0.5 per pair); Δt = 1 ms, one
// substep. Prints pile_bench's line ("-" for the sleep rule, which Bullet
// has not got with deactivation off). The deepest penetration is the most
// negative distance of any manifold point after each step.
// Usage: bullet_pile N [runs]; RBS_PILE_SEED as for pile_bench
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "box_grid.h"
#include "bullet_world.h"

namespace {

using rigid_body_sim::core::LinkState;

struct World : rigid_body_sim::bench::BulletWorld {
  explicit World(const std::vector<LinkState>& start) : BulletWorld(start, 0.5, 0.5) {}

  /// The deepest penetration of any contact point now (m, ≥ 0).
  double deepest() {
    double d = 0.0;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      for (int p = 0; p < manifold->getNumContacts(); ++p) d = std::max(d, -manifold->getContactPoint(p).getDistance());
    }
    return d;
  }

  double atRestShare() const {
    int slow = 0;
    for (std::size_t i = 1; i < bodies.size(); ++i) {
      slow += bodies[i]->getLinearVelocity().length() < 0.01 && bodies[i]->getAngularVelocity().length() < 0.1;
    }
    return 100.0 * slow / static_cast<double>(bodies.size() - 1);
  }
};

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 1;
  std::vector<LinkState> start;
  {
    const auto scene = rigid_body_sim::bench::boxGrid(n, {}, rigid_body_sim::bench::pileSeed());
    for (int i = 0; i < n; ++i) start.push_back(linkState(scene.model.body(i), scene.start.bodies[i]));
  }
  for (int r = 0; r < runs; ++r) {
    World w(start);
    double deepest = 0.0;
    const double dt = 1e-3;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < 2000; ++k) {
      w.step(dt);
      deepest = std::max(deepest, w.deepest());
    }
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
    const double two = w.atRestShare();
    for (int k = 0; k < 1000; ++k) {
      w.step(dt);
      deepest = std::max(deepest, w.deepest());
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf(
        "engine bullet N %d ns_per_body_step %.1f rest2_sleep - rest2_peers %.1f rest3_sleep - rest3_peers %.1f "
        "deepest_mm %.3f peak_rss_kb %ld\n",
        n, ns / 2000.0 / n, two, w.atRestShare(), 1e3 * deepest, usage.ru_maxrss);
    std::fflush(stdout);
  }
}
