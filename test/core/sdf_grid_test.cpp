// A mesh's signed distance sampled on a grid (src/core/sdf_grid.cpp).
#include "rigid_body_sim/core/sdf_grid.h"

#include <gtest/gtest.h>

#include <random>

#include "../test_util.h"
#include "rigid_body_sim/core/sdf.h"

namespace rigid_body_sim::test {
namespace {

TEST(SdfGrid, AMeshCubeMatchesTheBoxDistanceWithinTwoCells) {
  // A 0.2 m cube as 12 triangles.
  core::TriangleMesh cube;
  for (int i = 0; i < 8; ++i) cube.vertices.emplace_back(i & 1 ? 0.1 : -0.1, i & 2 ? 0.1 : -0.1, i & 4 ? 0.1 : -0.1);
  cube.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
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

TEST(SdfGrid, FlippedTrianglesDoNotTurnTheInsideOut) {
  // The sign comes from the winding number, robust to a triangle wound the wrong way.
  core::TriangleMesh cube;
  for (int i = 0; i < 8; ++i) cube.vertices.emplace_back(i & 1 ? 0.1 : -0.1, i & 2 ? 0.1 : -0.1, i & 4 ? 0.1 : -0.1);
  cube.triangles = {{0, 1, 2}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};  // the first one flipped
  const auto grid = core::SdfGrid::fromMesh(cube, 16);
  EXPECT_LT(grid->eval(Vec3::Zero(), nullptr), -0.05);
  EXPECT_GT(grid->eval(Vec3(0.15, 0, 0), nullptr), 0.0);
}

}  // namespace
}  // namespace rigid_body_sim::test
