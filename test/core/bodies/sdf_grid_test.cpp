// A mesh's signed distance sampled on a grid (src/core/sdf_grid.cpp).
#include "rigid_body_sim/core/bodies/sdf_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <tuple>
#include <utility>

#include "../../test_util.h"
#include "rigid_body_sim/core/bodies/sdf.h"

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

/// A torus about z (radii R, r), n × m quads as triangles, wound outward:
/// not convex, with a hole through it.
core::TriangleMesh torusMesh(double R, double r, int n, int m) {
  core::TriangleMesh torus;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double u = 2.0 * M_PI * i / n, v = 2.0 * M_PI * j / m;
      torus.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                                  r * std::sin(v));
    }
  }
  const auto at = [n, m](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      torus.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      torus.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return torus;
}

/// How many samples of `grid` differ from the long way (meshSignedDistance):
/// in distance (which must be the same number), and in sign (where the
/// sample is off the surface by more than rounding: on it, ±0 are alike).
std::pair<int, int> differences(const core::SdfGrid& grid, const core::TriangleMesh& mesh) {
  int distance = 0, sign = 0;
  for (int k = 0; k < grid.samples(2); ++k) {
    for (int j = 0; j < grid.samples(1); ++j) {
      for (int i = 0; i < grid.samples(0); ++i) {
        const double fast = grid.sample(i, j, k);
        const double slow = core::meshSignedDistance(mesh, grid.lo() + grid.cell() * Vec3(i, j, k));
        distance += std::abs(fast) == std::abs(slow) ? 0 : 1;
        sign += (fast < 0.0) == (slow < 0.0) || std::abs(slow) < 1e-12 * grid.cell() ? 0 : 1;
      }
    }
  }
  return {distance, sign};
}

TEST(SdfGrid, EverySampleIsTheLongWaysSignedDistance) {
  // The nearest triangle through the tree is the same number as the least
  // of all; inside by the axes' parity is inside by the winding number.
  for (const auto& [name, mesh, resolution] : {std::tuple<const char*, core::TriangleMesh, int>{"cube", cubeMesh(), 20},
                                               {"torus", torusMesh(0.3, 0.1, 48, 24), 32},
                                               {"thin torus", torusMesh(0.5, 0.02, 96, 12), 40}}) {
    const auto grid = core::SdfGrid::fromMesh(mesh, resolution);
    const auto [distance, sign] = differences(*grid, mesh);
    EXPECT_EQ(distance, 0) << name;
    EXPECT_EQ(sign, 0) << name;
  }
}

TEST(SdfGrid, ASmallHoleIsOutvoted) {
  // Half the bottom face gone: the z rays through the hole miss a crossing,
  // and the x and y rays outvote them. Off the hole's own plane every sample
  // is the winding number's answer; in it (where the winding number is
  // about ½ and inside and outside are a matter of taste) it is inside.
  core::TriangleMesh cube = cubeMesh();
  cube.triangles.erase(cube.triangles.begin());
  const auto grid = core::SdfGrid::fromMesh(cube, 16);
  int in_plane = 0;
  for (int k = 0; k < grid->samples(2); ++k) {
    for (int j = 0; j < grid->samples(1); ++j) {
      for (int i = 0; i < grid->samples(0); ++i) {
        const Vec3 p = grid->lo() + grid->cell() * Vec3(i, j, k);
        const double fast = grid->sample(i, j, k), slow = core::meshSignedDistance(cube, p);
        ASSERT_EQ(std::abs(fast), std::abs(slow)) << p.transpose();
        if ((fast < 0.0) == (slow < 0.0) || std::abs(slow) < 1e-12 * grid->cell()) continue;
        ASSERT_NEAR(p.z(), -0.1, 1e-12) << "a sign off the hole's plane at " << p.transpose();
        ++in_plane;
      }
    }
  }
  EXPECT_GT(in_plane, 0);  // the hole's plane is sampled: the case is met
  EXPECT_LT(grid->eval(Vec3::Zero(), nullptr), -0.05);
  EXPECT_LT(grid->eval(Vec3(0.05, -0.05, -0.09), nullptr), 0.0);   // just inside, above the hole
  EXPECT_GT(grid->eval(Vec3(-0.05, -0.05, -0.15), nullptr), 0.0);  // below the hole, outside
}

}  // namespace
}  // namespace rigid_body_sim::test
