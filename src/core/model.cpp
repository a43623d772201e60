#include "rigid_body_sim/core/model.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "model_checks.h"
#include "rigid_body_sim/core/inertia.h"
#include "rigid_body_sim/core/ranges.h"
#include "rigid_body_sim/core/sdf_grid.h"
#include "rigid_body_sim/core/sdf_surface.h"
#include "validate.h"

namespace rigid_body_sim::core {
namespace {

/// Orders the first `extreme` points by recursive median splits along the
/// widest axis into groups of at most `group_size`, and bounds each group by a sphere.
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
  for (const CollisionShape& shape : spec.collision) {
    ShapeSamples samples = sampleShape(shape, X_BL, contact.sample_spacing, sample_round);
    for (ContactPoint& p : samples.points) {
      if (p.round >= 0) p.round += static_cast<int>(round.size());
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
  b.round = std::move(round);
  b.rim_points = std::move(rims);
  b.extreme_x = std::move(x);
  b.extreme_y = std::move(y);
  b.extreme_z = std::move(z);
  b.extreme_radius = std::move(radius);
}

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

/// A collision shape's size and place: finite, and at most kMaxExtent.
void validateShape(const CollisionShape& shape, const std::string& where) {
  const std::string field = where + "collision '" + shape.name + "'";
  double extent = std::max({shape.size.cwiseAbs().maxCoeff(), shape.radius, shape.length});
  for (const Vec3& v : shape.mesh.vertices) extent = std::max(extent, v.cwiseAbs().maxCoeff());
  if (!std::isfinite(extent) || extent > ranges::kMaxExtent) {
    detail::fail(field, detail::str(extent) + " m",
                 "its size must be finite and at most " + detail::str(ranges::kMaxExtent) + " m");
  }
  if (!shape.X_LS.translation.allFinite() || shape.X_LS.translation.norm() > ranges::kMaxExtent) {
    detail::fail(field + " origin", detail::str(shape.X_LS.translation),
                 "must be finite and within " + detail::str(ranges::kMaxExtent) + " m of the link frame");
  }
}

BodyModel validatedBody(const BodySpec& spec) {
  const std::string where = "body '" + spec.name + "': ";
  detail::requireWithin(spec.mass, ranges::kMinMass, ranges::kMaxMass, where + "mass", "kg");
  detail::requireFinite(spec.p_LC, where + "centre of mass");
  if (spec.p_LC.norm() > ranges::kMaxExtent) {
    detail::fail(where + "centre of mass", detail::str(spec.p_LC),
                 "is more than " + detail::str(ranges::kMaxExtent) + " m from the link frame");
  }
  validateInertia(spec.I_C_L, where + "inertia");
  const Vec3 moments = principalAxes(spec.I_C_L).moments;
  if (moments.minCoeff() < ranges::kMinInertia || moments.maxCoeff() > ranges::kMaxInertia) {
    detail::fail(where + "inertia", detail::str(spec.I_C_L),
                 "principal moments " + detail::str(moments) + " must be within [" + detail::str(ranges::kMinInertia) +
                     ", " + detail::str(ranges::kMaxInertia) + "] kg*m^2");
  }
  for (const CollisionShape& shape : spec.collision) validateShape(shape, where);

  BodyModel b;
  b.name = spec.name;
  b.link = spec.link.empty() ? spec.name : spec.link;
  b.collision = spec.collision;
  b.fixed_links = spec.fixed_links;
  b.mass = spec.mass;
  b.inv_mass = 1.0 / spec.mass;
  b.p_LB = spec.p_LC;
  b.I_C_L = spec.I_C_L;
  const PrincipalAxes pa = principalAxes(spec.I_C_L);
  b.q_LB = pa.q_FP;
  b.inertia_B = pa.moments;
  b.inv_inertia_B = pa.moments.cwiseInverse();
  return b;
}

/// A body's surface: its own coefficients, or the scene's.
void resolveSurface(const BodySpec& spec, const ContactSettings& c, BodyModel& body) {
  const std::string key = "body '" + spec.name + "': contact.";
  body.friction = spec.friction.value_or(c.friction);
  body.restitution = spec.restitution.value_or(c.restitution);
  body.own_friction = spec.friction.has_value();
  body.own_restitution = spec.restitution.has_value();
  detail::requireWithin(body.friction, 0.0, ranges::kMaxFriction, key + "friction", "");
  detail::requireWithin(body.restitution, 0.0, 1.0, key + "restitution", "");
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
        x.mesh.vertices != y.mesh.vertices || x.mesh.triangles != y.mesh.triangles) {
      return false;
    }
  }
  return true;
}

/// Gives `body` the contact points and solid of `twin` (built alike):
/// shared, not copied.
void shareGeometry(const BodyModel& twin, BodyModel& body) {
  body.contact_points = twin.contact_points;
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

}  // namespace

BodyModel BodyBuilder::buildBodyLike(const BodySpec& b, const BodyModel& twin) const {
  BodyModel body = validatedBody(b);
  resolveSurface(b, contact_, body);
  shareGeometry(twin, body);
  return body;
}

BodyModel BodyBuilder::buildBody(const BodySpec& b, bool with_solid) const {
  BodyModel body = validatedBody(b);
  resolveSurface(b, contact_, body);
  buildContactPoints(b, contact_, solver_, body);
  if (with_solid) buildSolid(b, solver_, body);
  if (!scene_empty_ && body.contact_points.empty()) {
    detail::fail("body '" + b.name + "': collision", "none",
                 "contacts are on (the scene is not empty) but the body has no <collision> geometry; "
                 "add one to the URDF or set scene: []");
  }
  if (contact_.method == ContactMethod::kShapeMatching && !scene_empty_ && body.points_inv_spread.isZero(0.0)) {
    detail::fail("body '" + b.name + "': collision", std::to_string(body.contact_points.size()) + " points",
                 "shape matching needs collision points that span three dimensions");
  }
  return body;
}

Model::Model(const ModelSpec& spec)
    : dt_(spec.dt),
      gravity_W_(spec.gravity_W),
      damping_(spec.damping),
      gyroscopic_(spec.gyroscopic),
      scene_(spec.scene),
      contact_(spec.contact),
      sleep_(spec.sleep),
      solver_(spec.solver),
      limits_(spec.limits) {
  detail::requireWithin(spec.dt, ranges::kMinDt, ranges::kMaxDt, "dt", "s");
  validateGravity(spec.gravity_W);
  validateLimits(spec.limits);
  validateContact(spec.contact);
  validateSleep(spec.sleep);
  validateSolver(spec.solver);
  for (std::size_t i = 0; i < spec.bodies.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (spec.bodies[i].name == spec.bodies[j].name) {
        detail::fail("bodies[" + std::to_string(i) + "].name", "'" + spec.bodies[i].name + "'",
                     "another body has this name; names must be unique");
      }
    }
  }
  bodies_.reserve(spec.bodies.size());
  // Bodies built alike share their points and solid (a pile of equal
  // boxes keeps one copy): each is compared with the last few distinct ones.
  const BodyBuilder builder = bodyBuilder();
  constexpr std::size_t kTwinsCompared = 8;
  std::vector<std::size_t> distinct;  // indices of bodies built in full, latest last
  for (std::size_t i = 0; i < spec.bodies.size(); ++i) {
    const BodySpec& b = spec.bodies[i];
    const auto twin = std::find_if(distinct.rbegin(), distinct.rbegin() + std::min(distinct.size(), kTwinsCompared),
                                   [&](std::size_t j) { return sameGeometry(spec.bodies[j], b); });
    if (twin != distinct.rbegin() + std::min(distinct.size(), kTwinsCompared)) {
      bodies_.push_back(builder.buildBodyLike(b, bodies_[*twin]));
    } else {
      bodies_.push_back(builder.buildBody(b, spec.bodies.size() > 1));
      distinct.push_back(i);
    }
  }
  validateDamping(spec.damping, spec.dt, bodies_);
  validatePenalty(spec.contact, spec.dt, bodies_);
  validateBarrier(spec.contact, spec.limits, spec.gravity_W, bodies_);
  deriveSettings();
}

