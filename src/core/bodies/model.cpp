#include "rigid_body_sim/core/bodies/model.h"

#include <algorithm>
#include <cmath>

#include "body_geometry.h"
#include "model_checks.h"
#include "rigid_body_sim/core/bodies/inertia.h"
#include "rigid_body_sim/core/bodies/ranges.h"
#include "validate.h"

namespace rigid_body_sim::core {
void setBodyFriction(BodySpec& spec, double mu) {
  spec.friction = mu;
  for (CollisionShape& shape : spec.collision) shape.friction.reset();
}

namespace {

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
  b.collision_group = spec.collision_group;
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

}  // namespace

BodyModel BodyBuilder::buildBodyLike(const BodySpec& b, const BodyModel& twin) const {
  BodyModel body = validatedBody(b);
  resolveSurface(b, contact_, body);
  detail::shareGeometry(twin, body);
  return body;
}

BodyModel BodyBuilder::buildBody(const BodySpec& b, bool with_solid) const {
  BodyModel body = validatedBody(b);
  resolveSurface(b, contact_, body);
  detail::buildContactPoints(b, contact_, solver_, body);
  if (with_solid) detail::buildSolid(b, solver_, body);
  // A body without <collision> is kept, as Gazebo keeps it: it touches
  // nothing (io::touchesNothing says so to the user).
  if (contact_.method == ContactMethod::kShapeMatching && !scene_empty_ && !body.contact_points.empty() &&
      body.points_inv_spread.isZero(0.0)) {
    detail::fail("body '" + b.name + "': collision", std::to_string(body.contact_points.size()) + " points",
                 "shape matching needs collision points that span three dimensions");
  }
  return body;
}

std::optional<Pose> linkPose(const BodyModel& body, const std::string& link) {
  Pose X_LK;
  std::string at = link;
  for (std::size_t hops = 0; !at.empty() && at != body.link; ++hops) {
    const auto f = std::find_if(body.fixed_links.begin(), body.fixed_links.end(),
                                [&](const FixedLink& l) { return l.name == at; });
    if (f == body.fixed_links.end() || hops > body.fixed_links.size()) return std::nullopt;
    X_LK = f->X_PK * X_LK;  // climb toward the root
    at = f->parent;
  }
  return X_LK;
}

Model::Model(const ModelSpec& spec)
    : dt_(spec.dt),
      gravity_W_(spec.gravity_W),
      damping_(spec.damping),
      gyroscopic_(spec.gyroscopic),
      articulation_integrator_(spec.articulation_integrator),
      scene_(spec.scene),
      contact_(spec.contact),
      sleep_(spec.sleep),
      solver_(spec.solver),
      limits_(spec.limits) {
  validateSettings(spec);
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
                                   [&](std::size_t j) { return detail::sameGeometry(spec.bodies[j], b); });
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
  linear_decay_ = std::exp(-damping_.linear * dt_);
  angular_decay_ = std::exp(-damping_.angular * dt_);
  max_restitution_ = contact_.restitution;
  grouped_ = false;
  for (BodyModel& b : bodies_) {
    grouped_ = grouped_ || b.collision_group >= 0;
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
  Model m = *this;  // the other bodies' distance grids are shared, not copied
  m.addBody(body);
  return m;
}

Model Model::withoutBody(std::size_t i) const {
  Model m = *this;
  m.removeBody(i);
  return m;
}

void Model::insertBody(std::size_t i, const PreparedBody& body) {
  const std::string& name = body.body().name;
  if (i > bodies_.size()) {
    detail::fail("body", std::to_string(i), "past the last body (" + std::to_string(bodies_.size()) + " in the model)");
  }
  for (const BodyModel& b : bodies_) {
    if (b.name == name) detail::fail("name", "'" + name + "'", "another body has this name; names must be unique");
  }
  const auto at = bodies_.begin() + static_cast<std::ptrdiff_t>(i);
  bodies_.insert(at, body.body());
  try {
    for (BodyModel& b : bodies_) {  // a one-body world had no solids: contact between bodies needs them
      if (b.solid_B.empty()) {
        BodySpec shapes;
        shapes.name = b.name;
        shapes.collision = b.collision;
        detail::buildSolid(shapes, solver_, b);
      }
    }
    validateDamping(damping_, dt_, bodies_);
    validatePenalty(contact_, dt_, bodies_);
    validateBarrier(contact_, limits_, gravity_W_, bodies_);
  } catch (...) {
    // Unchanged but for the solids built above, which only bodies use.
    bodies_.erase(bodies_.begin() + static_cast<std::ptrdiff_t>(i));
    deriveSettings();
    throw;
  }
  deriveSettings();
}

void Model::removeBody(std::size_t i) {
  if (i >= bodies_.size()) {
    detail::fail("body", std::to_string(i), "no such body (" + std::to_string(bodies_.size()) + " in the model)");
  }
  bodies_.erase(bodies_.begin() + static_cast<std::ptrdiff_t>(i));
  deriveSettings();
}

Model Model::retuned(const Tuning& t) const {
  ModelSpec spec;  // the settings in force, with the tuning's
  spec.dt = dt_;
  spec.gyroscopic = gyroscopic_;
  spec.articulation_integrator = articulation_integrator_;
  spec.contact = contact_;
  spec.sleep = sleep_;
  spec.solver = solver_;
  spec.limits = limits_;
  spec.gravity_W = t.gravity_W;
  spec.damping = t.damping;
  spec.contact.friction = t.friction;
  spec.contact.restitution = t.restitution;
  validateSettings(spec);
  const ContactSettings& contact = spec.contact;
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
