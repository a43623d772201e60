// The model: everything that does not change while the simulation runs.
//
// Following MuJoCo's mjModel/mjData split, a Model is built once from a
// ModelSpec (creation settings, as Jolt's BodyCreationSettings), validated on
// construction, and never modified; step() takes it by const reference.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/collision.h"
#include "rigid_body_sim/core/bodies/sdf.h"
#include "rigid_body_sim/core/bodies/settings.h"
#include "rigid_body_sim/core/bodies/shared_array.h"
#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

/// A link joined to the body by a fixed joint: a frame users see (tf), not a
/// separate body.
struct FixedLink {
  std::string name;    ///< its URDF link name
  std::string parent;  ///< the link it hangs from (the root link or another fixed link)
  Pose X_PK;           ///< its pose in the parent link's frame (the joint's origin)
};

/// Creation settings of one rigid body (what a URDF provides).
struct BodySpec {
  std::string name = "body";  ///< the body's name in the world (by default its URDF root link's)
  std::string link = "";      ///< its URDF root link name ("" = name): the frame users see
  double mass = 1.0;          ///< kg
  Vec3 p_LC = Vec3::Zero();   ///< centre of mass in the link frame L (m)
  /// Inertia about the centre of mass, axes of L (kg·m²).
  Mat3 I_C_L = Mat3::Identity();
  std::vector<CollisionShape> collision;  ///< the URDF <collision> elements
  std::vector<FixedLink> fixed_links;     ///< links lumped into the body, in URDF order
  /// Its surface (config bodies[i].contact); unset: the scene's,
  /// contact.friction and contact.restitution.
  std::optional<double> friction, restitution;
  /// Bodies of one group (≥ 0) never touch each other: the links of one
  /// articulation, whose self-collision is off (docs/physics.md §11.8). −1: none.
  int collision_group = -1;
};

/// Gives the whole body the friction `mu` (a config entry's, a spawn's):
/// its shapes' own surfaces (lumped links') give way to it.
void setBodyFriction(BodySpec& spec, double mu);

/// Creation settings of the whole model.
struct ModelSpec {
  std::vector<BodySpec> bodies;
  double dt = 1e-3;                        ///< time step Δt (s)
  Vec3 gravity_W = Vec3(0.0, 0.0, -9.81);  ///< m/s², world frame
  Damping damping;
  /// Integrate the gyroscopic term −ω × (I ω) of Euler's equation. Off
  /// integrates ω_{n+1} = ω_n + Δt I⁻¹ τ alone (docs/physics.md §5.6), which is only
  /// right for bodies with isotropic inertia (spheres, cubes).
  bool gyroscopic = true;
  /// The articulations' integrator (§11.5).
  ArticulationIntegrator articulation_integrator = ArticulationIntegrator::kVerlet;
  /// Static geometry the bodies collide with; empty means no contacts.
  /// (The config's default is the ground plane z = 0.)
  std::vector<Sdf> scene;
  ContactSettings contact;
  SleepSettings sleep;
  SolverSettings solver;
  SpeedLimits limits;
};

