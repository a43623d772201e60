// The surface of a signed distance, for rviz (src/core/sdf_surface.cpp):
// bounds and marching-tetrahedra triangles.
#include "rigid_body_sim/core/bodies/sdf_surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../../test_util.h"

namespace rigid_body_sim::test {
namespace {

TEST(SdfSurface, TrianglesLieOnTheSurfaceOfAComposition) {
  const core::Sdf room =
      core::Sdf::subtract({core::Sdf::box(Vec3(2.2, 2.2, 1.2)).transformed({Quat::Identity(), Vec3(0, 0, 0.5)}),
                           core::Sdf::box(Vec3(2.0, 2.0, 1.5)).transformed({Quat::Identity(), Vec3(0, 0, 0.75)})});
  const auto bounds = core::solidBounds(room);
  ASSERT_TRUE(bounds.has_value());
  EXPECT_LT((bounds->lo - Vec3(-1.1, -1.1, -0.1)).norm(), 1e-12);
  EXPECT_LT((bounds->hi - Vec3(1.1, 1.1, 1.1)).norm(), 1e-12);
  const double cell = 0.05;
  const std::vector<Vec3> tris = core::surfaceTriangles(room, *bounds, cell);
  ASSERT_GT(tris.size(), 300u);
  EXPECT_EQ(tris.size() % 3, 0u);
  for (const Vec3& p : tris) EXPECT_LT(std::abs(room.eval(p)), cell) << p.transpose();
  EXPECT_FALSE(core::solidBounds(core::Sdf::plane(Vec3::UnitZ())).has_value());
  EXPECT_FALSE(core::solidBounds(core::Sdf::unite({core::Sdf::sphere(1), core::Sdf::plane(Vec3::UnitZ())})));
}

TEST(SdfSurface, BoundsOfPrimitivesFollowTheirNamedDimensions) {
  const auto box = core::solidBounds(core::Sdf::box(Vec3(0.4, 0.2, 0.1)));
  ASSERT_TRUE(box.has_value());
  EXPECT_EQ(box->hi, Vec3(0.2, 0.1, 0.05));
  const auto capsule = core::solidBounds(core::Sdf::capsule(0.1, 0.6));  // radius, length without the caps
  ASSERT_TRUE(capsule.has_value());
  EXPECT_EQ(capsule->hi, Vec3(0.1, 0.1, 0.4));
  const auto cylinder = core::solidBounds(core::Sdf::cylinder(0.1, 0.6));
  ASSERT_TRUE(cylinder.has_value());
  EXPECT_EQ(cylinder->lo, Vec3(-0.1, -0.1, -0.3));
}

}  // namespace
}  // namespace rigid_body_sim::test
