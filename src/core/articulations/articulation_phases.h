// An articulation's step in two halves around its impulse solve (private to
// the core): the one step (step.cpp, through scene_step.cpp) solves the rows
// between them, docs/physics.md §11.5, §11.9.
#pragma once

#include <Eigen/Core>

#include "rigid_body_sim/core/articulations/articulation_step.h"

#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core::detail {

/// Everything before the rows, from the kinematics at the start (ws.kin,
/// which the caller has computed at `state`): the factored A = M + h D
/// (ws.factor), the velocity the step gives without rows (ws.next) by
/// `integrator`, the joints' momenta it carries (ws.rhs) and the floating
/// base's whole momentum (ws.H_W).
void predictArticulation(const ArticulationModel& model, const ArticulationState& state, const ArticulationLoads& loads,
                         const Vec3& g_W, double h, ArticulationIntegrator integrator, ArticulationWorkspace& ws);

/// Everything after: the rows' generalized impulse Σ Jᵀλ (if any) into the
/// momenta, the damping, the speed limits, q⁺ = q + h v⁺ and the base;
/// then the positions moved by h times the position correction's `pseudo`
/// velocity (if any); the momenta carried to the next step. ws.next must
/// hold the velocity after the rows.
void finishArticulation(const ArticulationModel& model, const SpeedLimits& limits, double h,
                        const Eigen::VectorXd* impulse, const Eigen::VectorXd* pseudo, ArticulationState& state,
                        ArticulationWorkspace& ws);

/// Whether any effort, wrench or impulse acts (a sleeper wakes for it).
bool loaded(const ArticulationLoads& loads);

/// Sleep's clock (§11.8), as a body's (§6): the time the articulation has
/// been touching something (`touching`) with every joint and the base
/// slower than the sleep speeds (a prismatic joint and the base's v by the
/// linear one); whether it has reached `sleep.time` (sleep on).
bool updateStillTime(const ArticulationModel& model, const SleepSettings& sleep, bool touching, double h,
                     ArticulationState& state);

/// Asleep: its velocities zeroed, nothing carried; not stepped until a
/// load wakes it or its caller clears the flag.
void fallAsleep(ArticulationState& state);

/// Throws std::invalid_argument when `loads` has a size other than the
/// model's (efforts: one per joint; wrenches and impulses: one per link).
void checkLoads(const ArticulationModel& model, const ArticulationLoads& loads);

/// The guard (§11.7): a state not finite after a step is put back where
/// the step began (`start`'s positions), at rest, nothing carried; returns
/// whether the state was finite.
bool guardArticulation(const ArticulationModel& model, const ArticulationState& start, ArticulationState& state);

}  // namespace rigid_body_sim::core::detail
#pragma GCC visibility pop
