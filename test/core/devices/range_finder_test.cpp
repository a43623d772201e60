// A range finder's reading from a scan's rays (core/devices/range_finder.h):
// the nearest met range, REP 117's ±inf kept, noise seeded and held within
// the ranges.
#include "rigid_body_sim/core/devices/range_finder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace rigid_body_sim::core {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(RangeFinder, ReadsTheNearestMetRayAndKeepsRep117sInfinities) {
  RangeFinder exact(RangeFinderSettings{});
  EXPECT_EQ(exact.reading({kInf, 1.25, 0.75, kInf, 0.9}, 0.02, 2.0), 0.75);
  EXPECT_EQ(exact.reading({kInf, kInf}, 0.02, 2.0), kInf);         // nothing within max_range
  EXPECT_EQ(exact.reading({1.0, -kInf, kInf}, 0.02, 2.0), -kInf);  // something nearer than min_range
  EXPECT_EQ(exact.reading({}, 0.02, 2.0), kInf);
}

TEST(RangeFinder, ItsNoiseIsSeededGaussianAndHeldWithinItsRanges) {
  RangeFinder a(RangeFinderSettings{0.01, 7}), b(RangeFinderSettings{0.01, 7});
  double sum = 0.0, squares = 0.0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const double x = a.reading({1.0, 1.5}, 0.02, 2.0);
    EXPECT_EQ(x, b.reading({1.0, 1.5}, 0.02, 2.0));  // the same seed, the same readings
    sum += x;
    squares += (x - 1.0) * (x - 1.0);
  }
  EXPECT_NEAR(sum / n, 1.0, 4.0 * 0.01 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(squares / n), 0.01, 0.0003);
  // Near an end, the noisy reading stays a valid one.
  RangeFinder wide(RangeFinderSettings{1.0, 3});
  for (int k = 0; k < 1000; ++k) {
    const double x = wide.reading({1.9}, 0.02, 2.0);
    EXPECT_GE(x, 0.02);
    EXPECT_LE(x, 2.0);
  }
  a.restart();
  RangeFinder fresh(RangeFinderSettings{0.01, 7});
  EXPECT_EQ(a.reading({1.0}, 0.02, 2.0), fresh.reading({1.0}, 0.02, 2.0));
  // A reading due but not taken (nobody listened) leaves the next one as it would have been.
  RangeFinder every(RangeFinderSettings{0.01, 9}), late(RangeFinderSettings{0.01, 9});
  const double first = every.reading({1.0}, 0.02, 2.0), second = every.reading({1.0}, 0.02, 2.0);
  late.pass();
  EXPECT_EQ(late.reading({1.0}, 0.02, 2.0), second);
  EXPECT_NE(first, second);
  EXPECT_THROW(RangeFinder(RangeFinderSettings{-1.0, 0}), std::invalid_argument);
  EXPECT_THROW(RangeFinder(RangeFinderSettings{std::nan(""), 0}), std::invalid_argument);
}

}  // namespace
}  // namespace rigid_body_sim::core
