// Collision shapes sampled into contact points (src/core/collision.cpp).
#include "rigid_body_sim/core/bodies/collision.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../../test_util.h"
#include "rigid_body_sim/core/bodies/sdf.h"

namespace rigid_body_sim::test {
namespace {

core::CollisionShape box(const Vec3& size) {
  core::CollisionShape s;
  s.kind = core::CollisionShape::Kind::kBox;
  s.size = size;
  return s;
}

TEST(Collision, ABoxIsItsEightCornersPlusSamplesAllOnItsSurface) {
  const core::CollisionShape shape = box(Vec3(0.4, 0.2, 0.1));
  const auto points = core::sampleShape(shape, core::Pose{}, 0.05, false).points;
  const core::Sdf solid = core::Sdf::box(shape.size);
  int extreme = 0;
  for (const core::ContactPoint& p : points) {
    EXPECT_NEAR(solid.eval(p.r_B), 0.0, 1e-15) << p.r_B.transpose();
    EXPECT_EQ(p.radius, 0.0);
    if (p.extreme) {
      ++extreme;
      EXPECT_EQ(p.r_B.cwiseAbs(), Vec3(0.2, 0.1, 0.05));  // only the corners can be deepest against a plane
    }
  }
  EXPECT_EQ(extreme, 8);
  EXPECT_GT(points.size(), 8u);  // edges and faces sampled at the spacing
}

TEST(Collision, ASphereIsItsCentreWithItsRadiusUnlessShapeMatchingNeedsVertices) {
  core::CollisionShape shape;
  shape.kind = core::CollisionShape::Kind::kSphere;
  shape.radius = 0.3;
  const auto exact = core::sampleShape(shape, core::Pose{}, 0.05, false).points;
  ASSERT_EQ(exact.size(), 1u);
  EXPECT_EQ(exact[0].r_B, Vec3::Zero());
  EXPECT_EQ(exact[0].radius, 0.3);
  const auto sampled = core::sampleShape(shape, core::Pose{}, 0.05, true).points;
  ASSERT_GT(sampled.size(), 100u);  // 4π r² / spacing²
  for (const core::ContactPoint& p : sampled) EXPECT_NEAR(p.r_B.norm(), 0.3, 1e-12);
}

TEST(Collision, ACylinderIsTwoExactRimsAndItsSideUnlessShapeMatchingNeedsVertices) {
  core::CollisionShape shape;
  shape.kind = core::CollisionShape::Kind::kCylinder;
  shape.radius = 0.1;
  shape.length = 0.4;
  const core::Pose X_BL{Quat(Eigen::AngleAxisd(0.3, Vec3::UnitX())), Vec3(0, 0, 1)};
  const core::Sdf solid = core::Sdf::cylinder(0.1, 0.4).transformed(X_BL);
  const core::ShapeSamples exact = core::sampleShape(shape, X_BL, 0.02, false);
  ASSERT_EQ(exact.round.size(), 3u);  // two rims and the side, in B
  for (int end = 0; end < 2; ++end) {
    const core::RoundFeature& rim = exact.round[end];
    EXPECT_EQ(rim.kind, core::RoundFeature::Kind::kRim);
    EXPECT_LT((rim.centre_B - X_BL * Vec3(0, 0, end == 0 ? -0.2 : 0.2)).norm(), 1e-15);
    EXPECT_LT((rim.axis_B - X_BL.rotation * Vec3::UnitZ()).norm(), 1e-15);
    EXPECT_EQ(rim.rho, 0.1);
  }
  EXPECT_EQ(exact.round[2].kind, core::RoundFeature::Kind::kSide);
  EXPECT_EQ(exact.round[2].half_length, 0.2);
  int rim_points = 0, side_points = 0;
  for (const core::ContactPoint& p : exact.points) {
    EXPECT_FALSE(p.extreme);  // the plane tests the rims in closed form
    if (p.round < 0) {
      EXPECT_NEAR(solid.eval(p.r_B), 0.0, 1e-12);  // cap samples
    } else {
      (p.round < 2 ? rim_points : side_points) += 1;
    }
  }
  EXPECT_EQ(rim_points, 6);
  EXPECT_EQ(side_points, 2);
  const core::ShapeSamples sampled = core::sampleShape(shape, X_BL, 0.02, true);
  EXPECT_TRUE(sampled.round.empty());
  for (const core::ContactPoint& p : sampled.points) EXPECT_NEAR(solid.eval(p.r_B), 0.0, 1e-12);
}

TEST(Collision, ACapsuleIsItsEndCentresWithItsRadiusAndItsSegment) {
  core::CollisionShape shape;
  shape.kind = core::CollisionShape::Kind::kCapsule;
  shape.radius = 0.1;
  shape.length = 0.4;
  const core::ShapeSamples exact = core::sampleShape(shape, core::Pose{}, 0.02, false);
  ASSERT_EQ(exact.points.size(), 4u);
  EXPECT_EQ(exact.points[0].r_B, Vec3(0, 0, -0.2));
  EXPECT_EQ(exact.points[1].r_B, Vec3(0, 0, 0.2));
  for (const core::ContactPoint& p : exact.points) EXPECT_EQ(p.radius, 0.1);
  ASSERT_EQ(exact.round.size(), 1u);
  EXPECT_EQ(exact.round[0].kind, core::RoundFeature::Kind::kSegment);
  EXPECT_EQ(exact.round[0].half_length, 0.2);
  EXPECT_EQ(exact.points[2].round, 0);
  EXPECT_EQ(exact.points[3].round, 0);
  EXPECT_EQ(exact.points[3].phase, 1);
  const core::Sdf solid = core::Sdf::capsule(0.1, 0.4);
  const core::ShapeSamples sampled = core::sampleShape(shape, core::Pose{}, 0.02, true);
  ASSERT_GT(sampled.points.size(), 100u);
  for (const core::ContactPoint& p : sampled.points) EXPECT_NEAR(solid.eval(p.r_B), 0.0, 1e-12);
}

TEST(Collision, PointsAreExpressedInTheBodyFrameThroughTheShapeAndLinkPoses) {
  core::CollisionShape shape = box(Vec3(0.2, 0.2, 0.2));
  shape.X_LS = {Quat::Identity(), Vec3(1, 0, 0)};                                          // the shape 1 m along L's x
  const core::Pose X_BL{Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())), Vec3(0, 0, 2)};  // L turned in B, 2 m up
  Vec3 mean = Vec3::Zero();
  const auto points = core::sampleShape(shape, X_BL, 1.0, false).points;
  for (const core::ContactPoint& p : points) mean += p.r_B;
  mean /= static_cast<double>(points.size());
  EXPECT_LT((mean - Vec3(0, 1, 2)).norm(), 1e-12);  // the shape's centre, X_BL X_LS applied
}

}  // namespace
}  // namespace rigid_body_sim::test
