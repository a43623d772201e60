// A body's collision geometry and the contact points it is sampled into.
#pragma once

#include <string>
#include <vector>

#include "rigid_body_sim/core/geometry.h"
#include "rigid_body_sim/core/types.h"

namespace rigid_body_sim::core {

/// One <collision> element, posed in the link frame L.
struct CollisionShape {
  enum class Kind { kBox, kSphere, kCylinder, kPoints };
  Kind kind = Kind::kBox;
  Pose X_LS;                 ///< pose of the shape in the link frame
  Vec3 size = Vec3::Zero();  ///< box: full size along x, y, z (m)
  double radius = 0.0;       ///< sphere, cylinder (m)
  double length = 0.0;       ///< cylinder: along z (m)
  TriangleMesh mesh;         ///< kPoints: the mesh, scaled, in the shape frame (m)
  std::string name;          ///< where it came from, for messages
};

/// A point the contact stage tests against the scene: a vertex (radius 0)
/// or the centre of a sphere, which touches when φ(centre) < radius.
struct ContactPoint {
  Vec3 r_B = Vec3::Zero();  ///< position relative to the centre of mass, body frame B (m)
  double radius = 0.0;      ///< m
  /// A corner of its shape's convex hull (box corners, cylinder rims, sphere
  /// centres, mesh vertices). Against a plane only these can be deepest, so
  /// the plane test skips the others (a box's edge and face samples).
  bool extreme = true;
  /// The outward normal of the face the point samples (unit, B): box and
  /// cap faces, cylinder sides, sampled sphere surfaces. Zero where the
  /// surface has no one normal: corners, edges, rims, sphere centres, mesh
  /// vertices. Detection uses it to drop contacts another body's solid gives
  /// a face point along its own edges (§5.1).
  Vec3 normal_B = Vec3::Zero();
};

/// How many points sampleShape() gives, at most, computed without sampling
/// (so a spacing of 1e-12 m is refused before it allocates anything).
double sampleCount(const CollisionShape& shape, double spacing, bool sample_spheres);

/// Samples a shape into contact points at most `spacing` (m) apart, expressed
/// in the body frame B through X_BL (the link frame's pose in B):
///  - box: the 8 corners, plus points along the edges and on the faces;
///  - cylinder: points around both rims, on the caps and along the side;
///  - sphere: its centre with the sphere's radius, which is exact (a sampled
///    sphere is a polyhedron that bumps as it rolls), or, when
///    `sample_spheres` is set (shape matching needs vertices), points spread
///    evenly over the surface;
///  - points: the mesh vertices as given.
std::vector<ContactPoint> sampleShape(const CollisionShape& shape, const Pose& X_BL, double spacing,
                                      bool sample_spheres);

}  // namespace rigid_body_sim::core
