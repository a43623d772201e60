// Every setting of the simulation, with its unit, in one place (as Jolt's
// PhysicsSettings): what a config file sets (damping, contact, sleep, the
// solver's tolerances, the speed limits) and the numerical constants of each
// stage. A field is named as the last part of its config key
// (config/default.yaml: `contact.friction` is ContactSettings::friction);
// setting_keys.h lists the keys with their one range each. The fields below
// say which have no key.
#pragma once

#include <cmath>

namespace rigid_body_sim::core {

/// Velocity damping. Two forms, which add up:
///  - a decay rate k (1/s): v ← v·exp(−k Δt) each step, so v(t) = v₀ e^(−k t)
///    whatever Δt is (docs/physics.md §5.4);
///  - a drag force f = −σ v (and τ = −σ_ω ω), integrated explicitly
///    like every other force, so its effect depends on Δt.
struct Damping {
  double linear = 0.0;        ///< 1/s
  double angular = 0.0;       ///< 1/s
  double linear_drag = 0.0;   ///< σ, N·s/m
  double angular_drag = 0.0;  ///< σ_ω, N·m·s/rad
};

/// How contacts are resolved (docs/physics.md §5.5 and §7).
enum class ContactMethod {
  kImpulse,            ///< velocity impulses J = K⁻¹Δv per contact, Coulomb friction (default)
  kPenaltyQuadratic,   ///< f = k (ε − φ) N inside the buffer ε, plus damping
  kPenaltyLogBarrier,  ///< f = ρ (1/φ − 1/ε) N inside ε; the step shrinks so φ stays > 0
  kShapeMatching,      ///< per-vertex update with collision and friction, then rigidify
};

/// How a contact's coefficient comes from its two surfaces' (a body's own,
/// or the scene's: contact.friction and contact.restitution), as each engine
/// chooses: ODE and Gazebo take the smaller friction, Bullet multiplies both,
/// Box2D and Jolt take the geometric mean of frictions and the larger restitution.
enum class CombineRule {
  kMin,        ///< min(a, b)
  kMax,        ///< max(a, b)
  kAverage,    ///< (a + b) / 2
  kMultiply,   ///< a b
  kGeometric,  ///< √(a b)
};

/// The rule applied to two coefficients.
inline double combine(CombineRule rule, double a, double b) {
  switch (rule) {
    case CombineRule::kMin:
      return a < b ? a : b;
    case CombineRule::kMax:
      return a > b ? a : b;
    case CombineRule::kAverage:
      return 0.5 * (a + b);
    case CombineRule::kMultiply:
      return a * b;
    case CombineRule::kGeometric:
      return std::sqrt(a * b);
  }
  return a;
}

/// How an articulation's joints and floating base are integrated
/// (docs/physics.md §11.5).
enum class ArticulationIntegrator {
  /// Second order: velocity Verlet, its velocity the step's (at the middle
  /// of the step), the Coriolis terms at the velocity of the step's start.
  kVerlet,
  /// First order, symplectic: Euler on the joints' momenta, implicit in
  /// the velocity through ∂T/∂q (this project's step before the Verlet one).
  kSymplecticEuler,
};

struct ContactSettings {
  ContactMethod method = ContactMethod::kImpulse;
  /// The scene's surface, and every body's without its own (BodySpec).
  double restitution = 0.0;  ///< μ_N ∈ [0, 1]
  double friction = 0.5;     ///< μ_T (Coulomb) ≥ 0
  /// How a pair's coefficients combine: the smaller friction, as ODE and
  /// Gazebo; the larger restitution, as Box2D and Jolt (a ball bounces off
  /// concrete as it would off itself).
  CombineRule friction_combine = CombineRule::kMin;
  CombineRule restitution_combine = CombineRule::kMax;
  /// Restitution applies only above this approach speed (m/s), so a resting
  /// body does not jitter; never below 2|g|Δt (docs/physics.md §5.5), whatever is set.
  double restitution_threshold = 0.1;
  double sample_spacing = 0.1;     ///< m between collision samples on boxes and cylinders
  int iterations = 50;             ///< impulse solver: most Gauss-Seidel sweeps per step (a stack needs them)
  double position_slop = 1e-4;     ///< m of penetration left alone by the position correction
  double penalty_stiffness = 1e4;  ///< k, N/m per contact point
  double penalty_damping = 50.0;   ///< N·s/m per contact point (both penalty methods)
  double penalty_buffer = 0.005;   ///< ε, m
  double barrier_strength = 0.01;  ///< ρ, N·m per contact point
  double barrier_buffer = 0.005;   ///< ε, m
  /// A robot's links touch each other (those joined by a joint never do);
  /// off, as Gazebo's default (docs/physics.md §11.8).
  bool self_collision = false;
};

/// A body whose speed stays below these for `time` while in contact falls
/// asleep: it is not integrated, so it stays exactly where it is, until a
/// load, an impulse or a new state wakes it.
struct SleepSettings {
  bool enabled = true;
  double linear_velocity = 0.01;   ///< m/s
  double angular_velocity = 0.05;  ///< rad/s
  double time = 0.5;               ///< s
};

/// The fastest a body may move, as Jolt's mMaxLinearVelocity and
/// mMaxAngularVelocity and PhysX's maxAngularVelocity: a velocity beyond
/// them is scaled back to them wherever loads and contacts change it
/// (docs/physics.md §5.9), and the step reports the body (Workspace::speed_limited).
/// Without them an accepted load (1e12 N·m through a lever) spins a body to
/// overflow. Jolt's defaults are 500 m/s and about 47 rad/s, Unity's PhysX
/// 50 rad/s; 100 rad/s here lets a 0.1 m wheel roll at 10 m/s. Config keys
/// limits.max_linear_speed and limits.max_angular_speed, each in (0, 1e4].
struct SpeedLimits {
  double max_linear_speed = 500.0;   ///< m/s
  double max_angular_speed = 100.0;  ///< rad/s
};

/// The numerical constants of the stages: tolerances, iteration limits and
/// thresholds. The defaults are what the tests and benchmarks were measured
/// with (docs/physics.md says why each is what it is); the config sets those
/// with a key (`solver.KEY`), the others are fixed here.
struct SolverSettings {
  // -- impulse solve (docs/physics.md §5.5)
  /// m/s: sweeps stop once none changes a contact velocity by more than this
  /// (1e-10 m of drift a step: what a resting stack needs). Key velocity_tolerance.
  double velocity_tolerance = 1e-7;
  /// In a moving island, sweeps also stop below this fraction of the fastest
  /// contact's speed (a relative residual). Key relative_tolerance.
  double relative_tolerance = 1e-6;
  /// Stall rule: from this sweep on, the solve stops when a sweep takes off
  /// more than `stall_ratio` of what the sweep four before took (friction
  /// whose limit moves with the normal impulse can cycle instead of converging).
  int stall_min_sweeps = 8;
  double stall_ratio = 0.9;
  /// An island of one awake body whose contacts are stiffer in rotation than
  /// along their normals by more than this ratio (λ_max(I⁻¹) |r|² against
  /// 1/m; a uniform box is 3–13, a 200 kg box with I = 0.01 kg m² 3,000)
  /// solves its normal impulses together, exactly, before each sweep
  /// (stiff_body.cpp): one contact at a time, Gauss-Seidel would barely move
  /// its centre, and it would sink.
  double stiff_body_ratio = 100.0;
  /// m/s: a contact off by less than this holds to rounding and gets no
  /// impulse (about 1e-18 m/s is the rounding of impulses holding h g).
  double rounding_speed = 1e-15;
  /// m/s and rad/s: a body the solve leaves slower than this ends at exactly
  /// zero, so it rests exactly (3e-5 m a year). Key resting_speed.
  double resting_speed = 1e-12;
  /// Friction on the Coulomb disk: Newton iterations on the secular
  /// equation, their relative tolerance on |λ_T|, and the relative gap
  /// between TᵀKT's eigenvalues below which it counts as isotropic.
  int friction_newton_iterations = 30;
  double friction_newton_tolerance = 1e-10;
  double isotropy_tolerance = 1e-12;