void Model::deriveSettings() {
  restitution_threshold_ = std::max(contact_.restitution_threshold, 2.0 * gravity_W_.norm() * dt_);
  linear_decay_ = std::exp(-damping_.linear_rate * dt_);
  angular_decay_ = std::exp(-damping_.angular_rate * dt_);
  max_restitution_ = contact_.restitution;
  for (BodyModel& b : bodies_) {
    if (!b.own_friction) b.friction = contact_.friction;
    if (!b.own_restitution) b.restitution = contact_.restitution;
    max_restitution_ = std::max(max_restitution_, b.restitution);
  }
}

PreparedBody BodyBuilder::build(const BodySpec& spec) const {
  PreparedBody prepared;
  prepared.body_ = buildBody(spec, true);
  return prepared;
}

Model Model::withBody(const PreparedBody& body) const {
  const std::string& name = body.body().name;
  for (const BodyModel& b : bodies_) {
    if (b.name == name) detail::fail("name", "'" + name + "'", "another body has this name; names must be unique");
  }
  Model m = *this;  // the other bodies' distance grids are shared, not copied
  m.bodies_.push_back(body.body());
  for (BodyModel& b : m.bodies_) {  // a one-body world had no solids: contact between bodies needs them
    if (b.solid_B.empty()) {
      BodySpec shapes;
      shapes.name = b.name;
      shapes.collision = b.collision;
      buildSolid(shapes, solver_, b);
    }
  }
  validateDamping(damping_, dt_, m.bodies_);
  validatePenalty(contact_, dt_, m.bodies_);
  validateBarrier(contact_, limits_, gravity_W_, m.bodies_);
  m.deriveSettings();
  return m;
}

Model Model::withoutBody(std::size_t i) const {
  if (i >= bodies_.size()) {
    detail::fail("body", std::to_string(i), "no such body (" + std::to_string(bodies_.size()) + " in the model)");
  }
  Model m = *this;
  m.bodies_.erase(m.bodies_.begin() + static_cast<std::ptrdiff_t>(i));
  m.deriveSettings();
  return m;
}

Model Model::retuned(const Tuning& t) const {
  validateGravity(t.gravity_W);
  ContactSettings contact = contact_;
  contact.friction = t.friction;
  contact.restitution = t.restitution;
  validateContact(contact);
  validateDamping(t.damping, dt_, bodies_);
  validateBarrier(contact, limits_, t.gravity_W, bodies_);
  Model m = *this;  // the bodies' distance grids are shared, not copied
  m.gravity_W_ = t.gravity_W;
  m.damping_ = t.damping;
  m.contact_ = contact;
  m.deriveSettings();
  return m;
}

}  // namespace rigid_body_sim::core
