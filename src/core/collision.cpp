#include "rigid_body_sim/core/collision.h"

#include <algorithm>
#include <cmath>

namespace rigid_body_sim::core {
namespace {

/// Number of intervals so that none is longer than `spacing`.
int intervals(double length, double spacing) {
  return std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
}

void sampleBox(const Vec3& size, double spacing, std::vector<Vec3>& out, std::vector<bool>& extreme) {
  const Vec3 h = 0.5 * size;
  const int n[3] = {intervals(size.x(), spacing), intervals(size.y(), spacing), intervals(size.z(), spacing)};
  // A lattice point (i, j, k) lies on the surface when one index is at an end;
  // corners have three end indices, edges two, faces one.
  for (int i = 0; i <= n[0]; ++i) {
    for (int j = 0; j <= n[1]; ++j) {
      for (int k = 0; k <= n[2]; ++k) {
        const int ends = (i == 0 || i == n[0]) + (j == 0 || j == n[1]) + (k == 0 || k == n[2]);
        if (ends == 0) continue;  // inside the box
        out.emplace_back(-h.x() + size.x() * i / n[0], -h.y() + size.y() * j / n[1], -h.z() + size.z() * k / n[2]);
        extreme.push_back(ends == 3);  // a corner
      }
    }
  }
}

void sampleCylinder(double radius, double length, double spacing, std::vector<Vec3>& out, std::vector<bool>& extreme) {
  const int around = std::max(8, intervals(2.0 * M_PI * radius, spacing));
  const int along = intervals(length, spacing);
  const int rings = intervals(radius, spacing);
  for (int k = 0; k <= along; ++k) {  // rims and the side, ring by ring
    const double z = -0.5 * length + length * k / along;
    for (int a = 0; a < around; ++a) {
      const double t = 2.0 * M_PI * a / around;
      out.emplace_back(radius * std::cos(t), radius * std::sin(t), z);
      extreme.push_back(k == 0 || k == along);  // the rims
    }
  }
  for (double z : {-0.5 * length, 0.5 * length}) {  // caps: centre and inner rings
    out.emplace_back(0.0, 0.0, z);
    extreme.push_back(false);
    for (int r = 1; r < rings; ++r) {
      const double rr = radius * r / rings;
      const int m = std::max(6, intervals(2.0 * M_PI * rr, spacing));
      for (int a = 0; a < m; ++a) {
        const double t = 2.0 * M_PI * a / m;
        out.emplace_back(rr * std::cos(t), rr * std::sin(t), z);
        extreme.push_back(false);
      }
    }
  }
}

/// Evenly spread points on a sphere (a Fibonacci lattice).
void sampleSphereSurface(double radius, double spacing, std::vector<Vec3>& out) {
  const int n = std::max(12, static_cast<int>(std::ceil(4.0 * M_PI * radius * radius / (spacing * spacing))));
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt(1.0 - z * z);
    out.emplace_back(radius * r * std::cos(golden * i), radius * r * std::sin(golden * i), radius * z);
  }
}

/// Intervals of `spacing` along `length`, in floating point (no int to overflow).
double intervalCount(double length, double spacing) { return std::max(1.0, std::ceil(length / spacing - 1e-9)); }

}  // namespace

double sampleCount(const CollisionShape& shape, double spacing, bool sample_spheres) {
  switch (shape.kind) {
    case CollisionShape::Kind::kBox: {
      const double n = intervalCount(shape.size.x(), spacing) + 1.0;
      const double m = intervalCount(shape.size.y(), spacing) + 1.0;
      const double k = intervalCount(shape.size.z(), spacing) + 1.0;
      return n * m * k;  // the whole lattice: more than its surface
    }
    case CollisionShape::Kind::kCylinder: {
      const double around = std::max(8.0, intervalCount(2.0 * M_PI * shape.radius, spacing));
      const double along = intervalCount(shape.length, spacing);
      const double rings = intervalCount(shape.radius, spacing);
      return around * (along + 1.0 + 2.0 * rings) + 2.0;
    }
    case CollisionShape::Kind::kSphere:
      return sample_spheres ? std::max(12.0, std::ceil(4.0 * M_PI * shape.radius * shape.radius / (spacing * spacing)))
                            : 1.0;
    case CollisionShape::Kind::kPoints:
      return static_cast<double>(shape.mesh.vertices.size());
  }
  return 0.0;
}

std::vector<ContactPoint> sampleShape(const CollisionShape& shape, const Pose& X_BL, double spacing,
                                      bool sample_spheres) {
  std::vector<Vec3> local;
  std::vector<bool> extreme;
  double radius = 0.0;
  switch (shape.kind) {
    case CollisionShape::Kind::kBox:
      sampleBox(shape.size, spacing, local, extreme);
      break;
    case CollisionShape::Kind::kCylinder:
      sampleCylinder(shape.radius, shape.length, spacing, local, extreme);
      break;
    case CollisionShape::Kind::kSphere:
      if (sample_spheres) {
        sampleSphereSurface(shape.radius, spacing, local);
      } else {
        local.emplace_back(Vec3::Zero());
        radius = shape.radius;
      }
      break;
    case CollisionShape::Kind::kPoints:
      local = shape.mesh.vertices;
      break;
  }
  std::vector<ContactPoint> points;
  points.reserve(local.size());
  const Pose X_BS = X_BL * shape.X_LS;
  extreme.resize(local.size(), true);  // sphere centres and samples, mesh vertices
  for (std::size_t i = 0; i < local.size(); ++i) points.push_back({X_BS * local[i], radius, extreme[i]});
  return points;
}

}  // namespace rigid_body_sim::core
