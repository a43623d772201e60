// An articulation's joint constraints as rows of one impulse solve (private
// to the core; docs/physics.md §11.6): limits (one-sided), Coulomb joint
// friction (bounded) and mimic joints (equalities), in joint space.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

#include "rigid_body_sim/core/articulation.h"

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

#pragma GCC visibility push(hidden)

/// The rows an articulation's joints need this step, given the velocity it
/// would have without them (u_free): a limit the joint could reach within
/// h, each joint's friction, each mimic joint.
void buildJointRows(const ArticulationModel& model, const ArticulationState& state, const Eigen::VectorXd& u_free,
                    double h, std::vector<JointRow>& rows);

/// Projected Gauss-Seidel over the rows, through the factored A = M + h D:
/// u changes by Σ A⁻¹ Jᵀ λ; `impulse` gets Σ Jᵀ λ.
void solveJointRows(const Eigen::LLT<Eigen::MatrixXd>& A, std::vector<JointRow>& rows, Eigen::VectorXd& u,
                    Eigen::VectorXd& impulse);

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
