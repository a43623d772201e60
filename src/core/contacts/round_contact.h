// Where a round feature (a cylinder's rim or side, a capsule's segment;
// collision.h) is deepest against a surface (docs/physics.md §5.1): in closed
// form against a plane, by a short fixed-point or bisection search against
// any other signed distance. The contact stages call these in place of
// testing a fixed point.
#pragma once

#include "rigid_body_sim/core/bodies/collision.h"
#include "rigid_body_sim/core/bodies/sdf.h"

namespace rigid_body_sim::core::detail {

#pragma GCC visibility push(hidden)

/// A round feature's contact point.
struct RoundHit {
  Vec3 r_B = Vec3::Zero();        ///< the point on the feature, relative to the centre of mass, body frame B (m)
  double phi = 0.0;               ///< φ there (m), before the contact point's radius
  Vec3 normal_F = Vec3::UnitZ();  ///< ∇φ there, in the surface's frame F
};

/// A rim's point `phase` (0: the deepest; 1, 2: 120° on either side) against
/// the plane with unit normal n_B (B's axes) and φ = phi_centre at the
/// centre of mass. Exact.
RoundHit rimOnPlane(const RoundFeature& rim, int phase, const Vec3& n_B, double phi_centre);

/// The feature's point against `sdf`, which is in frame F, where the body
/// frame B sits at p_FB with axes R_FB. A segment or side has points only
/// where it is deeper inside than at both its ends (which the end spheres
/// and the rims cover): false when it has none; else its two points
/// (phase 0 and 1) are the ends of its lowest level stretch (one point
/// where it crosses an edge, the ends of what it lies on where it lies
/// flat).
bool roundOnSdf(const RoundFeature& f, int phase, const Sdf& sdf, const Mat3& R_FB, const Vec3& p_FB, RoundHit& hit);

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
