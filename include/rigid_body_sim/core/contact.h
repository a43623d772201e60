// Contacts with the static scene and between bodies: detection by signed
// distance (detection.cpp), and the responses of docs/physics.md: impulses and the
// position correction (contact_solver.cpp), penalties (penalty.cpp). Also
// the step's scratch memory (Workspace). Shape matching is in
// shape_matching.h.
#pragma once

#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "rigid_body_sim/core/loads.h"
#include "rigid_body_sim/core/model.h"
#include "rigid_body_sim/core/parallel.h"
#include "rigid_body_sim/core/state.h"
#include "rigid_body_sim/core/types.h"

namespace rigid_body_sim::core {

/// One contact point of a body against a scene item or another body: the
/// point is one of `body`'s contact points, tested against the signed
/// distance of the item or of the other body's solid.
struct Contact {
  int body = 0;                   ///< index in the model
  int other = -1;                 ///< the other body, or -1 for a scene item
  int item = -1;                  ///< index in model.scene(), or -1 for a body
  int point = 0;                  ///< index in `body`'s contact points
  Vec3 normal_W = Vec3::UnitZ();  ///< unit, out of the item (or other body) toward `body` (∇φ)
  Vec3 r_W = Vec3::Zero();        ///< contact point relative to `body`'s centre of mass, world axes (m)
  Vec3 r_other_W = Vec3::Zero();  ///< the same point relative to the other body's centre of mass (m)
  double separation = 0.0;        ///< φ − radius (m): < 0 penetrating, > 0 not yet touching

  // Results of the impulse solve.
  int last_impulse = -1;                  ///< index in the last step's state.contact_impulses, or -1 (new)
  double normal_impulse = 0.0;            ///< accumulated λ_N ≥ 0, N·s
  Vec3 tangent_impulse_W = Vec3::Zero();  ///< accumulated λ_T, |λ_T| ≤ μ λ_N, world axes, N·s
  double predicted_separation = 0.0;      ///< m after the step, from the solved velocity (linear)
};

/// A contact as the impulse solver sees it, built each step in island
/// order. With K the 3×3 matrix of the point (docs/physics.md §5.5), the solve needs nᵀKn,
/// the 2×2 TᵀKT, the Jacobian rows (r × n etc.: d·(v + ω × r) = d·v +
/// ω·(r × d)) and the angular velocity an impulse along n, t₁, t₂ gives
/// (I⁻¹ (r × n) etc.), for both bodies.
struct SolverContact {
  /// One body's side of the contact (zero for the scene and a sleeper).
  struct Side {
    Vec3 rn = Vec3::Zero(), rt1 = Vec3::Zero(), rt2 = Vec3::Zero();              ///< r × n, r × t₁, r × t₂ (m)
    Vec3 turn_n = Vec3::Zero(), turn_t1 = Vec3::Zero(), turn_t2 = Vec3::Zero();  ///< I⁻¹ (r × ·), 1/(kg·m)
    double inv_mass = 0.0;                                                       ///< 1/kg
  };
  /// TᵀKT = Q diag(k) Qᵀ, which sliding friction works in; made the first
  /// time the contact slides in a step.
  struct TangentEigen {
    Eigen::Vector2d k = Eigen::Vector2d::Zero();    ///< eigenvalues, 1/kg
    Eigen::Vector2d q1 = Eigen::Vector2d::UnitX();  ///< unit eigenvector of k.x(); q2 is q1 turned by 90°
    bool isotropic = false;                         ///< k.x() = k.y(): any basis
    bool ready = false;
  };
  int contact = 0;  ///< index in Workspace::contacts
  int body = 0;
  int other = -1;  ///< -1 for the scene; a sleeping other body has no mass terms (it is ground)
  Vec3 normal_W = Vec3::UnitZ(), tangent1_W = Vec3::UnitX(), tangent2_W = Vec3::UnitY();
  Side a, o;                                                   ///< `body`'s side and the other's
  double normal_mass = 0.0;                                    ///< 1 / (nᵀ K n), kg
  Eigen::Matrix2d tangent_k = Eigen::Matrix2d::Zero();         ///< Tᵀ K T, 1/kg
  Eigen::Vector2d normal_tangent_k = Eigen::Vector2d::Zero();  ///< nᵀ K T, 1/kg: a tangent impulse's normal velocity
  Eigen::Matrix2d tangent_mass = Eigen::Matrix2d::Zero();      ///< (Tᵀ K T)⁻¹, kg
  double separation = 0.0;                                     ///< m, as detected
  double target_normal_velocity = 0.0;                         ///< m/s, for the main solve
  double impact_target = 0.0;                                  ///< m/s: e × approach speed, in an impact pass
  double impact_normal = 0.0;                                  ///< N·s, this impact pass's λ_N
  Eigen::Vector2d impact_tangent = Eigen::Vector2d::Zero();    ///< N·s, this impact pass's λ_T
  double normal_impulse = 0.0;                                 ///< accumulated λ_N ≥ 0, N·s
  Eigen::Vector2d tangent_impulse = Eigen::Vector2d::Zero();   ///< accumulated, |λ_T| ≤ μ λ_N, N·s
  TangentEigen tangent_eigen;                                  ///< of tangent_k, for sliding friction
  double friction_nu = 0.0;  ///< 1/kg: the sliding friction's multiplier of the last sweep (the next one's guess)
};

/// A contact point found by the detection, before the reduction.
struct ContactCandidate {
  int other = -1;
  int item = -1;
  int point = 0;
  int region = 0;
  double separation = 0.0;        ///< m
  Vec3 normal_W = Vec3::UnitZ();  ///< ∇φ at the point
};

/// Scratch memory of one part of a step (one thread's share).
struct StepScratch {
  std::vector<ContactCandidate> candidates;
  std::vector<Vec3> region_normals;
  std::vector<int> region_members;
  std::vector<Vec3> region_points;
  std::vector<double> separations;
  std::vector<int> impact_contacts;
  std::vector<int> kept;                        ///< candidates kept by the reduction
  std::vector<Contact> contacts;                ///< this part's contacts, before they are merged
  std::vector<std::pair<int, int>> directions;  ///< broad phase: this part's directions, before they are merged
  double deepest = 0.0;                         ///< m
};

/// Scratch memory of a step (MuJoCo keeps it in mjData; here it is passed
/// in). Results do not depend on it: a fresh workspace or a reused one, one
/// thread or two, give bit-identical steps.
struct Workspace {
  /// Threads the step may use, the caller's included: 0 = every core. The
  /// step only splits work when enough bodies are awake for it to pay.
  int threads = 0;
  /// Awake bodies (or contacts) below which a stage runs on one thread: a
  /// hand-over to the other core costs about 1–1.5 µs, and an awake body's
  /// step 0.5–1.5 µs (bench/README.md).
  std::size_t min_parallel_work = 32;

