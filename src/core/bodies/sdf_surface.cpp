#include "rigid_body_sim/core/bodies/sdf_surface.h"

#include <algorithm>
#include <cmath>

#include "rigid_body_sim/core/bodies/sdf_grid.h"

namespace rigid_body_sim::core {
namespace {

/// The box around `b` after moving it by X.
Bounds transformedBounds(const Bounds& b, const Pose& X) {
  Bounds out{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner((i & 1) ? b.hi.x() : b.lo.x(), (i & 2) ? b.hi.y() : b.lo.y(), (i & 4) ? b.hi.z() : b.lo.z());
    const Vec3 p = X * corner;
    out.lo = out.lo.cwiseMin(p);
    out.hi = out.hi.cwiseMax(p);
  }
  return out;
}

}  // namespace

std::optional<Bounds> solidBounds(const Sdf& sdf) {
  const double r = sdf.radius(), half_length = 0.5 * sdf.length();
  std::optional<Bounds> local;
  switch (sdf.kind()) {
    case Sdf::Kind::kPlane:
      return std::nullopt;
    case Sdf::Kind::kSphere:
      local = Bounds{Vec3::Constant(-r), Vec3::Constant(r)};
      break;
    case Sdf::Kind::kBox:
      local = Bounds{-0.5 * sdf.size(), 0.5 * sdf.size()};
      break;
    case Sdf::Kind::kCapsule:
      local = Bounds{Vec3(-r, -r, -half_length - r), Vec3(r, r, half_length + r)};
      break;
    case Sdf::Kind::kCylinder:
      local = Bounds{Vec3(-r, -r, -half_length), Vec3(r, r, half_length)};
      break;
    case Sdf::Kind::kGrid:
      local = Bounds{sdf.samples()->lo(), sdf.samples()->hi()};
      break;
    case Sdf::Kind::kUnion:
      for (const Sdf& c : sdf.children()) {
        const auto b = solidBounds(c);
        if (!b) return std::nullopt;
        local = local ? Bounds{local->lo.cwiseMin(b->lo), local->hi.cwiseMax(b->hi)} : *b;
      }
      break;
    case Sdf::Kind::kIntersection:
      for (const Sdf& c : sdf.children()) {
        const auto b = solidBounds(c);
        if (!b) continue;
        local = local ? Bounds{local->lo.cwiseMax(b->lo), local->hi.cwiseMin(b->hi)} : *b;
      }
      if (!local) return std::nullopt;
      break;
    case Sdf::Kind::kDifference:
      local = solidBounds(sdf.children().front());
      if (!local) return std::nullopt;
      break;
  }
  return transformedBounds(*local, sdf.pose());
}

std::vector<Vec3> surfaceTriangles(const Sdf& sdf, const Bounds& bounds, double cell) {
  const Vec3 extent = bounds.hi - bounds.lo;
  int n[3];
  for (int a = 0; a < 3; ++a) n[a] = std::max(1, static_cast<int>(std::ceil(extent(a) / cell)));
  const Vec3 step(extent.x() / n[0], extent.y() / n[1], extent.z() / n[2]);
  const auto index = [&](int i, int j, int k) {
    return (static_cast<std::size_t>(k) * (n[1] + 1) + j) * (n[0] + 1) + i;
  };
  const auto point = [&](int i, int j, int k) { return Vec3(bounds.lo + Vec3(i, j, k).cwiseProduct(step)); };
  std::vector<double> phi((n[0] + 1) * static_cast<std::size_t>(n[1] + 1) * (n[2] + 1));
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i) phi[index(i, j, k)] = sdf.eval(point(i, j, k));

  // A cube's corners (x, y, z bits) and its split into six tetrahedra around the diagonal 0–7.
  static const int kTets[6][4] = {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}};
  std::vector<Vec3> triangles;
  Vec3 p[8];
  double v[8];
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        bool any_in = false, any_out = false;
        for (int c = 0; c < 8; ++c) {
          const int ci = i + (c & 1), cj = j + ((c >> 1) & 1), ck = k + ((c >> 2) & 1);
          v[c] = phi[index(ci, cj, ck)];
          p[c] = point(ci, cj, ck);
          (v[c] < 0.0 ? any_in : any_out) = true;
        }
        if (!any_in || !any_out) continue;
        for (const auto& tet : kTets) {
          int in[4], out[4], n_in = 0, n_out = 0;
          for (int t = 0; t < 4; ++t) (v[tet[t]] < 0.0 ? in[n_in++] : out[n_out++]) = tet[t];
          const auto cross = [&](int a, int b) { return Vec3(p[a] + (v[a] / (v[a] - v[b])) * (p[b] - p[a])); };
          if (n_in == 1 || n_in == 3) {
            const int lone = n_in == 1 ? in[0] : out[0];
            const int* others = n_in == 1 ? out : in;
            triangles.push_back(cross(lone, others[0]));
            triangles.push_back(cross(lone, others[1]));
            triangles.push_back(cross(lone, others[2]));
          } else if (n_in == 2) {
            const Vec3 a = cross(in[0], out[0]), b = cross(in[0], out[1]), c = cross(in[1], out[1]),
                       d = cross(in[1], out[0]);
            triangles.insert(triangles.end(), {a, b, c, a, c, d});
          }
        }
      }
    }
  }
  return triangles;
}

}  // namespace rigid_body_sim::core
