// The worker pool and the range split (src/core/parallel.cpp): every part
// runs once, whatever the number of threads, and ranges tile the items.
#include "rigid_body_sim/core/step/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace rigid_body_sim::test {
namespace {

TEST(Parallel, RangesTileTheItemsInOrderWithSizesWithinOne) {
  for (const std::size_t n : {0u, 1u, 7u, 100u, 1001u}) {
    for (int parts = 1; parts <= 9; ++parts) {
      std::size_t next = 0, smallest = n, largest = 0;
      for (int k = 0; k < parts; ++k) {
        const core::Range r = core::partRange(n, k, parts);
        EXPECT_EQ(r.begin, next) << n << " " << parts;
        next = r.end;
        smallest = std::min(smallest, r.end - r.begin);
        largest = std::max(largest, r.end - r.begin);
      }
      EXPECT_EQ(next, n);
      EXPECT_LE(largest - smallest, 1u);
    }
  }
}

TEST(Parallel, EveryPartRunsExactlyOnceWithMorePartsThanThreadsOrFewer) {
  core::WorkerPool pool(2);
  for (const int parts : {1, 2, 3, 5, 8}) {
    std::vector<std::atomic<int>> runs(parts);
    core::parallelFor(&pool, parts, [&](int k) { ++runs[k]; });
    for (int k = 0; k < parts; ++k) EXPECT_EQ(runs[k].load(), 1) << "part " << k << " of " << parts;
  }
}

TEST(Parallel, WithoutAPoolThePartsRunInOrderOnTheCaller) {
  std::vector<int> order;
  core::parallelFor(nullptr, 4, [&](int k) { order.push_back(k); });
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3}));
}

TEST(Parallel, ZeroThreadsMeansEveryCoreAndAnyOtherCountIsTaken) {
  EXPECT_EQ(core::threadCount(0), std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
  EXPECT_EQ(core::threadCount(3), 3);
  EXPECT_EQ(core::threadCount(16), 16);
}

}  // namespace
}  // namespace rigid_body_sim::test
