#include "rigid_body_sim/core/bodies/sdf_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigid_body_sim/core/bodies/ranges.h"

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

namespace {

/// Triangles in a bounding-volume hierarchy, for the nearest one to a point:
/// boxes around halves of the triangles (split at the median centroid along
/// the longest side), down to leaves of a few.
class TriangleTree {
 public:
  explicit TriangleTree(const TriangleMesh& mesh) : mesh_(mesh) {
    order_.resize(mesh.triangles.size());
    for (std::size_t t = 0; t < order_.size(); ++t) order_[t] = static_cast<int>(t);
    if (!order_.empty()) build(0, static_cast<int>(order_.size()));
  }

  /// The distance from p to the nearest triangle: the same number as the
  /// least pointTriangleDistance over all of them (a box is skipped only
  /// when it is no nearer than the best triangle found).
  double distance(const Vec3& p) const {
    double best = std::numeric_limits<double>::infinity();
    if (nodes_.empty()) return best;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      // Only a box farther than the best by more than rounding is passed
      // over: the two distances are computed differently, and a triangle on
      // a box's face must still be able to win by its last bit.
      if (boxDistance(node, p) > best * (1.0 + 1e-12)) continue;
      if (node.left < 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          const auto& t = mesh_.triangles[order_[k]];
          best = std::min(best,
                          pointTriangleDistance(p, mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]));
        }
        continue;
      }
      // The nearer child last, so that it is searched first.
      const double l = boxDistance(nodes_[node.left], p), r = boxDistance(nodes_[node.right], p);
      stack[top++] = l < r ? node.right : node.left;
      stack[top++] = l < r ? node.left : node.right;
    }
    return best;
  }

 private:
  struct Node {
    Vec3 lo, hi;
    int left = -1, right = -1;  ///< children, or −1 for a leaf
    int first = 0, count = 0;   ///< a leaf's triangles in order_
  };
  static constexpr int kLeaf = 4;

  static double boxDistance(const Node& n, const Vec3& p) { return (p - p.cwiseMax(n.lo).cwiseMin(n.hi)).norm(); }

  Vec3 centroid(int t) const {
    const auto& v = mesh_.triangles[t];
    return (mesh_.vertices[v[0]] + mesh_.vertices[v[1]] + mesh_.vertices[v[2]]) / 3.0;
  }

  /// Builds the node of order_[first, last) and those below it; returns its index.
  int build(int first, int last) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (int k = first; k < last; ++k) {
      for (const int v : mesh_.triangles[order_[k]]) {
        lo = lo.cwiseMin(mesh_.vertices[v]);
        hi = hi.cwiseMax(mesh_.vertices[v]);
      }
    }
    nodes_[index].lo = lo;
    nodes_[index].hi = hi;
    if (last - first <= kLeaf) {
      nodes_[index].first = first;
      nodes_[index].count = last - first;
      return index;
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const int middle = first + (last - first) / 2;
    std::nth_element(order_.begin() + first, order_.begin() + middle, order_.begin() + last,
                     [&](int a, int b) { return centroid(a)(axis) < centroid(b)(axis); });
    const int left = build(first, middle);
    const int right = build(middle, last);
    nodes_[index].left = left;
    nodes_[index].right = right;
    return index;
  }

  const TriangleMesh& mesh_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

