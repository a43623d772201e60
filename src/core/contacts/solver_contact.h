// The impulse solver's view of a contact (private to the core): built each
// step in island order from the Contacts detection found (contact_solver.cpp).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {
struct Contact;
}

namespace rigid_body_sim::core::detail {

/// A body's inverse inertia in world axes, R I⁻¹ Rᵀ (1/(kg·m²)).
inline Mat3 worldInverseInertia(const BodyModel& b, const Quat& q_WB) {
  const Mat3 R = q_WB.toRotationMatrix();
  return R * b.inv_inertia_B.asDiagonal() * R.transpose();
}

/// A body's velocity as the solve changes it, world axes (Box2D's solver body).
struct BodyVelocity {
  Vec3 v_W = Vec3::Zero();  ///< m/s, of the centre of mass
  Vec3 w_W = Vec3::Zero();  ///< rad/s
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
  int other = -1;            ///< -1 for the scene; a sleeping other body has no mass terms (it is ground)
  double friction = 0.0;     ///< μ_T of the pair (Model::friction)
  double restitution = 0.0;  ///< μ_N of the pair (Model::restitution)
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

struct StepScratch;

#pragma GCC visibility push(hidden)

/// The pairs that pressed on each other in the last step (λ_N > 0), sorted
/// (scene items and bodies alike; both directions of a body pair are one
/// pair): an impact between them is plastic (docs/physics.md §5.5).
void findPressedPairs(const State& state, std::vector<std::array<int, 3>>& pairs);

/// Fills `c` for `contact`: the entries of K = M⁻¹𝟙 − [r]× I⁻¹ [r]×
/// (docs/physics.md §5.5) its solve needs (nᵀKn = M⁻¹ + (r×n)ᵀ I⁻¹ (r×n),
/// and TᵀKT likewise, with the other body's terms added), its coefficients
/// (restitution 0 for a pair in sc.pressed_pairs) and its target normal
/// velocity. A sleeping body is part of the ground on either side: no mass
/// terms. `previous` is the solver contact before it in the island, if any.
void prepareContact(const Model& model, const State& state, const StepScratch& sc, double h, const Contact& contact,
                    const SolverContact* previous, SolverContact& c);

/// Coulomb friction on one contact by maximal dissipation: of the impulses
/// |λ| ≤ limit, the one that leaves the least slip energy ½ vᵀK⁻¹v, i.e. the
/// point of the disk nearest to the sticking impulse `stick` in K's metric
/// (K = TᵀKT, the 2×2 tangent block). Inside the disk it is `stick`;
/// outside, λ = (K + νI)⁻¹ K stick with ν > 0 such that |λ| = limit, and the
/// slip left after it is −νλ: the friction opposes the slip it leaves, as
/// Coulomb's law says, whatever K's rotational coupling. Being a projection
/// onto a convex set, it lets Gauss-Seidel converge (taking the direction
/// from the slip before the update instead can cycle). ν solves the secular
/// equation 1/|λ(ν)| = 1/limit by Newton's method in K's eigenbasis (Moré
/// and Sorensen's trust-region step). 1/|λ(ν)| is concave and increasing,
/// so from any ν ≤ ν* Newton climbs to ν* without overshooting, and from
/// ν > ν* its first step lands below ν*: `nu` (in: a guess, such as the
/// contact's ν of the last sweep; out: the ν found, 0 inside the disk)
/// saves most of the iterations of a converging Gauss-Seidel.
Eigen::Vector2d frictionOnDisk(const SolverSettings& settings, const Eigen::Matrix2d& K,
                               SolverContact::TangentEigen& eigen, const Eigen::Vector2d& stick, double limit,
                               double& nu);

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