/// One body as the integrator uses it: derived and validated quantities.
/// What the step reads comes first, grouped by the cache line it shares
/// with what is read with it, and each body starts on a line: at N = 10,000
/// the bodies' models outgrow the L2 cache, and a stage's cost per body is
/// the lines it touches (bench/HISTORY.md).
struct alignas(64) BodyModel {
  // The solve and the integrator.
  double inv_mass = 1.0;              ///< 1/kg
  Vec3 inv_inertia_B = Vec3::Ones();  ///< 1/(kg·m²)
  double friction = 0.5;              ///< its surface's μ_T (its own, or the scene's)
  double restitution = 0.0;           ///< its surface's μ_N (its own, or the scene's)
  double bound_radius = 0.0;          ///< m: every contact point lies within it of the centre of mass
  double mass = 1.0;                  ///< kg
  // What other bodies' points meet.
  /// The body's solid in B (the union of its collision shapes), which other
  /// bodies' points are tested against; only built when there are several bodies
  /// (a mesh's distance grid costs time at start).
  SharedArray<Sdf> solid_B;
  Vec3 solid_lo_B = Vec3::Zero(), solid_hi_B = Vec3::Zero();  ///< a box around solid_B, in B (m)
  // Its own points.
  SharedArray<ContactPoint> contact_points;            ///< collision samples, body frame B, extreme ones first
  SharedArray<RoundFeature> round;                     ///< the round features contact points refer to (B)
  SharedArray<int> rim_points;                         ///< the contact points on rims, which a plane tests too
  std::size_t extreme_points = 0;                      ///< how many of contact_points are extreme (see ContactPoint)
  bool own_friction = false, own_restitution = false;  ///< its own (BodySpec), not the scene's
  /// The extreme points again as columns (x, y, z, radius), so the plane
  /// test over a large mesh runs as vector arithmetic.
  SharedArray<double> extreme_x, extreme_y, extreme_z, extreme_radius;
  /// The extreme points, ordered so that each group of at most 32 is
  /// spatially compact (a median split), with a bounding sphere per group:
  /// a plane far from a group's sphere skips its points.
  struct PointGroup {
    std::size_t begin = 0, end = 0;  ///< range in contact_points
    Vec3 centre_B = Vec3::Zero();    ///< m
    double radius = 0.0;             ///< m, includes the points' own radii
  };
  SharedArray<PointGroup> extreme_groups;
  Vec3 inertia_B = Vec3::Ones();  ///< principal moments, kg·m²
  // Read at the start, for frames and drawing.
  std::string name;                       ///< the body's name in the world
  std::string link;                       ///< its URDF root link name
  Vec3 p_LB = Vec3::Zero();               ///< B's origin (the centre of mass) in L (m)
  Quat q_LB = Quat::Identity();           ///< principal axes B in L
  Mat3 I_C_L = Mat3::Identity();          ///< inertia about the centre of mass in L axes, as given
  std::vector<CollisionShape> collision;  ///< the collision shapes in L, as given (for drawing)
  /// The μ_T of the shapes with a surface of their own, which their contact
  /// points name (ContactPoint::surface); empty when none has.
  SharedArray<double> surface_friction;
  std::vector<FixedLink> fixed_links;  ///< frames fixed to the body (for tf)
  int collision_group = -1;            ///< BodySpec::collision_group
  /// Shape matching: the mean of the contact points (B) and (Σ r̄ r̄ᵀ)⁻¹ of
  /// the points about it; empty when the points do not span three dimensions.
  Vec3 points_centroid_B = Vec3::Zero();
  Mat3 points_inv_spread = Mat3::Zero();
};

/// The pose X_LK of `link` in the body's root link frame L: the root link
/// itself ("" too: the identity), or a link fixed to it, through its chain
/// of fixed joints (where an IMU is mounted); nullopt for any other name.
std::optional<Pose> linkPose(const BodyModel& body, const std::string& link);

/// The settings that may change between steps without rebuilding the
/// bodies (the node's dynamic_reconfigure server, ~physics).
struct Tuning {
  Vec3 gravity_W = Vec3(0.0, 0.0, -9.81);  ///< m/s²
  Damping damping;
  double friction = 0.5;     ///< the scene's surface, and every body's without its own
  double restitution = 0.0;  ///< likewise
};

class Model;

/// A body built for a model but not yet in it: what Model::withBody adds.
/// Only a BodyBuilder makes one.
class PreparedBody {
 public:
  const BodyModel& body() const { return body_; }

 private:
  friend class BodyBuilder;
  friend class Model;
  BodyModel body_;
};

/// Builds bodies as a model builds them: validates a spec and derives its
/// principal axes, contact points and solid (a mesh's distance grid: the
/// slow part of adding a body, seconds for a big mesh). It holds copies of
/// the settings it reads, which no edit of the model changes (retuned()
/// changes only surfaces, and withBody() sets those again), so a caller
/// may build on another thread while the model steps.
class BodyBuilder {
 public:
  /// Throws std::invalid_argument whose message names the field and value.
  PreparedBody build(const BodySpec& spec) const;

 private:
  friend class Model;
  BodyBuilder(const ContactSettings& contact, const SolverSettings& solver, bool scene_empty)
      : contact_(contact), solver_(solver), scene_empty_(scene_empty) {}
  /// The body, with its solid (for other bodies' points) if `with_solid`.
  BodyModel buildBody(const BodySpec& spec, bool with_solid) const;
  /// The body, sharing the points and solid of `twin`, built from a spec of
  /// the same geometry (shapes and mass properties).
  BodyModel buildBodyLike(const BodySpec& spec, const BodyModel& twin) const;
  ContactSettings contact_;
  SolverSettings solver_;
  bool scene_empty_;
};

class Model {
 public:
  /// Validates `spec` and derives the principal-axes form of every body; a
  /// model may have no bodies (an empty world, to add them to later).
  /// Throws std::invalid_argument whose message names the field and value.
  explicit Model(const ModelSpec& spec);

