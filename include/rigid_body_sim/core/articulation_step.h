// One step of an articulation on its own (docs/physics.md §11.5): efforts
// clipped to their limits, the semi-implicit Euler step in generalized
// coordinates with joint damping implicit, then positions. Eigen only.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "rigid_body_sim/core/articulation.h"

namespace rigid_body_sim::core {

/// What acts on an articulation over one step besides gravity.
struct ArticulationLoads {
  Eigen::VectorXd effort;      ///< per joint (N·m or N), clipped to |effort| ≤ the limit; empty for none
  std::vector<Vec6> wrench_L;  ///< per link, in its axes, moment about its origin; empty for none
};

/// Advances `state` by h seconds under gravity g_W (m/s²):
///   (M + h D) u⁺ = M u + h (τ − c(q, u)),  then q⁺ = q + h v⁺ and the base
/// moved by its new twist. D is the joints' damping, so any damping is stable.
void stepArticulation(const ArticulationModel& model, ArticulationState& state, const ArticulationLoads& loads,
                      const Vec3& g_W, double h);

/// The base pose after h seconds at twist V_B (in the base's axes): the
/// origin moved by h R v, the rotation by exp(h ω) on the body side.
Pose advanceBase(const Pose& X_WB, const Vec6& V_B, double h);

}  // namespace rigid_body_sim::core