  // -- the solve of the islands that hold a robot (§11.9), in joint space
  /// Its sweeps stop once none changes a velocity by more than this
  /// fraction of the fastest coordinate (rad/s or m/s, taken as at least
  /// 1), at most `joint_space_sweeps` of them, or when they stall (the rule
  /// above, below velocity_tolerance). Tighter than the free bodies': the
  /// robots' closed forms hold to 1e-9 m/s (scene_test); a box behaves
  /// alike pushed by a robot or by a body to velocity_tolerance.
  /// The same two stop the position lift of those islands (§11.9; absolute
  /// there, m/s of lift).
  double joint_space_tolerance = 1e-12;
  int joint_space_sweeps = 200;

  // -- a robot's integrators (§11.5): constants, not settings (the energy
  // figures and closed forms of articulation_test were measured with them;
  // no robot needs others)
  /// The symplectic corrector's fixed-point passes: at most this many, each
  /// at least halving the change of the last, to this tolerance relative to
  /// the fastest coordinate; else the prediction stands. Where the passes
  /// stall at the solve's rounding, a change below the looser tolerance
  /// counts as converged.
  static constexpr int kCorrectorPasses = 8;
  static constexpr double kCorrectorContraction = 0.5;
  static constexpr double kCorrectorTolerance = 1e-12;
  static constexpr double kCorrectorRounding = 1e-9;
  /// After a step whose passes did not contract, this many steps go straight
  /// to the prediction (a long, light chain rarely contracts: the passes
  /// would double its step's cost for nothing).
  static constexpr int kPredictOnlySteps = 3;
  /// The Verlet step's passes from its extrapolated prediction: none is
  /// second order but lets the energy drift (a double pendulum's by 4.4e-4
  /// m g l over 200 s), one holds it (2.4e-5), three reach the symmetric
  /// solution (4.6e-6) at half again the cost.
  static constexpr int kVerletPasses = 1;
  /// A floating base's Verlet twist: rounds to find the middle of the move,
  /// and their tolerance relative to the fastest coordinate.
  static constexpr int kMiddleRounds = 8;
  static constexpr double kMiddleTolerance = 1e-15;

