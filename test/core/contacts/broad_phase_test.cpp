// The broad phase (src/core/broad_phase.cpp): sweep and prune in strips gives
// exactly the pairs a brute-force test of every pair's boxes gives, none
// within a collision group.
#include "contacts/broad_phase.h"

#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "../../test_util.h"
#include "step/scratch.h"

namespace rigid_body_sim::test {
namespace {

TEST(BroadPhase, FindsExactlyThePairsWhoseGrownBoxesOverlap) {
  core::ModelSpec ms = spec(shippedBox(), 1e-3, Vec3::Zero());
  ms.bodies.clear();
  const int n = 300;
  for (int i = 0; i < n; ++i) {
    core::BodySpec b = boxBody(i % 3 == 0 ? Vec3(0.3, 0.1, 0.1) : Vec3(0.1, 0.1, 0.1));
    b.name = "box" + std::to_string(i);
    b.collision_group = i % 4 == 1 ? 0 : i % 4 == 2 ? 1 : -1;  // two robots' links among free bodies
    ms.bodies.push_back(b);
  }
  const core::Model model(ms);
  core::State s = core::restState(model);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 6.0), z(0.0, 0.5);
  for (core::BodyState& b : s.bodies) b.p_WB = Vec3(u(rng), u(rng), z(rng));  // crowded: many pairs
  for (int i = 0; i < n; i += 5) s.bodies[i].asleep = true;
  core::Workspace ws;
  core::detail::StepScratch& sc = *ws.scratch;
  sc.margins.assign(n, 0.01);
  for (const int parts : {1, 2, 3}) {
    ws.threads = parts;
    ws.min_parallel_work = 0;
    ASSERT_EQ(core::detail::partsFor(ws, n), parts);
    core::broadPhase(model, s, parts, ws);
    std::vector<std::pair<int, int>> expected;
    for (int a = 0; a < n; ++a) {
      for (int o = 0; o < n; ++o) {
        if (a == o || (s.bodies[a].asleep && s.bodies[o].asleep)) continue;  // two sleepers make no pair
        const int group = model.body(a).collision_group;
        if (group >= 0 && group == model.body(o).collision_group) continue;  // nor one group's bodies
        const double reach = model.body(a).bound_radius + model.body(o).bound_radius + 0.02;
        if (((s.bodies[a].p_WB - s.bodies[o].p_WB).cwiseAbs().array() <= reach).all()) expected.emplace_back(a, o);
      }
    }
    EXPECT_EQ(sc.directions, expected) << parts << " parts";
    EXPECT_GT(expected.size(), 100u);
  }
}

}  // namespace
}  // namespace rigid_body_sim::test
