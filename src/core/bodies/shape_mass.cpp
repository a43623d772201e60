// Mass properties of collision shapes: shape_mass.h.
#include "rigid_body_sim/core/bodies/shape_mass.h"

#include <cmath>

namespace rigid_body_sim::core {
namespace {

/// A solid box of mass m and full extents s, about its centre.
Mat3 boxInertia(double m, const Vec3& s) {
  return (m / 12.0 * Vec3(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(), s.x() * s.x() + s.y() * s.y()))
      .asDiagonal();
}

/// A solid cylinder along z, radius r, length l, mass m, about its centre.
Mat3 cylinderInertia(double m, double r, double l) {
  const double side = m * (3.0 * r * r + l * l) / 12.0;
  return Vec3(side, side, 0.5 * m * r * r).asDiagonal();
}

/// The mesh's mass properties in its own frame: Σ over triangles (a, b, c)
/// of the tetrahedron (0, a, b, c), signed volume V = a·(b × c)/6, centroid
/// (a + b + c)/4 and second moment ∫ x xᵀ dV = V/20 (aaᵀ + bbᵀ + ccᵀ + ssᵀ),
/// s = a + b + c. Its mass is 0 when it encloses no volume.
MassProperties meshMass(const TriangleMesh& mesh, double density) {
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double v = a.dot(b.cross(c)) / 6.0;
    const Vec3 s = a + b + c;
    volume += v;
    first += v * s / 4.0;
    second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  if (volume < 0.0) {  // wound inside out: the same solid
    volume = -volume;
    first = -first;
    second = -second;
  }
  MassProperties out;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  if (!mesh.vertices.empty()) lo = hi = mesh.vertices.front();
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double box = (hi - lo).prod();
  if (!(volume > 1e-9 * box) || !(box > 0.0)) {  // no volume enclosed: its bounding box
    out.mass = density * box;
    out.p_FC = 0.5 * (lo + hi);
    out.I_C_F = boxInertia(out.mass, hi - lo);
    return out;
  }
  out.mass = density * volume;
  out.p_FC = first / volume;
  const Mat3 about_origin = density * (second.trace() * Mat3::Identity() - second);
  out.I_C_F = parallelAxis(about_origin, -out.mass, out.p_FC);  // back to the centre of mass
  return out;
}

}  // namespace

MassProperties shapeMassProperties(const CollisionShape& shape, double density) {
  MassProperties local;  // in the shape frame S
  switch (shape.kind) {
    case CollisionShape::Kind::kBox:
      local.mass = density * shape.size.prod();
      local.I_C_F = boxInertia(local.mass, shape.size);
      break;
    case CollisionShape::Kind::kSphere: {
      const double r = shape.radius;
      local.mass = density * 4.0 / 3.0 * M_PI * r * r * r;
      local.I_C_F = (0.4 * local.mass * r * r) * Mat3::Identity();
      break;
    }
    case CollisionShape::Kind::kCylinder:
      local.mass = density * M_PI * shape.radius * shape.radius * shape.length;
      local.I_C_F = cylinderInertia(local.mass, shape.radius, shape.length);
      break;
    case CollisionShape::Kind::kCapsule: {
      // A cylinder and two half balls. A half ball of mass h about its
      // centre of mass, which lies 3r/8 from its flat face: 2/5 h r² about
      // the axis, (2/5 − 9/64) h r² across it; carried to the capsule's
      // middle, d = l/2 + 3r/8 away.
      const double r = shape.radius, l = shape.length;
      const double cylinder = density * M_PI * r * r * l;
      const double half = density * 2.0 / 3.0 * M_PI * r * r * r;
      const double d = 0.5 * l + 3.0 * r / 8.0;
      Mat3 I = cylinderInertia(cylinder, r, l);
      const double across = 2.0 * ((0.4 - 9.0 / 64.0) * half * r * r + half * d * d);
      I += Vec3(across, across, 2.0 * 0.4 * half * r * r).asDiagonal();
      local.mass = cylinder + 2.0 * half;
      local.I_C_F = I;
      break;
    }
    case CollisionShape::Kind::kPoints:
      local = meshMass(shape.mesh, density);
      break;
  }
  const Mat3 R = shape.X_LS.rotation.toRotationMatrix();
  return {local.mass, shape.X_LS * local.p_FC, R * local.I_C_F * R.transpose()};
}

MassProperties shapesMassProperties(const std::vector<CollisionShape>& shapes, double density) {
  std::vector<MassProperties> parts;
  parts.reserve(shapes.size());
  for (const CollisionShape& shape : shapes) parts.push_back(shapeMassProperties(shape, density));
  return combine(parts);
}

}  // namespace rigid_body_sim::core
