#include "body_geometry.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/core/bodies/sdf_grid.h"
#include "rigid_body_sim/core/bodies/sdf_surface.h"
#include "validate.h"

namespace rigid_body_sim::core::detail {
/// Orders the first `extreme` points by recursive median splits along the
/// widest axis into groups of at most `group_size`, and bounds each group by a sphere.
namespace {

std::vector<BodyModel::PointGroup> groupExtremePoints(std::vector<ContactPoint>& points, std::size_t extreme,
                                                      std::size_t group_size) {
  std::vector<BodyModel::PointGroup> groups;
  std::vector<std::pair<std::size_t, std::size_t>> todo{{0, extreme}};
  while (!todo.empty()) {
    const auto [begin, end] = todo.back();
    todo.pop_back();
    if (begin == end) continue;
    const auto first = points.begin() + static_cast<std::ptrdiff_t>(begin);
    const auto last = points.begin() + static_cast<std::ptrdiff_t>(end);
    if (end - begin <= group_size) {
      BodyModel::PointGroup g;
      g.begin = begin;
      g.end = end;
      for (auto it = first; it != last; ++it) g.centre_B += it->r_B;
      g.centre_B /= static_cast<double>(end - begin);
      for (auto it = first; it != last; ++it) g.radius = std::max(g.radius, (it->r_B - g.centre_B).norm() + it->radius);
      groups.push_back(g);
      continue;
    }
    Vec3 lo = first->r_B, hi = first->r_B;
    for (auto it = first; it != last; ++it) {
      lo = lo.cwiseMin(it->r_B);
      hi = hi.cwiseMax(it->r_B);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(first, points.begin() + static_cast<std::ptrdiff_t>(mid), last,
                     [axis](const ContactPoint& x, const ContactPoint& y) {
                       return x.r_B(axis) != y.r_B(axis) ? x.r_B(axis) < y.r_B(axis)
                                                         : std::lexicographical_compare(x.r_B.data(), x.r_B.data() + 3,
                                                                                        y.r_B.data(), y.r_B.data() + 3);
                     });
    todo.push_back({mid, end});
    todo.push_back({begin, mid});
  }
  std::sort(groups.begin(), groups.end(),
            [](const BodyModel::PointGroup& x, const BodyModel::PointGroup& y) { return x.begin < y.begin; });
  return groups;
}

/// The surface `shape`'s points name (ContactPoint::surface): 0 the body's,
/// else its own friction's place in `surfaces` plus one (added if new).
std::uint8_t shapeSurface(const BodySpec& spec, const CollisionShape& shape, std::vector<double>& surfaces) {
  if (!shape.friction) return 0;
  const double mu = *shape.friction;
  detail::requireWithin(mu, 0.0, ranges::kMaxFriction, "body '" + spec.name + "': " + shape.name + " friction", "");
  auto at = std::find(surfaces.begin(), surfaces.end(), mu);
  if (at == surfaces.end()) {
    if (surfaces.size() == std::numeric_limits<std::uint8_t>::max()) {
      detail::fail("body '" + spec.name + "'", shape.name,
                   "its shapes have more than 255 frictions of their own (give them fewer)");
    }
    at = surfaces.insert(surfaces.end(), mu);
  }
  return static_cast<std::uint8_t>(at - surfaces.begin() + 1);
}

}  // namespace

/// Samples the body's collision shapes into contact points in B, and the
/// quantities shape matching needs.
void buildContactPoints(const BodySpec& spec, const ContactSettings& contact, const SolverSettings& solver,
                        BodyModel& b) {
  const Pose X_BL = Pose{b.q_LB, b.p_LB}.inverse();
  const bool sample_round = contact.method == ContactMethod::kShapeMatching;
  double count = 0.0;
  for (const CollisionShape& shape : spec.collision) count += sampleCount(shape, contact.sample_spacing, sample_round);
  if (count > ranges::kMaxContactPoints) {
    detail::fail("contact.sample_spacing", detail::str(contact.sample_spacing),
                 "body '" + spec.name + "' would get " + detail::str(count) + " contact points, more than " +
                     detail::str(ranges::kMaxContactPoints) + " (raise the spacing or simplify the mesh)");
  }
  std::vector<ContactPoint> points;
  std::vector<RoundFeature> round;
  std::vector<double> surfaces;  // the shapes' own frictions, each once
  for (const CollisionShape& shape : spec.collision) {
    ShapeSamples samples = sampleShape(shape, X_BL, contact.sample_spacing, sample_round);
    const std::uint8_t surface = shapeSurface(spec, shape, surfaces);
    for (ContactPoint& p : samples.points) {
      if (p.round >= 0) p.round += static_cast<int>(round.size());
      p.surface = surface;
    }
    points.insert(points.end(), samples.points.begin(), samples.points.end());
    round.insert(round.end(), samples.round.begin(), samples.round.end());
  }
  const auto first_other =
      std::stable_partition(points.begin(), points.end(), [](const ContactPoint& p) { return p.extreme; });
  b.extreme_points = static_cast<std::size_t>(first_other - points.begin());
  b.extreme_groups = groupExtremePoints(points, b.extreme_points, static_cast<std::size_t>(solver.point_group_size));
  std::vector<double> x, y, z, radius;
  for (std::size_t i = 0; i < b.extreme_points; ++i) {
    x.push_back(points[i].r_B.x());
    y.push_back(points[i].r_B.y());
    z.push_back(points[i].r_B.z());
    radius.push_back(points[i].radius);
  }
  std::vector<int> rims;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ContactPoint& p = points[i];
    const RoundFeature* f = p.round >= 0 ? &round[static_cast<std::size_t>(p.round)] : nullptr;
    if (f != nullptr && f->kind == RoundFeature::Kind::kRim) rims.push_back(static_cast<int>(i));
    const double reach = f != nullptr ? f->rho + f->half_length : 0.0;
    b.bound_radius = std::max(b.bound_radius, p.r_B.norm() + reach + p.radius);
    b.points_centroid_B += p.r_B;
  }
  if (!points.empty()) {
    b.points_centroid_B /= static_cast<double>(points.size());
    Mat3 spread = Mat3::Zero();
    for (const ContactPoint& p : points) {
      const Vec3 r = p.r_B - b.points_centroid_B;
      spread += r * r.transpose();
    }
    // Invertible only if the points span three dimensions (not coplanar).
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(spread, Eigen::EigenvaluesOnly);
    if (eig.eigenvalues()(0) > 1e-12 * std::max(1.0, eig.eigenvalues()(2))) b.points_inv_spread = spread.inverse();
  }
  b.contact_points = std::move(points);
  b.surface_friction = std::move(surfaces);
  b.round = std::move(round);
  b.rim_points = std::move(rims);
  b.extreme_x = std::move(x);
  b.extreme_y = std::move(y);
  b.extreme_z = std::move(z);
  b.extreme_radius = std::move(radius);
}

namespace {

/// The cells along a mesh's longest side in its distance grid: the grid
/// costs resolution³ × triangles to build, so big meshes get a coarser one,
/// as coarse as the work bound needs, and a mesh too big even for the
/// coarsest is refused.
int gridResolution(const CollisionShape& shape, const SolverSettings& solver, const std::string& body) {
  const double triangles = static_cast<double>(shape.mesh.triangles.size());
  const int wanted =
      triangles > solver.large_mesh_triangles ? solver.large_mesh_grid_resolution : solver.mesh_grid_resolution;
  const int resolution = SdfGrid::resolutionWithin(triangles, wanted);
  if (resolution == 0) {
    detail::fail("body '" + body + "': collision mesh '" + shape.name + "'", detail::str(triangles) + " triangles",
                 "too many for its distance grid in a world (at most " +
                     detail::str(std::floor(ranges::kMaxGridWork / std::pow(ranges::kMinGridResolution, 3))) +
                     "; simplify the mesh)");
  }
  return resolution;
}

}  // namespace

/// The body's solid in B: the union of its collision shapes, each posed by
/// X_BS; meshes as a sampled signed-distance grid.
void buildSolid(const BodySpec& spec, const SolverSettings& solver, BodyModel& b) {
  const Pose X_BL = Pose{b.q_LB, b.p_LB}.inverse();
  std::vector<Sdf> parts;
  for (const CollisionShape& shape : spec.collision) {
    const Pose X_BS = X_BL * shape.X_LS;
    switch (shape.kind) {
      case CollisionShape::Kind::kBox:
        parts.push_back(Sdf::box(shape.size).transformed(X_BS));
        break;
      case CollisionShape::Kind::kSphere:
        parts.push_back(Sdf::sphere(shape.radius).transformed(X_BS));
        break;
      case CollisionShape::Kind::kCylinder:
        parts.push_back(Sdf::cylinder(shape.radius, shape.length).transformed(X_BS));
        break;
      case CollisionShape::Kind::kCapsule:
        parts.push_back(Sdf::capsule(shape.radius, shape.length).transformed(X_BS));
        break;
      case CollisionShape::Kind::kPoints:
        if (!SdfGrid::hasArea(shape.mesh)) break;  // a point cloud (or degenerate triangles) has no inside
        parts.push_back(
            Sdf::grid(SdfGrid::fromMesh(shape.mesh, gridResolution(shape, solver, spec.name))).transformed(X_BS));
        break;
    }
  }
  if (parts.size() == 1) {
    b.solid_B = std::vector<Sdf>{parts.front()};
  } else if (!parts.empty()) {
    b.solid_B = std::vector<Sdf>{Sdf::unite(std::move(parts))};
  }
  if (!b.solid_B.empty()) {
    const auto bounds = solidBounds(b.solid_B.front());
    b.solid_lo_B = bounds ? bounds->lo : Vec3::Constant(-INFINITY);
    b.solid_hi_B = bounds ? bounds->hi : Vec3::Constant(INFINITY);
  }
}

/// Whether two bodies get the same contact points and solid: the same
/// collision shapes, placed alike, and the same mass properties (which
/// place the principal frame B the points are in).
bool sameGeometry(const BodySpec& a, const BodySpec& b) {
  if (a.p_LC != b.p_LC || a.I_C_L != b.I_C_L || a.collision.size() != b.collision.size()) return false;
  for (std::size_t i = 0; i < a.collision.size(); ++i) {
    const CollisionShape &x = a.collision[i], &y = b.collision[i];
    if (x.kind != y.kind || x.X_LS.rotation.coeffs() != y.X_LS.rotation.coeffs() ||
        x.X_LS.translation != y.X_LS.translation || x.size != y.size || x.radius != y.radius || x.length != y.length ||
        x.mesh.vertices != y.mesh.vertices || x.mesh.triangles != y.mesh.triangles || x.friction != y.friction) {
      return false;
    }
  }
  return true;
}

/// Gives `body` the contact points and solid of `twin` (built alike):
/// shared, not copied.
void shareGeometry(const BodyModel& twin, BodyModel& body) {
  body.contact_points = twin.contact_points;
  body.surface_friction = twin.surface_friction;
  body.extreme_points = twin.extreme_points;
  body.round = twin.round;
  body.rim_points = twin.rim_points;
  body.extreme_x = twin.extreme_x;
  body.extreme_y = twin.extreme_y;
  body.extreme_z = twin.extreme_z;
  body.extreme_radius = twin.extreme_radius;
  body.extreme_groups = twin.extreme_groups;
  body.solid_B = twin.solid_B;
  body.solid_lo_B = twin.solid_lo_B;
  body.solid_hi_B = twin.solid_hi_B;
  body.bound_radius = twin.bound_radius;
  body.points_centroid_B = twin.points_centroid_B;
  body.points_inv_spread = twin.points_inv_spread;
}

}  // namespace rigid_body_sim::core::detail
