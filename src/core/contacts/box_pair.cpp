// Two boxes in contact (box_pair.h, docs/physics.md §5.1).
#include "box_pair.h"

#include <algorithm>
#include <cmath>

namespace rigid_body_sim::core::detail {
namespace {

/// The middle of the box's edge along `axis` that lies farthest along n.
Vec3 supportEdge(const BoxInFrame& b, int axis, const Vec3& n) {
  Vec3 p = b.centre_F;
  for (int k = 0; k < 3; ++k) {
    if (k != axis) p += (n.dot(b.R_FS.col(k)) >= 0.0 ? b.half(k) : -b.half(k)) * b.R_FS.col(k);
  }
  return p;
}

BoxInFrame boxOf(const Sdf& solid, const Mat3& R_FB, const Vec3& p_FB) {
  BoxInFrame box;
  box.centre_F = p_FB + R_FB * solid.pose().translation;
  box.R_FS = R_FB * solid.pose().rotation.toRotationMatrix();
  box.half = 0.5 * solid.size();
  return box;
}

}  // namespace

bool pairBoxes(const BodyModel& a, const BodyModel& o, const Mat3& R_OA, const Vec3& p_OA, BoxInFrame& box_a,
               BoxInFrame& box_o) {
  if (a.solid_B.empty() || o.solid_B.empty()) return false;
  const Sdf &solid_a = a.solid_B.front(), &solid_o = o.solid_B.front();
  if (solid_a.kind() != Sdf::Kind::kBox || solid_o.kind() != Sdf::Kind::kBox) return false;
  box_a = boxOf(solid_a, R_OA, p_OA);
  box_o = boxOf(solid_o, Mat3::Identity(), Vec3::Zero());
  return true;
}

PairPlane boxPairPlane(const BoxInFrame& base, const BoxInFrame& other, bool base_first) {
  // In base's axes: other's axes are the columns of C, the centres t apart.
  // Each axis's overlap is ra + rb − |t · L|, over |L| for the edge pairs
  // (|e_i × c_j| = √(1 − C_ij²)), as in Gottschalk's OBB test.
  const Mat3 C = base.R_FS.transpose() * other.R_FS;
  const Mat3 A = C.cwiseAbs();
  const Vec3 t = base.R_FS.transpose() * (other.centre_F - base.centre_F);
  const Vec3 &hb = base.half, &ho = other.half;
  PairPlane plane;
  Vec3 best_L = Vec3::Zero();  // in base's axes, unit
  double best_overlap = INFINITY;
  plane.gap = -INFINITY;
  int chosen_face = -1, chosen_edge_base = -1, chosen_edge_other = -1;
  // Takes L if it overlaps less than the best by the margin (any axis the
  // first time); every axis counts toward the gap.
  const auto consider = [&](const Vec3& L, double overlap, double margin, int face, int edge_base, int edge_other) {
    plane.gap = std::max(plane.gap, -overlap);
    if (best_overlap != INFINITY &&
        !(overlap < best_overlap - margin * std::abs(best_overlap) - SolverSettings::kBoxAbsoluteMargin)) {
      return;
    }
    best_overlap = overlap;
    best_L = L;
    chosen_face = face;
    chosen_edge_base = edge_base;
    chosen_edge_other = edge_other;
  };
  const auto base_faces = [&](double margin) {
    for (int i = 0; i < 3; ++i) {
      consider(Vec3::Unit(i), hb(i) + ho.dot(A.row(i).transpose()) - std::abs(t(i)), margin, i, -1, -1);
    }
  };
  const auto other_faces = [&](double margin) {
    for (int j = 0; j < 3; ++j) {
      consider(C.col(j), hb.dot(A.col(j)) + ho(j) - std::abs(t.dot(C.col(j))), margin, -1, -1, -1);
    }
  };
  if (base_first) {
    base_faces(0.0);
    other_faces(SolverSettings::kBoxFaceMargin);
  } else {
    other_faces(0.0);
    base_faces(SolverSettings::kBoxFaceMargin);
  }
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const double sine = std::sqrt(std::max(0.0, 1.0 - C(i, j) * C(i, j)));
      if (!(sine > SolverSettings::kBoxParallelSine)) continue;
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const Vec3 L = Vec3::Unit(i).cross(Vec3(C.col(j)));
      const double ra = hb(i1) * A(i2, j) + hb(i2) * A(i1, j);
      const double rb = ho(j1) * A(i, j2) + ho(j2) * A(i, j1);
      consider(L / sine, (ra + rb - std::abs(t.dot(L))) / sine, SolverSettings::kBoxEdgeMargin, -1, i, j);
    }
  }
  if (best_L.dot(t) < 0.0) best_L = -best_L;  // from base toward other
  plane.n_F = base.R_FS * best_L;
  plane.support = plane.n_F.dot(base.centre_F) + hb.dot(best_L.cwiseAbs());
  plane.base_face = chosen_face;
  plane.base_edge = chosen_edge_base;
  plane.other_edge = chosen_edge_other;
  return plane;
}

