// Signed distances: values and gradients against closed forms; compositions.
#include "rigid_body_sim/core/bodies/sdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../../test_util.h"

namespace rigid_body_sim::test {
namespace {

using core::Sdf;

void expectSdf(const Sdf& sdf, const Vec3& p, double phi, const Vec3& grad) {
  Vec3 g;
  EXPECT_NEAR(sdf.eval(p, &g), phi, 1e-14) << p.transpose();
  EXPECT_LT((g - grad).norm(), 1e-14) << "at " << p.transpose() << ": " << g.transpose();
}

TEST(Sdf, Plane) {
  const Vec3 n = Vec3(1, 0, 1).normalized();
  const Sdf plane = Sdf::plane(Vec3(1, 0, 1), Vec3(0, 0, 2));
  expectSdf(plane, Vec3(0, 5, 2), 0.0, n);
  expectSdf(plane, Vec3(1, 0, 3), std::sqrt(2.0), n);
  expectSdf(plane, Vec3(0, 0, 0), -std::sqrt(2.0), n);
}

TEST(Sdf, Sphere) {
  const Sdf ball = Sdf::sphere(0.5).transformed({Quat::Identity(), Vec3(1, 2, 3)});
  expectSdf(ball, Vec3(1, 2, 5), 1.5, Vec3::UnitZ());
  expectSdf(ball, Vec3(1.3, 2.4, 3), -0.0, Vec3(0.6, 0.8, 0));
  expectSdf(ball, Vec3(1, 2, 3.1), -0.4, Vec3::UnitZ());
}

TEST(Sdf, BoxFacesEdgesCornersAndInside) {
  const Sdf box = Sdf::box(Vec3(2, 4, 6));                                     // half extents 1, 2, 3
  expectSdf(box, Vec3(1.5, 0.3, -1), 0.5, Vec3::UnitX());                      // face region
  expectSdf(box, Vec3(-5, -5, 0), 5.0, Vec3(-0.8, -0.6, 0));                   // edge region: (4, 3) away
  expectSdf(box, Vec3(3, 4, 5), std::sqrt(12.0), Vec3(1, 1, 1).normalized());  // corner region
  expectSdf(box, Vec3(0.2, 1.5, 0), -0.5, Vec3::UnitY());                      // inside: nearest face
  expectSdf(box, Vec3(0, 0, -2.9), -0.1, -Vec3::UnitZ());
}

TEST(Sdf, Capsule) {
  const Sdf capsule = Sdf::capsule(0.5, 2.0);  // segment z ∈ [−1, 1]
  expectSdf(capsule, Vec3(2, 0, 0.3), 1.5, Vec3::UnitX());
  expectSdf(capsule, Vec3(0, 0, 3), 1.5, Vec3::UnitZ());
  expectSdf(capsule, Vec3(0, 3, -4), std::sqrt(9.0 + 9.0) - 0.5, Vec3(0, 1, -1).normalized());
  expectSdf(capsule, Vec3(0.2, 0, 0), -0.3, Vec3::UnitX());
}

TEST(Sdf, Cylinder) {
  const Sdf cyl = Sdf::cylinder(1.0, 2.0);                     // radius 1, z ∈ [−1, 1]
  expectSdf(cyl, Vec3(0, 3, 0.5), 2.0, Vec3::UnitY());         // side
  expectSdf(cyl, Vec3(0.5, 0, 1.5), 0.5, Vec3::UnitZ());       // cap
  expectSdf(cyl, Vec3(4, 0, -5), 5.0, Vec3(0.6, 0, -0.8));     // beyond the rim: (3, 4)
  expectSdf(cyl, Vec3(0.8, 0, 0), -0.2, Vec3::UnitX());        // inside, nearer the side
  expectSdf(cyl, Vec3(0, 0.1, -0.95), -0.05, -Vec3::UnitZ());  // inside, nearer a cap
}

TEST(Sdf, TransformMovesTheShape) {
  const Quat q(Eigen::AngleAxisd(0.7, Vec3(1, 1, 0).normalized()));
  const Vec3 t(0.5, -1, 2);
  const Sdf moved = Sdf::box(Vec3(1, 2, 3)).transformed({q, t});
  const Sdf at_origin = Sdf::box(Vec3(1, 2, 3));
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int i = 0; i < 100; ++i) {
    const Vec3 local(u(rng), u(rng), u(rng));
    Vec3 g_moved, g_local;
    EXPECT_NEAR(moved.eval(q * local + t, &g_moved), at_origin.eval(local, &g_local), 1e-13);
    EXPECT_LT((g_moved - q * g_local).norm(), 1e-13);
  }
}

/// The gradient is the unit direction of steepest increase, and φ is
/// 1-Lipschitz, for every primitive and composition.
TEST(Sdf, GradientsAreUnitAndMatchFiniteDifferences) {
  const std::vector<Sdf> shapes = {
      Sdf::plane(Vec3(0.3, -1, 2)),
      Sdf::sphere(0.7),
      Sdf::box(Vec3(1, 0.5, 2)).transformed({Quat(Eigen::AngleAxisd(0.4, Vec3::UnitZ())), Vec3(0.1, 0, 0)}),
      Sdf::capsule(0.3, 1.0),
      Sdf::cylinder(0.6, 1.2),
      Sdf::unite({Sdf::sphere(0.5), Sdf::box(Vec3(1, 1, 1)).transformed({Quat::Identity(), Vec3(1.5, 0, 0)})}),
      Sdf::intersect({Sdf::sphere(1.0), Sdf::plane(Vec3::UnitZ(), Vec3(0, 0, 0.3))}),
      Sdf::subtract({Sdf::box(Vec3(3, 3, 3)), Sdf::sphere(1.0).transformed({Quat::Identity(), Vec3(0, 0, 1.5)})}),
  };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  const double h = 1e-7;
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    for (int i = 0; i < 300; ++i) {
      const Vec3 p(u(rng), u(rng), u(rng)), q(u(rng), u(rng), u(rng));
      Vec3 g;
      const double phi = shapes[k].eval(p, &g);
      EXPECT_NEAR(g.norm(), 1.0, 1e-12) << "shape " << k;
      // Along the gradient φ grows at rate 1 (away from the non-smooth sets).
      EXPECT_NEAR((shapes[k].eval(p + h * g) - phi) / h, 1.0, 1e-5) << "shape " << k << " at " << p.transpose();
      EXPECT_LE(std::abs(shapes[k].eval(q) - phi), (q - p).norm() + 1e-12) << "shape " << k;
    }
  }
}