  const std::vector<BodyModel>& bodies() const { return bodies_; }
  const BodyModel& body(std::size_t i) const { return bodies_.at(i); }
  std::size_t bodyCount() const { return bodies_.size(); }
  double dt() const { return dt_; }
  const Vec3& gravity() const { return gravity_W_; }
  const Damping& damping() const { return damping_; }
  bool gyroscopic() const { return gyroscopic_; }
  ArticulationIntegrator articulationIntegrator() const { return articulation_integrator_; }
  const std::vector<Sdf>& scene() const { return scene_; }
  const ContactSettings& contact() const { return contact_; }
  const SleepSettings& sleep() const { return sleep_; }
  const SolverSettings& solver() const { return solver_; }
  const SpeedLimits& limits() const { return limits_; }
  Tuning tuning() const { return {gravity_W_, damping_, contact_.friction, contact_.restitution}; }
  /// This model with `t`'s settings, validated as the constructor validates
  /// a spec (std::invalid_argument naming the key); this one is unchanged.
  Model retuned(const Tuning& t) const;
  /// This model with one more body, last, built and validated as the
  /// constructor builds one (its name must be new); this one is unchanged.
  /// The other bodies keep their index. Pair it with a new BodyState, and
  /// step an edited model with a fresh Workspace (its caches assume the old one).
  Model withBody(const BodySpec& spec) const { return withBody(bodyBuilder().build(spec)); }
  /// The same with a body built beforehand by bodyBuilder() of this model or
  /// of one it was edited from. What is left is quick: the checks that
  /// involve the other bodies, and the solid of a one-body world's body.
  Model withBody(const PreparedBody& body) const;
  /// What builds bodies for this model (and for those edited from it).
  BodyBuilder bodyBuilder() const { return BodyBuilder(contact_, solver_, scene_.empty()); }
  /// This model without body i (the later ones move down by one); it may
  /// leave no body at all. Pair it with removeBody() on the state.
  Model withoutBody(std::size_t i) const;
  /// withBody() and withoutBody() on this model, in place: an edit between
  /// two steps copies none of the other bodies (the node's spawns and
  /// deletes, issue 32). addBody() leaves the model as it was when it
  /// throws. Step an edited model with Workspace::forEditedModel().
  void addBody(const PreparedBody& body) { insertBody(bodies_.size(), body); }
  /// addBody() at index i ≤ bodyCount(): the bodies from i on move up by
  /// one (a scene's free body goes before the robots' links).
  void insertBody(std::size_t i, const PreparedBody& body);
  void removeBody(std::size_t i);
  /// The coefficients of a contact between `body` and `other` (< 0: the
  /// scene), by the contact settings' combine rules.
  double friction(int body, int other) const {
    return combine(contact_.friction_combine, bodies_[body].friction,
                   other < 0 ? contact_.friction : bodies_[other].friction);
  }
  /// friction(body, other) for `body`'s contact point `point` (ContactKey's):
  /// its shape's own surface when it has one (a lumped link's), else the
  /// body's (a box pair's own points, point < 0, too).
  double friction(int body, int point, int other) const {
    const BodyModel& b = bodies_[body];
    const std::uint8_t s = point >= 0 ? b.contact_points[static_cast<std::size_t>(point)].surface : 0;
    return combine(contact_.friction_combine, s == 0 ? b.friction : b.surface_friction[s - 1u],
                   other < 0 ? contact_.friction : bodies_[other].friction);
  }
  double restitution(int body, int other) const {
    return combine(contact_.restitution_combine, bodies_[body].restitution,
                   other < 0 ? contact_.restitution : bodies_[other].restitution);
  }
  /// Whether any contact can bounce (some pair's restitution > 0).
  bool bounces() const { return max_restitution_ > 0.0; }
  /// The largest restitution any pair can have (the largest of the surfaces').
  double maxRestitution() const { return max_restitution_; }
  /// max(restitution_threshold, 2 |g| Δt), m/s.
  double restitutionThreshold() const { return restitution_threshold_; }
  /// Per-step decay factors α = e^(−k Δt) of the damping rates.
  /// Whether some bodies share a collision group (the broad phase then looks).
  bool hasCollisionGroups() const { return grouped_; }
  double linearDecay() const { return linear_decay_; }
  double angularDecay() const { return angular_decay_; }

 private:
  std::vector<BodyModel> bodies_;
  double dt_;
  Vec3 gravity_W_;
  Damping damping_;
  bool gyroscopic_;
  ArticulationIntegrator articulation_integrator_;
  std::vector<Sdf> scene_;
  ContactSettings contact_;
  SleepSettings sleep_;
  SolverSettings solver_;
  SpeedLimits limits_;
  /// What follows from the settings: the restitution threshold, the decay
  /// factors, every body's surface that is the scene's, whether anything bounces,
  /// whether any body has a collision group.
  void deriveSettings();

  double restitution_threshold_;
  double max_restitution_ = 0.0;
  bool grouped_ = false;
  double linear_decay_;
  double angular_decay_;
};

}  // namespace rigid_body_sim::core