namespace {

/// The point of other's edge nearest base's edge, for an edge pair's plane.
bool edgeCrossing(const BoxInFrame& base, const BoxInFrame& other, const PairPlane& plane, Vec3& on_other_F) {
  const Vec3 u = base.R_FS.col(plane.base_edge), w = other.R_FS.col(plane.other_edge);
  const Vec3 p0 = supportEdge(base, plane.base_edge, plane.n_F);
  const Vec3 q0 = supportEdge(other, plane.other_edge, -plane.n_F);
  // The lines p0 + s u and q0 + t w come nearest where both derivatives of
  // |p0 + s u − q0 − t w|² vanish.
  const Vec3 r = p0 - q0;
  const double b = u.dot(w), d = u.dot(r), e = w.dot(r);
  const double s = (b * e - d) / (1.0 - b * b);  // 1 − b² ≥ kParallelSine²: the axis was an edge pair's
  const double t = e + s * b;
  if (!(std::abs(s) <= base.half(plane.base_edge)) || !(std::abs(t) <= other.half(plane.other_edge))) return false;
  on_other_F = q0 + t * w;
  return true;
}

/// The two axes other than `axis`, in order.
void otherAxes(int axis, int& k1, int& k2) {
  k1 = axis == 0 ? 1 : 0;
  k2 = axis == 2 ? 1 : 2;
}

/// Edge `edge` of box b (4 × its axis + 2 × (sign of its first other axis
/// > 0) + (sign of its second > 0)): its two ends.
void edgeEnds(const BoxInFrame& b, int edge, Vec3& e0, Vec3& e1) {
  const int axis = edge / 4;
  int k1, k2;
  otherAxes(axis, k1, k2);
  const Vec3 mid = b.centre_F + ((edge & 2) ? b.half(k1) : -b.half(k1)) * b.R_FS.col(k1) +
                   ((edge & 1) ? b.half(k2) : -b.half(k2)) * b.R_FS.col(k2);
  e0 = mid - b.half(axis) * b.R_FS.col(axis);
  e1 = mid + b.half(axis) * b.R_FS.col(axis);
}

/// Where other's edge `edge` crosses side `side` of base's face `face`
/// (side 2 × slot + (sign > 0), slot 0 or 1 for the face's first or second
/// other axis) within that side's length.
bool sideCrossing(const BoxInFrame& base, const BoxInFrame& other, int face, int edge, int side, Vec3& p_F) {
  int k1, k2;
  otherAxes(face, k1, k2);
  const int k = side / 2 == 0 ? k1 : k2, l = side / 2 == 0 ? k2 : k1;
  const double target = (side & 1) ? base.half(k) : -base.half(k);
  Vec3 e0, e1;
  edgeEnds(other, edge, e0, e1);
  const Vec3 axis_k = base.R_FS.col(k);
  const double a0 = (e0 - base.centre_F).dot(axis_k) - target, a1 = (e1 - base.centre_F).dot(axis_k) - target;
  if (!((a0 <= 0.0) != (a1 <= 0.0))) return false;  // both ends on one side of it
  p_F = e0 + (a0 / (a0 - a1)) * (e1 - e0);
  return std::abs((p_F - base.centre_F).dot(base.R_FS.col(l))) <= base.half(l);
}

}  // namespace

int pairPoints(const BoxInFrame& base, const BoxInFrame& other, const PairPlane& plane,
               PairPoint (&out)[kMaxPairPoints]) {
  if (plane.base_edge >= 0) {
    if (!edgeCrossing(base, other, plane, out[0].p_F)) return 0;
    out[0].id = kEdgeCrossing;
    return 1;
  }
  if (plane.base_face < 0) return 0;
  // Other's face turned most against n: its four edges.
  int m = 0;
  for (int j = 1; j < 3; ++j) {
    if (std::abs(plane.n_F.dot(other.R_FS.col(j))) > std::abs(plane.n_F.dot(other.R_FS.col(m)))) m = j;
  }
  const bool m_positive = plane.n_F.dot(other.R_FS.col(m)) < 0.0;
  int a, b;
  otherAxes(m, a, b);
  int count = 0;
  for (const int along : {a, b}) {
    for (const bool across_positive : {false, true}) {
      // The edge along `along` at m's sign and across's: its index's bits
      // go to its own other axes in order.
      int k1, k2;
      otherAxes(along, k1, k2);
      const bool first_positive = k1 == m ? m_positive : across_positive;
      const bool second_positive = k2 == m ? m_positive : across_positive;
      const int edge = 4 * along + 2 * first_positive + second_positive;
      for (int side = 0; side < 4 && count < kMaxPairPoints; ++side) {
        if (sideCrossing(base, other, plane.base_face, edge, side, out[count].p_F)) {
          out[count++].id = kSideCrossing - (4 * edge + side);
        }
      }
    }
  }
  return count;
}

bool pairPoint(const BoxInFrame& base, const BoxInFrame& other, const PairPlane& plane, int id, Vec3& p_F) {
  if (id == kEdgeCrossing) return plane.base_edge >= 0 && edgeCrossing(base, other, plane, p_F);
  const int k = kSideCrossing - id;
  return plane.base_face >= 0 && k >= 0 && k < 48 && sideCrossing(base, other, plane.base_face, k / 4, k % 4, p_F);
}

}  // namespace rigid_body_sim::core::detail