TEST(Sdf, UnionIsExactOutside) {
  // Two balls: outside both, φ is the distance to the nearer one.
  const Sdf two = Sdf::unite({Sdf::sphere(1.0), Sdf::sphere(1.0).transformed({Quat::Identity(), Vec3(5, 0, 0)})});
  expectSdf(two, Vec3(2.5, 0, 0), 1.5, Vec3::UnitX());
  expectSdf(two, Vec3(7, 0, 0), 1.0, Vec3::UnitX());
  expectSdf(two, Vec3(0, 0.5, 0), -0.5, Vec3::UnitY());
}

TEST(Sdf, IntersectionIsExactInside) {
  // A ball cut by the plane z = 0.5, keeping the part below: inside, φ is
  // minus the distance to the nearer of the two surfaces.
  const Sdf cut = Sdf::intersect({Sdf::sphere(2.0), Sdf::plane(Vec3::UnitZ(), Vec3(0, 0, 0.5))});
  expectSdf(cut, Vec3(0, 0, 0.2), -0.3, Vec3::UnitZ());
  expectSdf(cut, Vec3(0, 0, -1.5), -0.5, -Vec3::UnitZ());
}

TEST(Sdf, DifferenceMakesARoom) {
  // An outer box minus an inner box taller than it: a floor and four walls, open on top.
  const Sdf room = Sdf::subtract({Sdf::box(Vec3(2.2, 2.2, 1.2)).transformed({Quat::Identity(), Vec3(0, 0, 0.5)}),
                                  Sdf::box(Vec3(2.0, 2.0, 1.5)).transformed({Quat::Identity(), Vec3(0, 0, 0.75)})});
  expectSdf(room, Vec3(0, 0, 0.3), 0.3, Vec3::UnitZ());     // above the floor
  expectSdf(room, Vec3(0.9, 0, 0.5), 0.1, -Vec3::UnitX());  // near the +x wall, inside the room
  expectSdf(room, Vec3(0, -0.8, 0.5), 0.2, Vec3::UnitY());
  EXPECT_LT(room.eval(Vec3(1.05, 0, 0.5)), 0.0);  // inside the wall
  EXPECT_GT(room.eval(Vec3(0, 0, 5)), 0.0);       // open top
}

}  // namespace
}  // namespace rigid_body_sim::test
