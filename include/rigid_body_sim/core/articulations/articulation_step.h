// One step of an articulation on its own (docs/physics.md §11.5): efforts
// clipped to their limits, the semi-implicit Euler step in generalized
// coordinates with joint damping implicit, then positions. Eigen only.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/articulations/articulation_contacts.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/bodies/settings.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/workspace.h"

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
  Eigen::LLT<Eigen::MatrixXd> llt;
  Eigen::VectorXd u, p, force, bias, predicted, next, corrected, rhs, gradient, lift;
  std::vector<Vec6> wrench_L;  ///< the loads' wrenches and impulses / h together
  ArticulationState start;
  /// The links as bodies, and the detection's workspace: after a step with
  /// colliders, `detection.contacts` holds its contacts with their impulses.
  State links;
  Workspace detection;
  std::vector<ContactImpulse> last_impulses;  ///< the last step's, for the warm start, during a step
  bool speed_limited = false;                 ///< the last step slowed something to the speed limits
  Vec6 H_W = Vec6::Zero();  ///< the floating base's rows: the whole momentum, world axes, within a step
  int predict_only = 0;     ///< within a step: the steps left that skip the corrector
};

/// Advances `state` by h seconds under gravity g_W (m/s²): symplectic Euler
/// on the joints' momenta with damping implicit, the joints' limits,
/// friction and mimics solved as rows, then q⁺ = q + h v⁺ and the base moved
/// by its new twist (§11.5, §11.6). With `colliders`, the links' contacts
/// with the scene are rows of the same solve as the joints' (§11.8), and
/// what still penetrates deeper than the slop is lifted out.
///
/// The speed limits (§5.9, §11.7): a joint faster than limits'
/// max_angular_speed (revolute, continuous) or max_linear_speed (prismatic),
/// or a base whose ω or v is, is slowed to it. The guard: a step that leaves
/// anything non-finite (a NaN or infinite effort) is undone: the state goes
/// back to where the step began, at rest, and false is returned.
/// Throws std::invalid_argument when `loads` has a size other than the
/// model's (efforts: one per joint; wrenches and impulses: one per link).
bool stepArticulation(const ArticulationModel& model, ArticulationState& state, const ArticulationLoads& loads,
                      const Vec3& g_W, double h, const SpeedLimits& limits = {},
                      ArticulationWorkspace* workspace = nullptr, const ArticulationColliders* colliders = nullptr);

/// The base pose after h seconds at twist V_B (in the base's axes): the
/// origin moved by h R v, the rotation by exp(h ω) on the body side.
Pose advanceBase(const Pose& X_WB, const Vec6& V_B, double h);

}  // namespace rigid_body_sim::core
