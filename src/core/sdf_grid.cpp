#include "rigid_body_sim/core/sdf_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigid_body_sim/core/ranges.h"

namespace rigid_body_sim::core {

double pointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Closest point on a triangle by Voronoi regions (Ericson, Real-Time
  // Collision Detection, 5.1.5).
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

namespace {

/// Solid angle of the triangle seen from the origin (Van Oosterom & Strackee).
double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

}  // namespace

bool SdfGrid::hasArea(const TriangleMesh& mesh) {
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    if ((b - a).cross(c - a).squaredNorm() > 0.0) return true;
  }
  return false;
}

int SdfGrid::resolutionWithin(double triangles, int wanted) {
  const int fits = static_cast<int>(std::cbrt(ranges::kMaxGridWork / std::max(triangles, 1.0)));
  return fits < ranges::kMinGridResolution ? 0 : std::min(wanted, fits);
}

std::shared_ptr<const SdfGrid> SdfGrid::fromMesh(const TriangleMesh& mesh, int resolution) {
  auto grid = std::make_shared<SdfGrid>();
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  constexpr int kSpare = 2;
  grid->cell_ = std::max((hi - lo).maxCoeff(), 1e-6) / resolution;
  grid->lo_ = lo - Vec3::Constant(kSpare * grid->cell_);
  for (int a = 0; a < 3; ++a) {
    grid->n_[a] = static_cast<int>(std::ceil((hi(a) - lo(a)) / grid->cell_)) + 2 * kSpare + 1;
  }
  grid->values_.resize(static_cast<std::size_t>(grid->n_[0]) * grid->n_[1] * grid->n_[2]);
  std::size_t index = 0;
  for (int k = 0; k < grid->n_[2]; ++k) {
    for (int j = 0; j < grid->n_[1]; ++j) {
      for (int i = 0; i < grid->n_[0]; ++i) {
        const Vec3 p = grid->lo_ + grid->cell_ * Vec3(i, j, k);
        double distance = INFINITY, winding = 0.0;
        for (const auto& t : mesh.triangles) {
          const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
          distance = std::min(distance, pointTriangleDistance(p, a, b, c));
          winding += solidAngle(a - p, b - p, c - p);
        }
        const bool inside = std::abs(winding) > 2.0 * M_PI;  // |winding number| > ½
        grid->values_[index++] = inside ? -distance : distance;
      }
    }
  }
  return grid;
}

double SdfGrid::eval(const Vec3& p, Vec3* gradient) const {
  // A point with a NaN or infinite coordinate is infinitely far from the
  // solid: no contact. (A NaN would otherwise reach the sample index: floor
  // of NaN cast to int is undefined, and read far out of the grid.)
  if (!p.allFinite()) {
    if (gradient != nullptr) *gradient = Vec3::UnitZ();
    return std::numeric_limits<double>::infinity();
  }
  const Vec3 top = hi();
  const Vec3 q = p.cwiseMax(lo_).cwiseMin(top);
  double outside = (p - q).norm();
  if (std::isinf(outside)) outside = (p - q).stableNorm();  // far beyond 1e154 m: the squares overflow
  const Vec3 u = (q - lo_) / cell_;
  int i[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    i[a] = std::min(static_cast<int>(std::floor(u(a))), n_[a] - 2);
    f[a] = u(a) - i[a];
  }
  double c[2][2][2];
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) c[dz][dy][dx] = at(i[0] + dx, i[1] + dy, i[2] + dz);
  const auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  const double x00 = lerp(c[0][0][0], c[0][0][1], f[0]), x10 = lerp(c[0][1][0], c[0][1][1], f[0]);
  const double x01 = lerp(c[1][0][0], c[1][0][1], f[0]), x11 = lerp(c[1][1][0], c[1][1][1], f[0]);
  const double y0 = lerp(x00, x10, f[1]), y1 = lerp(x01, x11, f[1]);
  const double value = lerp(y0, y1, f[2]);
  if (gradient != nullptr) {
    if (outside > 0.0) {
      *gradient = (p - q) / outside;
    } else {
      const double gz = (y1 - y0) / cell_;
      const double gy = lerp(x10 - x00, x11 - x01, f[2]) / cell_;
      const double gx = lerp(lerp(c[0][0][1] - c[0][0][0], c[0][1][1] - c[0][1][0], f[1]),
                             lerp(c[1][0][1] - c[1][0][0], c[1][1][1] - c[1][1][0], f[1]), f[2]) /
                        cell_;
      const Vec3 g(gx, gy, gz);
      *gradient = g.norm() > 0.0 ? Vec3(g.normalized()) : Vec3::UnitZ();
    }
  }
  return value + outside;
}

}  // namespace rigid_body_sim::core
