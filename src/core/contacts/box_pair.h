// Two boxes in contact (docs/physics.md §5.1): one normal for the pair, the
// axis along which they overlap least (or are farthest apart) of the fifteen
// a separating-axis test tries, as ODE's and Bullet's box-box tests choose
// it; and, where that axis is an edge pair's, the point where the two edges
// cross. Each box's points against the other then push along that one line,
// so two boxes whose edges cross no longer squeeze each other along the side
// faces their points happen to be nearest to, and an edge crossing between
// the samples is caught.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"

namespace rigid_body_sim::core::detail {

#pragma GCC visibility push(hidden)

/// A box: centre, axes and half extents, all in one frame F.
struct BoxInFrame {
  Vec3 centre_F = Vec3::Zero();  ///< m
  Mat3 R_FS = Mat3::Identity();  ///< its axes
  Vec3 half = Vec3::Zero();      ///< half extents (m)
};

/// The plane a pair's points are measured against: a point p_F of `other`
/// is at signed distance `n_F · p_F − support` from `base`.
struct PairPlane {
  Vec3 n_F = Vec3::UnitZ();  ///< unit, from `base` toward `other`
  double support = 0.0;      ///< the largest n_F · x over `base` (m)
  /// The largest separation along any of the fifteen axes (m; ≤ 0 where
  /// they overlap): no point of other is nearer base than this.
  double gap = 0.0;
  /// n_F is ± this axis of base's (a face of base), or −1.
  int base_face = -1;
  /// n_F is the cross product of these axes' edges (base's, other's), or −1.
  int base_edge = -1, other_edge = -1;
};

/// Whether both bodies' solids are single boxes; if so, both in o's body
/// frame (F = B of o), where a's centre of mass is at p_OA with axes R_OA.
bool pairBoxes(const BodyModel& a, const BodyModel& o, const Mat3& R_OA, const Vec3& p_OA, BoxInFrame& box_a,
               BoxInFrame& box_o);

/// The separating axis of two boxes in one frame, pointing from `base`
/// toward `other`: of base's three face normals, other's three and the nine
/// cross products of their edges, the one with the least overlap. Ties go
/// to the faces, and between the faces to the box with the lower body
/// index (`base_first`), so both directions of a pair pick the same line.
PairPlane boxPairPlane(const BoxInFrame& base, const BoxInFrame& other, bool base_first);

/// A point of `other`'s edges where the pair touches between its samples,
/// named as a ContactKey::point: kEdgeCrossing, or kSideCrossing − k.
struct PairPoint {
  int id = kEdgeCrossing;
  Vec3 p_F = Vec3::Zero();
};

/// Ids of the points where an edge of other's crosses a side of base's
/// face: kSideCrossing − (4 × edge + side), edge 0–11, side 0–3.
constexpr int kSideCrossing = kEdgeCrossing - 1;

/// How many PairPoints pairPoints() gives at most.
constexpr int kMaxPairPoints = 8;

/// Other's points that its samples may miss: for an edge pair's plane, the
/// point of other's edge nearest base's edge, where both edges meet (none
/// when the nearest points of their lines lie beyond an end: a corner or a
/// face meets the other box there, which the samples cover); for a plane of
/// base's face, the points where the edges of other's face turned to it
/// cross the sides of that face (the corners of the region they share that
/// are neither box's corner). Returns how many it wrote to `out`.
int pairPoints(const BoxInFrame& base, const BoxInFrame& other, const PairPlane& plane,
               PairPoint (&out)[kMaxPairPoints]);

/// The point `id` names, at the boxes' present poses; false if it no longer exists.
bool pairPoint(const BoxInFrame& base, const BoxInFrame& other, const PairPlane& plane, int id, Vec3& p_F);

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
