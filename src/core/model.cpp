#include "rigid_body_sim/core/model.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "rigid_body_sim/core/inertia.h"
#include "rigid_body_sim/core/sdf_grid.h"
#include "rigid_body_sim/core/sdf_surface.h"
#include "validate.h"

namespace rigid_body_sim::core {
namespace {

/// Orders the extreme points by recursive median splits along the widest
/// axis into groups of at most `group_size`, and bounds each group by a sphere.
void groupExtremePoints(BodyModel& b, std::size_t group_size) {
  std::vector<std::pair<std::size_t, std::size_t>> todo{{0, b.extreme_points}};
  while (!todo.empty()) {
    const auto [begin, end] = todo.back();
    todo.pop_back();
    if (begin == end) continue;
    const auto first = b.contact_points.begin() + static_cast<std::ptrdiff_t>(begin);
    const auto last = b.contact_points.begin() + static_cast<std::ptrdiff_t>(end);
    if (end - begin <= group_size) {
      BodyModel::PointGroup g;
      g.begin = begin;
      g.end = end;
      for (auto it = first; it != last; ++it) g.centre_B += it->r_B;
      g.centre_B /= static_cast<double>(end - begin);
      for (auto it = first; it != last; ++it) g.radius = std::max(g.radius, (it->r_B - g.centre_B).norm() + it->radius);
      b.extreme_groups.push_back(g);
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
    std::nth_element(first, b.contact_points.begin() + static_cast<std::ptrdiff_t>(mid), last,
                     [axis](const ContactPoint& x, const ContactPoint& y) {
                       return x.r_B(axis) != y.r_B(axis) ? x.r_B(axis) < y.r_B(axis)
                                                         : std::lexicographical_compare(x.r_B.data(), x.r_B.data() + 3,
                                                                                        y.r_B.data(), y.r_B.data() + 3);
                     });
    todo.push_back({mid, end});
    todo.push_back({begin, mid});
  }
  std::sort(b.extreme_groups.begin(), b.extreme_groups.end(),
            [](const BodyModel::PointGroup& x, const BodyModel::PointGroup& y) { return x.begin < y.begin; });
}

/// Samples the body's collision shapes into contact points in B, and the
/// quantities shape matching needs.
void buildContactPoints(const BodySpec& spec, const ContactSettings& contact, const SolverSettings& solver,
                        BodyModel& b) {
  const Pose X_BL = Pose{b.q_LB, b.p_LB}.inverse();
  const bool sample_spheres = contact.method == ContactMethod::kShapeMatching;
  for (const CollisionShape& shape : spec.collision) {
    const auto points = sampleShape(shape, X_BL, contact.sample_spacing, sample_spheres);
    b.contact_points.insert(b.contact_points.end(), points.begin(), points.end());
  }
  const auto first_other = std::stable_partition(b.contact_points.begin(), b.contact_points.end(),
                                                 [](const ContactPoint& p) { return p.extreme; });
  b.extreme_points = static_cast<std::size_t>(first_other - b.contact_points.begin());
  groupExtremePoints(b, static_cast<std::size_t>(solver.point_group_size));
  for (std::size_t i = 0; i < b.extreme_points; ++i) {
    b.extreme_x.push_back(b.contact_points[i].r_B.x());
    b.extreme_y.push_back(b.contact_points[i].r_B.y());
    b.extreme_z.push_back(b.contact_points[i].r_B.z());
    b.extreme_radius.push_back(b.contact_points[i].radius);
  }
  for (const ContactPoint& p : b.contact_points) {
    b.bound_radius = std::max(b.bound_radius, p.r_B.norm() + p.radius);
    b.points_centroid_B += p.r_B;
  }
  if (b.contact_points.empty()) return;
  b.points_centroid_B /= static_cast<double>(b.contact_points.size());
  Mat3 spread = Mat3::Zero();
  for (const ContactPoint& p : b.contact_points) {
    const Vec3 r = p.r_B - b.points_centroid_B;
    spread += r * r.transpose();
  }
  // Invertible only if the points span three dimensions (not coplanar).
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(spread, Eigen::EigenvaluesOnly);
  if (eig.eigenvalues()(0) > 1e-12 * std::max(1.0, eig.eigenvalues()(2))) b.points_inv_spread = spread.inverse();
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
      case CollisionShape::Kind::kPoints:
        if (shape.mesh.triangles.empty()) break;  // a point cloud has no inside
        // The grid costs resolution³ × triangles to build: coarser for big meshes.
        parts.push_back(Sdf::grid(SdfGrid::fromMesh(shape.mesh, static_cast<int>(shape.mesh.triangles.size()) >
                                                                        solver.large_mesh_triangles
                                                                    ? solver.large_mesh_grid_resolution
                                                                    : solver.mesh_grid_resolution))
                            .transformed(X_BS));
        break;
    }
  }
  if (parts.size() == 1) {
    b.solid_B.push_back(parts.front());
  } else if (!parts.empty()) {
    b.solid_B.push_back(Sdf::unite(std::move(parts)));
  }
  if (!b.solid_B.empty()) {
    const auto bounds = solidBounds(b.solid_B.front());
    b.solid_lo_B = bounds ? bounds->lo : Vec3::Constant(-INFINITY);
    b.solid_hi_B = bounds ? bounds->hi : Vec3::Constant(INFINITY);
  }
}

BodyModel buildBody(const BodySpec& spec) {
  const std::string where = "body '" + spec.name + "': ";
  detail::requirePositive(spec.mass, where + "mass", "kg");
  detail::requireFinite(spec.p_LC, where + "centre of mass");
  validateInertia(spec.I_C_L, where + "inertia");

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

void validateDamping(const Damping& d, double dt, const std::vector<BodyModel>& bodies) {
  detail::requireNonNegative(d.linear_rate, "damping.linear", "1/s");
  detail::requireNonNegative(d.angular_rate, "damping.angular", "1/s");
  detail::requireNonNegative(d.linear_drag, "damping.linear_drag", "N*s/m");
  detail::requireNonNegative(d.angular_drag, "damping.angular_drag", "N*m*s/rad");
  // The explicit drag step v ← v (1 − σΔt/M) reverses v when σΔt/M ≥ 1.
  for (const BodyModel& b : bodies) {
    const double lin = d.linear_drag * dt * b.inv_mass;
    const double ang = d.angular_drag * dt * b.inv_inertia_B.maxCoeff();
    if (lin >= 1.0) {
      detail::fail("damping.linear_drag", detail::str(d.linear_drag),
                   "sigma*dt/mass = " + detail::str(lin) + " >= 1 for body '" + b.name +
                       "' (explicit drag would reverse the velocity; use damping.linear, a decay rate)");
    }
    if (ang >= 1.0) {
      detail::fail("damping.angular_drag", detail::str(d.angular_drag),
                   "sigma*dt/I_min = " + detail::str(ang) + " >= 1 for body '" + b.name +
                       "' (explicit drag would reverse the spin; use damping.angular, a decay rate)");
    }
  }
}

void validateContact(const ContactSettings& c) {
  if (!std::isfinite(c.restitution) || c.restitution < 0.0 || c.restitution > 1.0) {
    detail::fail("contact.restitution", detail::str(c.restitution), "must be within [0, 1]");
  }
  detail::requireNonNegative(c.friction, "contact.friction", "");
  detail::requireNonNegative(c.restitution_threshold, "contact.restitution_threshold", "m/s");
  detail::requirePositive(c.sample_spacing, "contact.sample_spacing", "m");
  if (c.iterations < 1) detail::fail("contact.iterations", std::to_string(c.iterations), "must be >= 1");
  detail::requireNonNegative(c.position_slop, "contact.position_slop", "m");
  detail::requirePositive(c.penalty_stiffness, "contact.penalty_stiffness", "N/m");
  detail::requireNonNegative(c.penalty_damping, "contact.penalty_damping", "N*s/m");
  detail::requirePositive(c.penalty_buffer, "contact.penalty_buffer", "m");
  detail::requirePositive(c.barrier_strength, "contact.barrier_strength", "N*m");
  detail::requirePositive(c.barrier_buffer, "contact.barrier_buffer", "m");
}

void validateSleep(const SleepSettings& s) {
  detail::requireNonNegative(s.linear_velocity, "sleep.linear_velocity", "m/s");
  detail::requireNonNegative(s.angular_velocity, "sleep.angular_velocity", "rad/s");
  detail::requireNonNegative(s.time, "sleep.time", "s");
}

void validateSolver(const SolverSettings& s) {
  detail::requirePositive(s.velocity_tolerance, "solver.velocity_tolerance", "m/s");
  detail::requireNonNegative(s.relative_tolerance, "solver.relative_tolerance", "");
  detail::requireNonNegative(s.resting_speed, "solver.resting_speed", "m/s");
  detail::requireNonNegative(s.rounding_speed, "solver.rounding_speed", "m/s");
  if (s.position_iterations < 0) {
    detail::fail("solver.position_iterations", std::to_string(s.position_iterations), "must be >= 0");
  }
  if (s.mesh_grid_resolution < 2 || s.large_mesh_grid_resolution < 2) {
    detail::fail("solver.mesh_grid_resolution", std::to_string(s.mesh_grid_resolution), "must be >= 2");
  }
  if (s.point_group_size < 1)
    detail::fail("solver.point_group_size", std::to_string(s.point_group_size), "must be >= 1");
}

}  // namespace

Model::Model(const ModelSpec& spec)
    : dt_(spec.dt),
      gravity_W_(spec.gravity_W),
      damping_(spec.damping),
      gyroscopic_(spec.gyroscopic),
      scene_(spec.scene),
      contact_(spec.contact),
      sleep_(spec.sleep),
      solver_(spec.solver) {
  if (spec.bodies.empty()) detail::fail("bodies", "[]", "the model needs at least one body");
  detail::requirePositive(spec.dt, "dt", "s");
  detail::requireFinite(spec.gravity_W, "gravity");
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
  for (const BodySpec& b : spec.bodies) {
    bodies_.push_back(buildBody(b));
    BodyModel& body = bodies_.back();
    buildContactPoints(b, spec.contact, spec.solver, body);
    if (spec.bodies.size() > 1) buildSolid(b, spec.solver, body);
    if (!scene_.empty() && body.contact_points.empty()) {
      detail::fail("body '" + b.name + "': collision", "none",
                   "contacts are on (the scene is not empty) but the body has no <collision> geometry; "
                   "add one to the URDF or set scene: []");
    }
    if (spec.contact.method == ContactMethod::kShapeMatching && !scene_.empty() && body.points_inv_spread.isZero(0.0)) {
      detail::fail("body '" + b.name + "': collision", std::to_string(body.contact_points.size()) + " points",
                   "shape matching needs collision points that span three dimensions");
    }
  }
  restitution_threshold_ = std::max(spec.contact.restitution_threshold, 2.0 * gravity_W_.norm() * dt_);
  validateDamping(spec.damping, spec.dt, bodies_);
  linear_decay_ = std::exp(-spec.damping.linear_rate * spec.dt);
  angular_decay_ = std::exp(-spec.damping.angular_rate * spec.dt);
}

}  // namespace rigid_body_sim::core