  // -- position correction (§5.8)
  /// Gauss-Seidel sweeps on positions. Key position_iterations.
  int position_iterations = 4;
  /// An island is corrected when a contact is predicted to end deeper than
  /// this fraction of contact.position_slop (the prediction is linear).
  double correction_trigger = 0.5;

  // -- detection (§5.1)
  /// m: the smallest speculative margin, so resting contacts persist.
  double min_margin = 1e-4;
  /// Contacts of one item whose normals are within this cosine (about 20°)
  /// form one region, reduced to four points.
  double region_cos = 0.94;
  /// The reduction's near-ties: m of depth and of distance, and relative;
  /// ties go to the lowest point index, so the same points are kept from
  /// step to step (warm starting needs it).
  double reduction_tie_depth = 1e-9;
  double reduction_tie_distance2 = 1e-18;  ///< m²
  double reduction_tie_relative = 1e-9;

  // -- detection's fixed choices (§5.1): constants, not settings (no scene
  // needs others, and the hot loops read them as immediates)
  /// A face point's contact with another body counts only if the solid's
  /// normal there is within 30° of the face's own, reversed (cos 30°).
  static constexpr double kFaceContactCos = 0.8660254037844387;
  /// Two boxes: how much less a later axis must overlap than the best so far
  /// to replace it, relative to the best's magnitude (the other box's faces
  /// 2 %, an edge pair 5 %, as ODE's box-box test prefers faces), and in
  /// absolute terms (m) for overlaps near zero; so one axis is kept from step
  /// to step where two nearly tie, and the solver warm-starts.
  static constexpr double kBoxFaceMargin = 0.02;
  static constexpr double kBoxEdgeMargin = 0.05;
  static constexpr double kBoxAbsoluteMargin = 1e-6;  ///< m
  /// Box edges closer to parallel than this |a × b| (unit edges) give no
  /// axis: the faces already cover them.
  static constexpr double kBoxParallelSine = 1e-3;
  /// Round features: below this |n × a| a rim counts as flat on the surface
  /// (level within ρ × 1e-9 m), and its first point goes to a fixed
  /// direction, so a cylinder standing on its cap keeps its three points.
  static constexpr double kFlatRim = 1e-9;
  /// A slope ∇φ · a along a cylinder's side or a capsule's segment below
  /// this counts as level (1 mm per metre), so a body lying across a beam
  /// rests on both its edges instead of rocking between them.
  static constexpr double kLevelSlope = 1e-3;
  /// m: the bisection for where such a line is level stops below this.
  static constexpr double kLevelLength = 1e-12;
  /// m: a deleted body wakes the bodies within its bound radius plus this.
  static constexpr double kWakeReach = 0.01;

  // -- gyroscopic rotation (§5.6)
  /// Fixed-point passes of the implicit midpoint rule, their tolerance on
  /// |Δu|²/|u|² (1e-12 relative), and the most sub-steps when it cannot
  /// contract. Constants, not settings: the hottest loop of a one-body step
  /// runs them, and a compile-time trip count saves 4% of its instructions
  /// (bench/HISTORY.md); no scene needs others (the sub-steps keep it exact).
  static constexpr int kGyroscopicIterations = 40;
  static constexpr double kGyroscopicTolerance2 = 1e-24;
  static constexpr int kGyroscopicMaxSubsteps = 1 << 16;

  // -- penalty and barrier responses (§7)
  /// m: the log barrier is evaluated no closer than this (ρ/φ stays finite).
  static constexpr double kBarrierFloor = 1e-9;
  /// Log barrier: the relative mismatch between the end separations a pass
  /// assumed and where it ended above which the step is halved.
  static constexpr double kBarrierSettle = 0.01;
  /// m/s: penalty friction is viscous below this slip (regularised Coulomb).
  double stiction_speed = 1e-3;
  /// Log barrier: a step is taken again as two halves when φ would shrink or
  /// grow by more than this factor, at most `barrier_max_halvings` times.
  double barrier_step_factor = 2.0;
  int barrier_max_halvings = 20;
  /// Log barrier: passes after the first that take each contact's force as
  /// the exact work of its potential to where the last pass ended.
  int barrier_passes = 2;

  // -- shape matching (§7.3)
  /// Passes projecting the fitted pose's penetrating vertices out and fitting again.
  int shape_matching_passes = 10;

  // -- the model (collision geometry)
  /// Extreme points per group with a bounding sphere (the plane test skips whole groups).
  int point_group_size = 32;
  /// Cells along a mesh's longest side in its signed-distance grid; meshes
  /// of more than `large_mesh_triangles` triangles get the coarser grid.
  /// Key mesh_grid_resolution (the fine one).
  int mesh_grid_resolution = 32;
  int large_mesh_grid_resolution = 20;
  int large_mesh_triangles = 2000;
};

}  // namespace rigid_body_sim::core
