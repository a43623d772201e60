#include "rigid_body_sim/core/bodies/collision.h"

#include <algorithm>
#include <cmath>

namespace rigid_body_sim::core {
namespace {

/// Number of intervals so that none is longer than `spacing`.
int intervals(double length, double spacing) {
  return std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
}

/// A sample's position, whether it is extreme, and its face normal (zero: none), in the shape's frame.
struct Sample {
  std::vector<Vec3> at, normal;
  std::vector<bool> extreme;
  void add(const Vec3& p, bool is_extreme, const Vec3& n = Vec3::Zero()) {
    at.push_back(p);
    extreme.push_back(is_extreme);
    normal.push_back(n);
  }
};

void sampleBox(const Vec3& size, double spacing, Sample& out) {
  const Vec3 h = 0.5 * size;
  const int n[3] = {intervals(size.x(), spacing), intervals(size.y(), spacing), intervals(size.z(), spacing)};
  // A lattice point (i, j, k) lies on the surface when one index is at an end;
  // corners have three end indices, edges two, faces one.
  for (int i = 0; i <= n[0]; ++i) {
    for (int j = 0; j <= n[1]; ++j) {
      for (int k = 0; k <= n[2]; ++k) {
        const int ends = (i == 0 || i == n[0]) + (j == 0 || j == n[1]) + (k == 0 || k == n[2]);
        if (ends == 0) continue;     // inside the box
        Vec3 normal = Vec3::Zero();  // on one face only: its normal
        if (ends == 1) {
          const int index[3] = {i, j, k};
          for (int axis = 0; axis < 3; ++axis) {
            if (index[axis] == 0) normal[axis] = -1.0;
            if (index[axis] == n[axis]) normal[axis] = 1.0;
          }
        }
        out.add(Vec3(-h.x() + size.x() * i / n[0], -h.y() + size.y() * j / n[1], -h.z() + size.z() * k / n[2]),
                ends == 3, normal);  // extreme: a corner
      }
    }
  }
}

/// Points around both rims and along the side of a cylinder (shape
/// matching's vertices), rim points extreme.
void sampleCylinderSide(double radius, double length, double spacing, Sample& out) {
  const int around = std::max(8, intervals(2.0 * M_PI * radius, spacing));
  const int along = intervals(length, spacing);
  for (int k = 0; k <= along; ++k) {  // rims and the side, ring by ring
    const double z = -0.5 * length + length * k / along;
    for (int a = 0; a < around; ++a) {
      const double t = 2.0 * M_PI * a / around;
      const bool rim = k == 0 || k == along;
      out.add(Vec3(radius * std::cos(t), radius * std::sin(t), z), rim,
              rim ? Vec3::Zero() : Vec3(std::cos(t), std::sin(t), 0.0));
    }
  }
}

/// Points on a cylinder's caps inside the rims: the centres and inner rings.
void sampleCaps(double radius, double length, double spacing, Sample& out) {
  const int rings = intervals(radius, spacing);
  for (double z : {-0.5 * length, 0.5 * length}) {
    const Vec3 cap(0.0, 0.0, z > 0.0 ? 1.0 : -1.0);
    out.add(Vec3(0.0, 0.0, z), false, cap);
    for (int r = 1; r < rings; ++r) {
      const double rr = radius * r / rings;
      const int m = std::max(6, intervals(2.0 * M_PI * rr, spacing));
      for (int a = 0; a < m; ++a) {
        const double t = 2.0 * M_PI * a / m;
        out.add(Vec3(rr * std::cos(t), rr * std::sin(t), z), false, cap);
      }
    }
  }
}

/// Evenly spread points on a sphere (a Fibonacci lattice); a capsule's
/// caps are its two halves, moved apart by `length` along z.
void sampleSphereSurface(double radius, double length, double spacing, Sample& out) {
  const int n = std::max(12, static_cast<int>(std::ceil(4.0 * M_PI * radius * radius / (spacing * spacing))));
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt(1.0 - z * z);
    const Vec3 normal(r * std::cos(golden * i), r * std::sin(golden * i), z);
    out.add(radius * normal + Vec3(0.0, 0.0, z > 0.0 ? 0.5 * length : -0.5 * length), true, normal);
  }
}

/// Intervals of `spacing` along `length`, in floating point (no int to overflow).
double intervalCount(double length, double spacing) { return std::max(1.0, std::ceil(length / spacing - 1e-9)); }

}  // namespace

