// A body's collision geometry and the contact points it is sampled into.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/geometry.h"
#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

/// One <collision> element, posed in the link frame L.
struct CollisionShape {
  enum class Kind { kBox, kSphere, kCylinder, kCapsule, kPoints };
  Kind kind = Kind::kBox;
  Pose X_LS;                 ///< pose of the shape in the link frame
  Vec3 size = Vec3::Zero();  ///< box: full size along x, y, z (m)
  double radius = 0.0;       ///< sphere, cylinder, capsule (m)
  double length = 0.0;       ///< cylinder, capsule: along z (m; a capsule's segment, without its caps)
  TriangleMesh mesh;         ///< kPoints: the mesh, scaled, in the shape frame (m)
  std::string name;          ///< where it came from, for messages
  /// Its own surface's μ_T: a link lumped into the body with friction of
  /// its own (Gazebo's <mu1>, <mu2> on that link). Unset: the body's.
  std::optional<double> friction;
};

/// A round edge or core of a shape, found exactly rather than sampled
/// (docs/physics.md §5.1): the points c + ρ u + t a with u a unit vector
/// across the axis a and |t| ≤ h.
///  - rim (h = 0): a cylinder's rim circle of radius ρ;
///  - segment (ρ = 0): a capsule's core, swept by the contact point's radius;
///  - side (both): a cylinder's side, the line at the deepest u.
struct RoundFeature {
  enum class Kind { kRim, kSegment, kSide };
  Kind kind = Kind::kRim;
  Vec3 centre_B = Vec3::Zero();   ///< the rim's centre, or the segment's or side's midpoint (m)
  Vec3 axis_B = Vec3::UnitZ();    ///< a, unit
  Vec3 across_B = Vec3::UnitX();  ///< a unit vector across a: where a rim's first point sits when the rim lies flat
  double rho = 0.0;               ///< ρ (m)
  double half_length = 0.0;       ///< h (m)
};

/// A point the contact stage tests against the scene: a vertex (radius 0),
/// the centre of a sphere, which touches when φ(centre) < radius, or a
/// point of a round feature, found where it is deepest.
struct ContactPoint {
  Vec3 r_B = Vec3::Zero();  ///< position relative to the centre of mass, body frame B (m)
  double radius = 0.0;      ///< m
  /// A corner of its shape's convex hull (box corners, sphere and capsule
  /// end centres, mesh vertices). Against a plane only these and the rims
  /// can be deepest, so the plane test skips the others (a box's edge and
  /// face samples).
  bool extreme = true;
  /// Of a rim: which of its three points, 120° apart, the first being the
  /// deepest (three hold a cylinder standing on its cap). Of a segment or
  /// side: which end of the stretch that bears. Otherwise 0.
  std::int8_t phase = 0;
  /// Its shape's surface: 0 the body's, k > 0 BodyModel::surface_friction[k − 1]
  /// (a shape with friction of its own).
  std::uint8_t surface = 0;
  /// Its round feature (an index into the body's round features; into
  /// ShapeSamples::round for sampleShape()), or −1: the point is r_B. For a
  /// round feature r_B is the feature's centre.
  int round = -1;
  /// The outward normal of the face the point samples (unit, B): box and
  /// cap faces, cylinder sides, sampled sphere surfaces. Zero where the
  /// surface has no one normal: corners, edges, rims, sphere centres, mesh
  /// vertices. Detection uses it to drop contacts another body's solid gives
  /// a face point along its own edges (§5.1).
  Vec3 normal_B = Vec3::Zero();
};

/// How many points sampleShape() gives, at most, computed without sampling
/// (so a spacing of 1e-12 m is refused before it allocates anything).
double sampleCount(const CollisionShape& shape, double spacing, bool sample_round);

/// A shape's contact points and the round features some of them refer to.
struct ShapeSamples {
  std::vector<ContactPoint> points;
  std::vector<RoundFeature> round;
};

/// Samples a shape into contact points at most `spacing` (m) apart, expressed
/// in the body frame B through X_BL (the link frame's pose in B):
///  - box: the 8 corners, plus points along the edges and on the faces;
///  - sphere: its centre with the sphere's radius, which is exact (a sampled
///    sphere is a polyhedron that bumps as it rolls);
///  - capsule: its two end centres with its radius, and its segment;
///  - cylinder: its two rims (three points each) and its side, exact, and
///    points on the caps (for edges and corners that meet a cap inside);
///  - points: the mesh vertices as given.
/// With `sample_round` (shape matching needs vertices) spheres, capsules and
/// cylinders are points spread over their surfaces instead.
ShapeSamples sampleShape(const CollisionShape& shape, const Pose& X_BL, double spacing, bool sample_round);

}  // namespace rigid_body_sim::core