/// Whether each sample is inside the mesh: by the parity of the triangles a
/// line of samples crosses, along each axis, by majority of the three. A
/// triangle wound the wrong way changes no parity, and a small hole one
/// axis's rays pass through is outvoted by the other two. The rays are
/// offset by a few parts in 1e7 of a cell from the sample lines, so that
/// they meet no edge exactly (an edge two triangles share would count twice).
std::vector<char> insideSamples(const TriangleMesh& mesh, const Vec3& lo, double cell, const int n[3]) {
  const std::size_t count = static_cast<std::size_t>(n[0]) * n[1] * n[2];
  std::vector<unsigned char> votes(count, 0);
  const auto index = [n](int i, int j, int k) { return (static_cast<std::size_t>(k) * n[1] + j) * n[0] + i; };
  std::vector<std::vector<double>> hits;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // the plane the rays pierce
    const double shift_a = 3.1415926e-7 * cell, shift_b = 2.7182818e-7 * cell;
    hits.assign(static_cast<std::size_t>(n[a]) * n[b], {});
    for (const auto& t : mesh.triangles) {
      const Vec3 &p0 = mesh.vertices[t[0]], &p1 = mesh.vertices[t[1]], &p2 = mesh.vertices[t[2]];
      // The triangle in the plane (a, b): which ray lines its box spans.
      const double lo_a = std::min({p0(a), p1(a), p2(a)}), hi_a = std::max({p0(a), p1(a), p2(a)});
      const double lo_b = std::min({p0(b), p1(b), p2(b)}), hi_b = std::max({p0(b), p1(b), p2(b)});
      const int first_a = std::max(0, static_cast<int>(std::ceil((lo_a - shift_a - lo(a)) / cell)));
      const int last_a = std::min(n[a] - 1, static_cast<int>(std::floor((hi_a - shift_a - lo(a)) / cell)));
      const int first_b = std::max(0, static_cast<int>(std::ceil((lo_b - shift_b - lo(b)) / cell)));
      const int last_b = std::min(n[b] - 1, static_cast<int>(std::floor((hi_b - shift_b - lo(b)) / cell)));
      const double area = (p1(a) - p0(a)) * (p2(b) - p0(b)) - (p2(a) - p0(a)) * (p1(b) - p0(b));
      if (area == 0.0) continue;  // edge-on to these rays: crossed by none
      for (int jb = first_b; jb <= last_b; ++jb) {
        for (int ja = first_a; ja <= last_a; ++ja) {
          const double x = lo(a) + ja * cell + shift_a, y = lo(b) + jb * cell + shift_b;
          // Barycentric coordinates of the ray's point in the projected triangle.
          const double w1 = ((x - p0(a)) * (p2(b) - p0(b)) - (p2(a) - p0(a)) * (y - p0(b))) / area;
          const double w2 = ((p1(a) - p0(a)) * (y - p0(b)) - (x - p0(a)) * (p1(b) - p0(b))) / area;
          if (w1 < 0.0 || w2 < 0.0 || w1 + w2 > 1.0) continue;
          hits[static_cast<std::size_t>(jb) * n[a] + ja].push_back(p0(axis) + w1 * (p1(axis) - p0(axis)) +
                                                                   w2 * (p2(axis) - p0(axis)));
        }
      }
    }
    for (int jb = 0; jb < n[b]; ++jb) {
      for (int ja = 0; ja < n[a]; ++ja) {
        std::vector<double>& line = hits[static_cast<std::size_t>(jb) * n[a] + ja];
        std::sort(line.begin(), line.end());
        // Walking up the line: inside after an odd number of crossings.
        std::size_t crossed = 0;
        for (int s = 0; s < n[axis]; ++s) {
          const double at = lo(axis) + s * cell;
          while (crossed < line.size() && line[crossed] < at) ++crossed;
          if (crossed % 2 == 0) continue;
          int ijk[3];
          ijk[axis] = s;
          ijk[a] = ja;
          ijk[b] = jb;
          ++votes[index(ijk[0], ijk[1], ijk[2])];
        }
      }
    }
  }
  std::vector<char> inside(count);
  for (std::size_t i = 0; i < count; ++i) inside[i] = votes[i] >= 2 ? 1 : 0;
  return inside;
}

}  // namespace

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
  const std::vector<char> inside = insideSamples(mesh, grid->lo_, grid->cell_, grid->n_);
  const TriangleTree tree(mesh);
  grid->values_.resize(inside.size());
  std::size_t index = 0;
  for (int k = 0; k < grid->n_[2]; ++k) {
    for (int j = 0; j < grid->n_[1]; ++j) {
      for (int i = 0; i < grid->n_[0]; ++i, ++index) {
        const double distance = tree.distance(grid->lo_ + grid->cell_ * Vec3(i, j, k));
        grid->values_[index] = inside[index] ? -distance : distance;
      }
    }
  }
  return grid;
}

double meshSignedDistance(const TriangleMesh& mesh, const Vec3& p) {
  double distance = INFINITY, winding = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    distance = std::min(distance, pointTriangleDistance(p, a, b, c));
    winding += solidAngle(a - p, b - p, c - p);
  }
  return std::abs(winding) > 2.0 * M_PI ? -distance : distance;  // |winding number| > ½: inside
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