  std::vector<Contact> contacts;
  /// Impulse solver: the contacts island by island (see island_starts).
  std::vector<SolverContact> solver_contacts;
  /// Deepest penetration seen in this step's detection (m, ≥ 0).
  double deepest_penetration = 0.0;
  /// Per body: touched the scene or another body this step (only bodies in contact may sleep).
  std::vector<char> in_contact;
  /// Impulse solver: the velocities of the bodies in contact, world axes, side by side (Box2D's solver bodies).
  struct Velocity {
    Vec3 v_W = Vec3::Zero();  ///< m/s, of the centre of mass
    Vec3 w_W = Vec3::Zero();  ///< rad/s
  };
  std::vector<Velocity> velocities;
  /// Impulse solver: the awake bodies' inverse inertia in world axes, R I⁻¹ Rᵀ (1/(kg·m²)).
  std::vector<Mat3> inverse_inertias;
  /// Shape matching: where each vertex of the current body went (m, world).
  std::vector<Vec3> positions;
  /// Broad phase: bodies in sweep order, and their boxes.
  std::vector<int> sweep_order;  ///< by (strip along y, lo x)
  std::vector<double> margins, box_lo, box_hi, box_strip, sorted_boxes;
  /// Both directions (a, o) of every pair whose boxes overlap, sorted: a's points against o's solid.
  std::vector<std::pair<int, int>> directions;
  /// Islands of the impulse solve: contact indices island by island, and offsets.
  std::vector<int> island_contacts, island_starts, island_of;
  /// Per body: its island's root, the island's smallest body index (findIslands).
  std::vector<int> island_root;
  std::vector<char> island_flags;  ///< per island root: scratch of the sleep and position stages
  /// Per body: pushed by a contact (λ_N > 0) and left exactly still (v = ω = 0)
  /// by this step's impulse solve: in equilibrium, so it may sleep at once.
  std::vector<char> held_still;
  std::vector<int> correct_contacts;  ///< the contacts the position stage corrects
  std::vector<StepScratch> parts;
  std::shared_ptr<WorkerPool> pool;

