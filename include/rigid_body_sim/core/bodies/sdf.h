// Signed distance functions: collision detection (docs/physics.md §5.1).
//
// φ(x) < 0 inside a solid, > 0 in free space, with gradient ∇φ the outward
// unit normal. Primitives are exact (value and gradient); compositions:
//   union         φ = min(φᵢ)       exact outside, approximate inside
//   intersection  φ = max(φᵢ)       exact inside, a lower bound outside
//   difference    φ = max(φ₀, −φᵢ)  shape 0 with the others cut out
// Every composition stays 1-Lipschitz, so |φ(x) − φ(y)| ≤ |x − y| always:
// the contact stage uses this to skip shapes far from a body.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/geometry.h"
#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

class SdfGrid;

class Sdf {
 public:
  enum class Kind { kPlane, kSphere, kBox, kCapsule, kCylinder, kGrid, kUnion, kIntersection, kDifference };

  /// The half-space below the plane through `point` with outward `normal`.
  static Sdf plane(const Vec3& normal, const Vec3& point = Vec3::Zero());
  /// A sphere of `radius` (m) centred at the shape frame's origin.
  static Sdf sphere(double radius);
  /// A box of full size `size` (m), centred, axes of the shape frame.
  static Sdf box(const Vec3& size);
  /// A capsule: a segment of `length` (m) along z, swept by a sphere of `radius`.
  static Sdf capsule(double radius, double length);
  /// A cylinder of `radius` and `length` (m) along z, centred.
  static Sdf cylinder(double radius, double length);
  /// A sampled signed distance (a mesh's), in the shape frame.
  static Sdf grid(std::shared_ptr<const SdfGrid> grid);
  static Sdf unite(std::vector<Sdf> shapes);
  static Sdf intersect(std::vector<Sdf> shapes);
  /// shapes[0] with every other shape cut out of it.
  static Sdf subtract(std::vector<Sdf> shapes);

  /// The same shape moved by X_WS (composes with any pose it already has).
  Sdf transformed(const Pose& X_WS) const;

  /// φ at p_W (m) and, if `gradient` is given, ∇φ (unit length almost everywhere).
  double eval(const Vec3& p_W, Vec3* gradient = nullptr) const;

  Kind kind() const { return kind_; }
  /// Pose of the shape frame in the world; the dimensions below are in it.
  const Pose& pose() const { return X_WS_; }
  /// Plane: the outward unit normal, in the shape frame's axes.
  const Vec3& normal() const { return params_; }
  /// Box: the full size along x, y, z (m).
  const Vec3& size() const { return params_; }
  /// Sphere, capsule, cylinder: the radius (m).
  double radius() const { return params_.x(); }
  /// Capsule, cylinder: the length along z (m; a capsule's without its caps).
  double length() const { return params_.y(); }
  const std::vector<Sdf>& children() const { return children_; }
  const SdfGrid* samples() const { return grid_.get(); }
  bool isComposite() const { return kind_ >= Kind::kUnion; }

 private:
  Sdf(Kind kind, const Vec3& params) : kind_(kind), params_(params) {}
  double evalLocal(const Vec3& p_S, Vec3* grad_S) const;

  Kind kind_;
  Vec3 params_;  ///< by kind: the normal, the size, or (radius, length, 0), read through the accessors above
  Pose X_WS_;
  Pose X_SW_;  // cached inverse
  std::vector<Sdf> children_;
  std::shared_ptr<const SdfGrid> grid_;
};

}  // namespace rigid_body_sim::core
