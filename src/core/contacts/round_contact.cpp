#include "round_contact.h"

#include <cmath>

#include "rigid_body_sim/core/bodies/settings.h"

namespace rigid_body_sim::core::detail {
namespace {

/// The unit u across a with n · u least: where a rim is deepest along n.
Vec3 deepestAcross(const Vec3& n, const Vec3& a, const Vec3& across) {
  const Vec3 perp = n - n.dot(a) * a;
  const double norm = perp.norm();
  return norm > SolverSettings::kFlatRim ? Vec3(-perp / norm) : across;
}

/// u turned about a by phase × 120° (phase 2 is −120°).
Vec3 turned(const Vec3& u, const Vec3& a, int phase) {
  if (phase == 0) return u;
  constexpr double kSin120 = 0.8660254037844386;
  return -0.5 * u + (phase == 1 ? kSin120 : -kSin120) * a.cross(u);
}

/// The stretch [t0, t1] of [−h, h] where φ along c + t a is level (|∇φ · a|
/// ≤ SolverSettings::kLevelSlope) and lowest, found by bisection, if the line comes down
/// into it from both ends (φ is convex along a line for convex shapes; for
/// others this is a local minimum). A line lying on a flat face gets the
/// two ends of what it lies on, one crossing an edge or a curve one point
/// (t0 ≈ t1); a line whose lowest point is an end has none (the end spheres
/// and the rims hold it). t0 and t1 are the bracket's level sides, so the
/// normal there is the face's, not the edge's beside it.
bool levelStretch(const Sdf& sdf, const Vec3& c, const Vec3& a, double h, double& t0, double& t1) {
  Vec3 n;
  const auto slope = [&](double t) {
    sdf.eval(c + t * a, &n);
    return n.dot(a);
  };
  if (!(slope(-h) < -SolverSettings::kLevelSlope) || !(slope(h) > SolverSettings::kLevelSlope)) return false;
  double lo = -h, hi = h;
  for (int k = 0; k < 60 && hi - lo > SolverSettings::kLevelLength; ++k) {  // the first level t
    const double mid = 0.5 * (lo + hi);
    (slope(mid) < -SolverSettings::kLevelSlope ? lo : hi) = mid;
  }
  t0 = hi;
  lo = t0;
  hi = h;
  for (int k = 0; k < 60 && hi - lo > SolverSettings::kLevelLength; ++k) {  // the last level t
    const double mid = 0.5 * (lo + hi);
    (slope(mid) <= SolverSettings::kLevelSlope ? lo : hi) = mid;
  }
  t1 = lo;
  return true;
}

}  // namespace

RoundHit rimOnPlane(const RoundFeature& rim, int phase, const Vec3& n_B, double phi_centre) {
  const Vec3 u = turned(deepestAcross(n_B, rim.axis_B, rim.across_B), rim.axis_B, phase);
  RoundHit hit;
  hit.r_B = rim.centre_B + rim.rho * u;
  hit.phi = phi_centre + n_B.dot(hit.r_B);
  return hit;
}

bool roundOnSdf(const RoundFeature& f, int phase, const Sdf& sdf, const Mat3& R_FB, const Vec3& p_FB, RoundHit& hit) {
  const Vec3 c = p_FB + R_FB * f.centre_B, a = R_FB * f.axis_B, across = R_FB * f.across_B;
  Vec3 n;
  double t = 0.0, t0 = 0.0, t1 = 0.0;
  if (f.kind == RoundFeature::Kind::kSegment) {
    if (!levelStretch(sdf, c, a, f.half_length, t0, t1)) return false;
    t = phase == 0 ? t0 : t1;
    hit.phi = sdf.eval(c + t * a, &hit.normal_F);
    hit.r_B = f.centre_B + t * f.axis_B;
    return true;
  }
  sdf.eval(c, &n);
  Vec3 u = deepestAcross(n, a, across);
  if (f.kind == RoundFeature::Kind::kSide) {
    // The line along the side where it faces the surface, where it is
    // lowest, then u again from the normal there and the line once more.
    if (!levelStretch(sdf, c + f.rho * u, a, f.half_length, t0, t1)) return false;
    sdf.eval(c + f.rho * u + 0.5 * (t0 + t1) * a, &n);
    u = deepestAcross(n, a, across);
    if (!levelStretch(sdf, c + f.rho * u, a, f.half_length, t0, t1)) return false;
    t = phase == 0 ? t0 : t1;
  } else {
    // A rim: u from the normal at the rim's point, until it settles (at
    // once for a plane; a few rounds where the surface curves).
    for (int k = 0; k < 4; ++k) {
      sdf.eval(c + f.rho * u, &n);
      const Vec3 next = deepestAcross(n, a, across);
      const bool settled = (next - u).squaredNorm() < 1e-24;
      u = next;
      if (settled) break;
    }
    u = turned(u, a, phase);
  }
  const Vec3 p = c + f.rho * u + t * a;
  hit.phi = sdf.eval(p, &hit.normal_F);
  hit.r_B = R_FB.transpose() * (p - p_FB);
  return true;
}

}  // namespace rigid_body_sim::core::detail
