// The rows of an articulation's impulse solve in joint space (private to the
// core): its joints' limits (one-sided), Coulomb joint friction (bounded)
// and mimic joints (equalities), docs/physics.md §11.6; its links' contacts
// with the scene (a normal row and a friction cone), §11.8
// (articulation_contacts.cpp).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

#include "rigid_body_sim/core/articulation.h"
#include "rigid_body_sim/core/articulation_contacts.h"
#include "rigid_body_sim/core/articulation_dynamics.h"
#include "rigid_body_sim/core/state.h"
#include "rigid_body_sim/core/workspace.h"
#include "solver_contact.h"

namespace rigid_body_sim::core::detail {

/// One row: its velocity w = J u, with J = e_dof + coefficient · e_other,
/// is driven to `target` by an impulse λ kept within [lower, upper] (the
/// generalized impulse Jᵀλ).
struct JointRow {
  int dof = 0;
  int other = -1;                   ///< a second dof (mimic), or -1
  double coefficient = 0.0;         ///< J's entry at `other`
  double sign = 1.0;                ///< J's entry at `dof`: −1 for an upper limit
  double target = 0.0;              ///< rad/s or m/s
  double lower = 0.0, upper = 0.0;  ///< bounds on the accumulated λ, N·m·s or N·s
  double impulse = 0.0;             ///< accumulated λ
  Eigen::VectorXd response;         ///< A⁻¹ Jᵀ: the velocity change a unit λ makes
  double mass = 0.0;                ///< 1 / (J A⁻¹ Jᵀ)
};

/// One contact of a link with the scene: three rows, the point's velocity
/// along n, t₁ and t₂ (w = Jᵀ u, J's columns), a normal impulse λ_N ≥ 0 and
/// a friction impulse on the disk |λ_T| ≤ μ λ_N.
struct ContactRows {
  Eigen::Matrix<double, Eigen::Dynamic, 3> J;         ///< nv × 3: the rows, as columns
  Eigen::Matrix<double, Eigen::Dynamic, 3> response;  ///< A⁻¹ J: the velocity change a unit impulse makes
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero();        ///< Jᵀ A⁻¹ J (1/kg)
  double friction = 0.0;                              ///< μ of the pair
  double separation = 0.0;                            ///< m, as detected
  double target = 0.0;  ///< normal velocity aimed at (m/s): −separation/h if apart, e × the approach speed in an impact
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();            ///< λ_N, λ₁, λ₂ (N·s)
  Vec3 tangent1_W = Vec3::UnitX(), tangent2_W = Vec3::UnitY();  ///< t₁, t₂ (n is the contact's)
  int contact = 0;                                              ///< index in the detection's Workspace::contacts
  /// Friction as one 2 × 2 block by maximal dissipation (frictionOnDisk),
  /// where the articulation can move the point in both tangent directions;
  /// else row by row, then onto the disk.
  bool block = false;
  Eigen::Matrix2d tangent_mass = Eigen::Matrix2d::Zero();  ///< (Tᵀ K T)⁻¹ where `block`
  SolverContact::TangentEigen eigen;
  double nu = 0.0;  ///< frictionOnDisk's multiplier of the last sweep
};

#pragma GCC visibility push(hidden)

/// The rows an articulation's joints need this step, given the velocity it
/// would have without them (u_free): a limit the joint could reach within
/// h, each joint's friction, each mimic joint.
void buildJointRows(const ArticulationModel& model, const ArticulationState& state, const Eigen::VectorXd& u_free,
                    double h, std::vector<JointRow>& rows);

/// Projected Gauss-Seidel over the joint rows and the contacts together,
/// through the factored A = M + h D: u changes by Σ A⁻¹ Jᵀ λ; `impulse`
/// gets Σ Jᵀ λ.
void solveRows(const SolverSettings& settings, const Eigen::LLT<Eigen::MatrixXd>& A, std::vector<JointRow>& rows,
               std::vector<ContactRows>& contacts, Eigen::VectorXd& u, Eigen::VectorXd& impulse);

/// One Gauss-Seidel update of a contact's rows (articulation_contacts.cpp):
/// the normal toward its target, then friction on its disk. Returns the
/// largest velocity change it made along a row (m/s).
double sweepContactRows(const SolverSettings& settings, ContactRows& c, Eigen::VectorXd& u);

/// The links' contacts with the scene at the positions of `kin` (its twists,
/// those of u, give the speculative margins), detected as a world's bodies'
/// are, into `ws.contacts`, each made three rows (J only: solveRows adds the
/// rest), with its target: a contact arriving faster than the restitution
/// threshold at u leaves at e times that speed. `links` holds the links'
/// body states.
void findContactRows(const ArticulationModel& model, const ArticulationColliders& colliders,
                     const ArticulationKinematics& kin, const Eigen::VectorXd& u, double h, State& links, Workspace& ws,
                     std::vector<ContactRows>& contacts);

/// After the solve: each contact's impulses into `ws.contacts`.
void reportContactImpulses(const std::vector<ContactRows>& contacts, Workspace& ws);

/// The position correction (split impulse): where a contact would end the
/// step deeper than the slop, a second solve of the normal rows alone
/// finds the velocity that lifts each out to half the slop in one step,
/// and the positions (not the velocities) move by it. Returns whether
/// anything moved.
bool correctContactPositions(const ArticulationModel& model, std::vector<ContactRows>& contacts,
                             const Eigen::VectorXd& u, double h, double slop, ArticulationState& state);

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
