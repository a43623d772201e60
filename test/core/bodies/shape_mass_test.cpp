// The mass of collision shapes filled with a density (src/core/shape_mass.cpp):
// the closed forms of the primitives against a tessellation or a fine
// voxel sum, and a mesh's divergence-theorem sums against a box's closed form.
#include "rigid_body_sim/core/bodies/shape_mass.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../../test_util.h"

namespace rigid_body_sim::test {
namespace {

using core::CollisionShape;
using core::MassProperties;

/// A 0.2 × 0.3 × 0.4 m box as 12 triangles, counter-clockwise from outside.
core::TriangleMesh boxMesh(const Vec3& size) {
  core::TriangleMesh m;
  for (int i = 0; i < 8; ++i) {
    m.vertices.emplace_back((i & 1 ? 0.5 : -0.5) * size.x(), (i & 2 ? 0.5 : -0.5) * size.y(),
                            (i & 4 ? 0.5 : -0.5) * size.z());
  }
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

/// A solid's mass properties by summing voxels of side h inside it.
MassProperties voxels(const std::function<bool(const Vec3&)>& inside, double reach, double h, double density) {
  std::vector<double> masses;
  std::vector<Vec3> points;
  for (double x = -reach + h / 2; x < reach; x += h) {
    for (double y = -reach + h / 2; y < reach; y += h) {
      for (double z = -reach + h / 2; z < reach; z += h) {
        if (!inside(Vec3(x, y, z))) continue;
        masses.push_back(density * h * h * h);
        points.emplace_back(x, y, z);
      }
    }
  }
  MassProperties mp = core::pointMassProperties(masses, points);
  // Each voxel's own inertia, m h²/6 about each axis, on top of the points'.
  mp.I_C_F += (mp.mass * h * h / 6.0) * Mat3::Identity();
  return mp;
}

void expectClose(const MassProperties& a, const MassProperties& b, double relative) {
  EXPECT_NEAR(a.mass, b.mass, relative * b.mass);
  EXPECT_LT((a.p_FC - b.p_FC).norm(), relative);
  EXPECT_LT((a.I_C_F - b.I_C_F).norm(), relative * b.I_C_F.norm()) << a.I_C_F << "\nagainst\n" << b.I_C_F;
}

TEST(ShapeMass, AMeshBoxIsTheBoxsClosedFormWhereverItIsPosed) {
  CollisionShape box;
  box.kind = CollisionShape::Kind::kBox;
  box.size = Vec3(0.2, 0.3, 0.4);
  CollisionShape mesh;
  mesh.kind = CollisionShape::Kind::kPoints;
  mesh.mesh = boxMesh(box.size);
  for (CollisionShape* s : {&box, &mesh}) {
    s->X_LS.translation = Vec3(0.1, -0.2, 0.3);
    s->X_LS.rotation = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, -1).normalized()));
  }
  const MassProperties a = core::shapeMassProperties(box, core::kWaterDensity);
  const MassProperties b = core::shapeMassProperties(mesh, core::kWaterDensity);
  EXPECT_NEAR(a.mass, 24.0, 1e-12);  // 0.024 m³ of water
  EXPECT_LT((a.p_FC - Vec3(0.1, -0.2, 0.3)).norm(), 1e-15);
  const Mat3 R = box.X_LS.rotation.toRotationMatrix();
  EXPECT_LT((a.I_C_F - R * boxInertia(24.0, 0.5 * box.size) * R.transpose()).norm(), 1e-14);
  expectClose(b, a, 1e-12);
  // Wound inside out, the same solid.
  for (auto& t : mesh.mesh.triangles) std::swap(t[1], t[2]);
  expectClose(core::shapeMassProperties(mesh, core::kWaterDensity), a, 1e-12);
}

TEST(ShapeMass, SphereCylinderAndCapsuleMatchAVoxelSum) {
  CollisionShape sphere, cylinder, capsule;
  sphere.kind = CollisionShape::Kind::kSphere;
  sphere.radius = 0.1;
  cylinder.kind = CollisionShape::Kind::kCylinder;
  cylinder.radius = 0.05;
  cylinder.length = 0.3;
  capsule.kind = CollisionShape::Kind::kCapsule;
  capsule.radius = 0.05;
  capsule.length = 0.2;
  const double h = 0.002;
  expectClose(core::shapeMassProperties(sphere, 1000.0),
              voxels([](const Vec3& p) { return p.norm() < 0.1; }, 0.11, h, 1000.0), 0.01);
  expectClose(
      core::shapeMassProperties(cylinder, 1000.0),
      voxels([](const Vec3& p) { return p.head<2>().norm() < 0.05 && std::abs(p.z()) < 0.15; }, 0.16, h, 1000.0), 0.01);
  expectClose(core::shapeMassProperties(capsule, 1000.0),
              voxels(
                  [](const Vec3& p) {
                    const double z = std::clamp(p.z(), -0.1, 0.1);  // the nearest point of the core segment
                    return (p - Vec3(0, 0, z)).norm() < 0.05;
                  },
                  0.16, h, 1000.0),
              0.01);
}

TEST(ShapeMass, AMeshEnclosingNoVolumeIsItsBoundingBox) {
  CollisionShape flat;
  flat.kind = CollisionShape::Kind::kPoints;
  flat.mesh.vertices = {Vec3(0, 0, 0), Vec3(0.2, 0, 0), Vec3(0, 0.1, 0.05)};
  flat.mesh.triangles = {{0, 1, 2}};
  const MassProperties m = core::shapeMassProperties(flat, 1000.0);
  EXPECT_NEAR(m.mass, 1000.0 * 0.2 * 0.1 * 0.05, 1e-12);
  EXPECT_LT((m.p_FC - Vec3(0.1, 0.05, 0.025)).norm(), 1e-15);
}

}  // namespace
}  // namespace rigid_body_sim::test