  /// A step that changed nothing but the time and the still times, bit for
  /// bit (bodies resting exactly: the contact impulses cancel gravity and
  /// leave v so small that x + Δt v = x). The step is a function of its
  /// input, so the next step from the same input, under the same loads,
  /// changes nothing again: step() then only counts the time (step.cpp).
  /// The input is kept only while every awake body is below the sleep
  /// speeds, so moving worlds do not pay for the copy. A repeated step takes
  /// the contacts and islands the last step left here: run nothing else on
  /// this workspace between steps, or set holds = false.
  struct FixedPoint {
    /// The last step returned its input, kept below, unchanged.
    bool holds = false;
    const Model* model = nullptr;          ///< the model the input was stepped with
    std::vector<BodyState> bodies;         ///< still times aside
    std::vector<ContactImpulse> impulses;  ///< the warm start
    Loads loads;
    bool islands_known = false;  ///< the last step's islands are in island_root
  } fixed_point;
  /// false: compute every step (the tests compare the two, state for state).
  bool skip_fixed_points = true;
  /// Steps found to be a fixed point and not computed again (a count for tests and benchmarks).
  std::size_t skipped_steps = 0;
};

/// How many parts a stage of `work` units (awake bodies, contacts) splits
/// into: one unless there is enough for another core to pay.
int partsFor(Workspace& ws, std::size_t work);

/// Runs part(k) for k < parts, in parallel when parts > 1 (one part is a
/// plain call: no std::function, no allocation). A part's result must not
/// depend on the thread that runs it.
template <class Part>
void runParts(Workspace& ws, int parts, Part&& part) {
  if (parts == 1) {
    part(0);
  } else {
    ws.pool->run(std::function<void(int)>(std::ref(part)));
  }
}

/// Contacts of the awake bodies, at the current state, against the scene and
/// against each other: every contact point with φ − radius < margin, where
/// the margin is the distance the bodies can travel in h (speculative
/// contacts: a fast body is caught before it passes through a thin shape) or
/// the penalty buffer. Between two bodies both ways are tested: the points
/// of each against the other's solid (analytic for boxes, spheres and
/// cylinders, a sampled grid for meshes); only pairs whose bounding boxes
/// overlap are tested (sweep and prune). For the impulse method the points
/// of one region (one item or body, one normal direction) are reduced to at
/// most four that span it; separate regions (the three walls of a room's
/// corner) stay separate. A sleeping body hit by an awake one wakes up.
void detectContacts(const Model& model, const State& state, double h, Workspace& ws);

/// Wakes the sleeping bodies an awake body comes at (faster than a resting
/// contact) or presses into (deeper than the slop). Returns whether any woke.
bool wakeTouchedSleepers(const Model& model, State& state, const Workspace& ws, double h);

/// Islands: bodies joined by contacts between awake bodies (the scene and
/// sleepers join nothing). Fills ws.island_root, per body the smallest body
/// index of its island.
void findIslands(const Model& model, const State& state, Workspace& ws);

/// The impulse response (docs/physics.md §5.5), for all contacts together: per contact the
/// 3×3 K = M⁻¹𝟙 − [r]× I⁻¹ [r]× (with the other body's terms
/// added); normal and friction impulses solved by projected Gauss-Seidel
/// with accumulated clamping, λ_N ≥ 0 and |λ_T| ≤ μ λ_N (Coulomb's law on the
/// impulse, which is the friction factor a = max(1 − μ_T(1+μ_N)|v_N|/|v_T|, 0) when K
/// is isotropic). Restitution first, in impact passes: the contacts arriving
/// faster than the threshold separate at e × the approach speed they had
/// before the solve; contacts set approaching by that collide in the next
/// pass (a row of touching balls passes the impulse along). Warm-started
/// from the last step's impulses.
/// Updates v_WB and w_B of the bodies in contact.
void solveContactImpulses(const Model& model, State& state, double h, Workspace& ws);

/// Moves penetrating bodies out along the contact normals (nonlinear
/// Gauss-Seidel on positions, as Box2D does), leaving at most the slop.
/// Velocities are not touched, so no kinetic energy is added.
void correctPositions(const Model& model, State& state, Workspace& ws);

/// Penalty forces of the contacts on one body, reduced to the centre of
/// mass: quadratic f = k (ε − φ) or log-barrier f = ρ (1/φ − 1/ε), both
/// minus damping c v_N and never pulling, with Coulomb friction μ |f_N|.
void accumulatePenaltyForces(const Model& model, const State& state, const Workspace& ws, int body, Vec3& force_W,
                             Vec3& torque_W);

/// The smallest φ − radius of any contact point of `body` within `margin`
/// of the scene (+infinity if none is that close; other bodies not counted).
double minSeparation(const Model& model, const BodyState& s, int body, double margin);

}  // namespace rigid_body_sim::core
