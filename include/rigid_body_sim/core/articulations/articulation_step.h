// What an articulation's step takes and keeps (docs/physics.md §11.5): its
// loads and the memory it reuses. The step itself is the one step of every
// world (core::stepScene, step.h): a robot alone is a scene of one robot.
// Eigen only.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/articulations/tree_factor.h"
#include "rigid_body_sim/core/bodies/settings.h"
#include "rigid_body_sim/core/bodies/state.h"

namespace rigid_body_sim::core {

/// What acts on an articulation over one step besides gravity.
struct ArticulationLoads {
  Eigen::VectorXd effort;      ///< per joint (N·m or N), clipped to |effort| ≤ the limit; empty for none
  std::vector<Vec6> wrench_L;  ///< per link, in its axes, moment about its origin; empty for none
  /// Per link, as wrench_L, an impulse (N·m·s; N·s) given at the step's
  /// start: the momenta change by exactly it (it acts as impulse / h over
  /// the step); empty for none.
  std::vector<Vec6> impulse_L;
};

/// The memory a step reuses from one step to the next, so that once sized
/// a step allocates nothing for its dynamics (MuJoCo keeps it in mjData).
/// Results never depend on it.
struct ArticulationWorkspace {
  ArticulationKinematics kin;
  DynamicsScratch dynamics;
  Eigen::MatrixXd A;
  TreeFactor factor;  ///< of A
  Eigen::VectorXd u, p, force, bias, predicted, next, corrected, rhs, gradient, lift;
  Eigen::VectorXd before, mid;  ///< the Verlet step's ū of the last step, and ½ (ū + ū⁺)
  Eigen::VectorXd gain;         ///< the Verlet step's ū⁺ − ū by the dynamics alone (no rows)
  ArticulationState middle;     ///< a floating base's Verlet step: the middle of its move
  ArticulationKinematics middle_kin;
  Eigen::MatrixXd middle_M;
  std::vector<Vec6> wrench_L;               ///< the loads' wrenches and impulses / h together
  Eigen::VectorXd row_impulse, row_pseudo;  ///< its part of the solve's impulse and pseudo velocity
  ArticulationState start;                  ///< where the step began, for the guard
  bool speed_limited = false;               ///< the last step slowed something to the speed limits
  Vec6 H_W = Vec6::Zero();                  ///< the floating base's rows: the whole momentum, world axes, within a step
  int predict_only = 0;                     ///< within a step: the steps left that skip the corrector
  bool carries_joint_momenta = false;       ///< within a step: the integrator carries the joints' momenta (rhs)
};

/// The base pose after h seconds at twist V_B (in the base's axes): the
/// origin moved by h R v, the rotation by exp(h ω) on the body side.
Pose advanceBase(const Pose& X_WB, const Vec6& V_B, double h);

}  // namespace rigid_body_sim::core