double sampleCount(const CollisionShape& shape, double spacing, bool sample_round) {
  const auto sphere = [&] {
    return std::max(12.0, std::ceil(4.0 * M_PI * shape.radius * shape.radius / (spacing * spacing)));
  };
  const double around = std::max(8.0, intervalCount(2.0 * M_PI * shape.radius, spacing));
  const double along = intervalCount(shape.length, spacing);
  switch (shape.kind) {
    case CollisionShape::Kind::kBox: {
      const double n = intervalCount(shape.size.x(), spacing) + 1.0;
      const double m = intervalCount(shape.size.y(), spacing) + 1.0;
      const double k = intervalCount(shape.size.z(), spacing) + 1.0;
      return n * m * k;  // the whole lattice: more than its surface
    }
    case CollisionShape::Kind::kCylinder:  // side and rims (or 7 exact points), and caps
      return (sample_round ? around * (along + 1.0) : 8.0) + 2.0 * around * intervalCount(shape.radius, spacing) + 2.0;
    case CollisionShape::Kind::kCapsule:
      return sample_round ? sphere() + around * (along + 1.0) : 4.0;
    case CollisionShape::Kind::kSphere:
      return sample_round ? sphere() : 1.0;
    case CollisionShape::Kind::kPoints:
      return static_cast<double>(shape.mesh.vertices.size());
  }
  return 0.0;
}

ShapeSamples sampleShape(const CollisionShape& shape, const Pose& X_BL, double spacing, bool sample_round) {
  Sample local;
  double radius = 0.0;
  std::vector<RoundFeature> round;                    // in the shape's frame
  std::vector<std::pair<int, std::int8_t>> round_of;  // per sample: (feature, phase), or (−1, 0)
  const auto addRound = [&](const RoundFeature& f, int phases) {
    for (int k = 0; k < phases; ++k) {
      local.add(f.centre_B, false);
      round_of.resize(local.at.size() - 1, {-1, 0});
      round_of.push_back({static_cast<int>(round.size()), static_cast<std::int8_t>(k)});
    }
    round.push_back(f);
  };
  const double h = 0.5 * shape.length;
  switch (shape.kind) {
    case CollisionShape::Kind::kBox:
      sampleBox(shape.size, spacing, local);
      break;
    case CollisionShape::Kind::kCylinder:
      if (sample_round) {
        sampleCylinderSide(shape.radius, shape.length, spacing, local);
      } else {
        for (const double z : {-h, h})
          addRound({RoundFeature::Kind::kRim, Vec3(0.0, 0.0, z), Vec3::UnitZ(), Vec3::UnitX(), shape.radius, 0.0}, 3);
        addRound({RoundFeature::Kind::kSide, Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), shape.radius, h}, 2);
      }
      sampleCaps(shape.radius, shape.length, spacing, local);
      break;
    case CollisionShape::Kind::kCapsule:
      if (sample_round) {
        sampleSphereSurface(shape.radius, shape.length, spacing, local);
        Sample side;
        sampleCylinderSide(shape.radius, shape.length, spacing, side);
        for (std::size_t i = 0; i < side.at.size(); ++i) {
          if (!side.extreme[i]) local.add(side.at[i], false, side.normal[i]);
        }
      } else {
        local.add(Vec3(0.0, 0.0, -h), true);
        local.add(Vec3(0.0, 0.0, h), true);
        addRound({RoundFeature::Kind::kSegment, Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 0.0, h}, 2);
        radius = shape.radius;
      }
      break;
    case CollisionShape::Kind::kSphere:
      if (sample_round) {
        sampleSphereSurface(shape.radius, 0.0, spacing, local);
      } else {
        local.add(Vec3::Zero(), true);
        radius = shape.radius;
      }
      break;
    case CollisionShape::Kind::kPoints:
      for (const Vec3& v : shape.mesh.vertices) local.add(v, true);
      break;
  }
  round_of.resize(local.at.size(), {-1, 0});
  ShapeSamples out;
  out.points.reserve(local.at.size());
  const Pose X_BS = X_BL * shape.X_LS;
  for (std::size_t i = 0; i < local.at.size(); ++i) {
    ContactPoint p;
    p.r_B = X_BS * local.at[i];
    p.radius = radius;
    p.extreme = local.extreme[i];
    p.normal_B = X_BS.rotation * local.normal[i];
    p.round = round_of[i].first;
    p.phase = round_of[i].second;
    out.points.push_back(p);
  }
  for (RoundFeature f : round) {
    f.centre_B = X_BS * f.centre_B;
    f.axis_B = X_BS.rotation * f.axis_B;
    f.across_B = X_BS.rotation * f.across_B;
    out.round.push_back(f);
  }
  return out;
}

}  // namespace rigid_body_sim::core
