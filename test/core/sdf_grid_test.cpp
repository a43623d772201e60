// A mesh's signed distance sampled on a grid (src/core/sdf_grid.cpp).
#include "rigid_body_sim/core/sdf_grid.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <utility>

#include "../test_util.h"
#include "rigid_body_sim/core/sdf.h"

namespace rigid_body_sim::test {
namespace {

/// A 0.2 m cube centred at the origin as 12 triangles, counter-clockwise seen from outside.
core::TriangleMesh cubeMesh() {
  core::TriangleMesh cube;
  for (int i = 0; i < 8; ++i) cube.vertices.emplace_back(i & 1 ? 0.1 : -0.1, i & 2 ? 0.1 : -0.1, i & 4 ? 0.1 : -0.1);
  cube.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return cube;
}

TEST(SdfGrid, AMeshCubeMatchesTheBoxDistanceWithinTwoCells) {
  const core::TriangleMesh cube = cubeMesh();
  const auto grid = core::SdfGrid::fromMesh(cube, 32);
  const core::Sdf exact = core::Sdf::box(Vec3(0.2, 0.2, 0.2));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (int i = 0; i < 500; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    EXPECT_NEAR(grid->eval(p, nullptr), exact.eval(p), 2 * grid->cell()) << p.transpose();  // trilinear near edges
  }
  EXPECT_LT(grid->eval(Vec3::Zero(), nullptr), -0.09);         // inside is negative
  EXPECT_NEAR(grid->eval(Vec3(1, 0, 0), nullptr), 0.9, 1e-9);  // beyond the grid: plus the distance
}

TEST(SdfGrid, AnyPointIsSafeNaNAndInfinityAreFarAway) {
  // Issue 13: a NaN state made eval cast floor(NaN) to int and read far out of the grid (SIGSEGV).
  const core::TriangleMesh cube = cubeMesh();
  const auto grid = core::SdfGrid::fromMesh(cube, 8);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const Vec3& p : {Vec3(nan, 0, 0), Vec3(0, nan, nan), Vec3(inf, 0, 0), Vec3(-inf, inf, 0)}) {
    Vec3 g;
    EXPECT_EQ(grid->eval(p, &g), inf) << p.transpose();
    EXPECT_EQ(g, Vec3::UnitZ());
  }
  Vec3 g;
  EXPECT_NEAR(grid->eval(Vec3(1e300, 0, 0), &g), 1e300, 1e285);  // huge but finite: the distance
  EXPECT_TRUE(g.allFinite());
  EXPECT_NEAR(g.norm(), 1.0, 1e-12);
}

TEST(SdfGrid, FlippedTrianglesDoNotTurnTheInsideOut) {
  // The sign comes from the winding number, robust to a triangle wound the wrong way.
  core::TriangleMesh cube = cubeMesh();
  std::swap(cube.triangles[0][1], cube.triangles[0][2]);  // the first triangle wound the wrong way
  const auto grid = core::SdfGrid::fromMesh(cube, 16);
  EXPECT_LT(grid->eval(Vec3::Zero(), nullptr), -0.05);
  EXPECT_GT(grid->eval(Vec3(0.15, 0, 0), nullptr), 0.0);
}

}  // namespace
}  // namespace rigid_body_sim::test
