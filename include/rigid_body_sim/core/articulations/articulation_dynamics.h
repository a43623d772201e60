// An articulation's kinematics and dynamics in generalized coordinates
// (docs/physics.md §11): link placements and twists, the joint-space mass
// matrix by the composite-rigid-body algorithm, generalized forces by
// recursive Newton-Euler, forward dynamics, energy and momentum. Eigen only.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"

namespace rigid_body_sim::core {

/// Where every link is and how it moves, for one state (§11.2).
struct ArticulationKinematics {
  std::vector<Placement> X_PL;      ///< each link in its parent's frame (the base: in W)
  std::vector<Placement> X_WL;      ///< each link in W
  std::vector<Vec6> V_L;            ///< each link's twist in W, expressed in its own axes
  std::vector<Vec6> S_L;            ///< each joint's motion axis in its link's axes (the base's unused)
  std::vector<SpatialInertia> I_L;  ///< each link's inertia about its origin, its axes
  // The same in one frame for all, the base's B (§11.3): sums down and up
  // the tree then need no transforms.
  std::vector<Placement> X_BL;      ///< each link in the base's frame
  std::vector<Vec6> S_B;            ///< each joint's motion axis in B (the base's unused)
  std::vector<SpatialInertia> I_B;  ///< each link's inertia about B's origin, B's axes
};

/// The child link's placement in its parent at joint position q (§11.2):
/// the joint frame, then a rotation about or a slide along the axis.
Placement jointPlacement(const ArticulatedLink& link, double q);

/// Placements, twists and joint axes for a state.
ArticulationKinematics kinematics(const ArticulationModel& model, const ArticulationState& state);
/// The same into `kin`, reusing its memory.
void kinematics(const ArticulationModel& model, const ArticulationState& state, ArticulationKinematics& kin);

/// Memory the in-place forms below reuse (results never depend on it).
struct DynamicsScratch {
  std::vector<SpatialInertia> composite;
  std::vector<Vec6> a, f, v;
};

/// Sets the twists of `kin` for the generalized velocity u (its placements kept).
void setTwists(const ArticulationModel& model, const Eigen::VectorXd& u, ArticulationKinematics& kin);

/// ∂T/∂q at the twists of `kin` (velocities held), per joint (§11.5):
/// −Sₖ·(Vₖ ×* Hₖ), Hₖ the momentum of link k's subtree. Zero for the base's rows.
Eigen::VectorXd kineticEnergyGradient(const ArticulationModel& model, const ArticulationKinematics& kin);
void kineticEnergyGradient(const ArticulationModel& model, const ArticulationKinematics& kin, DynamicsScratch& scratch,
                           Eigen::VectorXd& gradient);

/// The joint-space mass matrix M(q), dofCount() square, by the
/// composite-rigid-body algorithm (§11.3).
Eigen::MatrixXd massMatrix(const ArticulationModel& model, const ArticulationKinematics& kin);
void massMatrix(const ArticulationModel& model, const ArticulationKinematics& kin, DynamicsScratch& scratch,
                Eigen::MatrixXd& M);

/// How fast joint `link`'s speed answers an impulse on it, (M⁻¹)ᵢᵢ (1/(kg·m²)
/// or 1/kg) at this state, with nothing touching: its greatest answer, as
/// contacts and loads on the other links only slow it (§11.12). Infinite
/// when M is singular there.
double jointResponse(const ArticulationModel& model, const ArticulationKinematics& kin, int link);

/// Recursive Newton-Euler (§11.4): the generalized forces that give the
/// generalized accelerations `udot` at this state under gravity g_W (m/s²),
/// with external wrenches `wrench_L` on the links (each in its link's axes,
/// moment about its origin; empty for none): τ = M u̇ + c(q, u) − Jᵀ F.
Eigen::VectorXd inverseDynamics(const ArticulationModel& model, const ArticulationKinematics& kin,
                                const Eigen::VectorXd& udot, const Vec3& g_W, const std::vector<Vec6>& wrench_L = {});

/// What each joint carries (§11.4, the backward pass of inverseDynamics):
/// per link, the wrench its parent puts on it through its joint, the sum
/// over its subtree of I a + v ×* I v less gravity's and `wrench_L`'s, at
/// the generalized accelerations `udot`: [moment about the link's origin;
/// force], in its axes, N·m and N. Entry 0 is the base's: what would hold
/// the whole robot so (zero for a free base at the accelerations its loads give).
std::vector<Vec6> jointWrenches(const ArticulationModel& model, const ArticulationKinematics& kin,
                                const Eigen::VectorXd& udot, const Vec3& g_W, const std::vector<Vec6>& wrench_L = {});

/// The bias forces c(q, u): Coriolis, centrifugal and gravity terms (and
/// the external wrenches', with the opposite sign): inverse dynamics at u̇ = 0.
Eigen::VectorXd biasForces(const ArticulationModel& model, const ArticulationKinematics& kin, const Vec3& g_W,
                           const std::vector<Vec6>& wrench_L = {});

/// The bias at rest (the twists of `kin` taken as zero): gravity's and the
/// wrenches' generalized forces, with the sign of c.
Eigen::VectorXd restForces(const ArticulationModel& model, const ArticulationKinematics& kin, const Vec3& g_W,
                           const std::vector<Vec6>& wrench_L = {});
/// biasForces (moving) or restForces (not) into `out`.
void biasForces(const ArticulationModel& model, const ArticulationKinematics& kin, const Vec3& g_W,
                const std::vector<Vec6>& wrench_L, bool moving, DynamicsScratch& scratch, Eigen::VectorXd& out);

/// biasForces with gravity and the wrenches at the generalized velocity u
/// instead of the twists of `kin` (whose placements and axes it takes, and
/// whose twists it leaves): the twists are carried down the tree in the
/// same Newton-Euler pass.
void biasForcesAt(const ArticulationModel& model, const ArticulationKinematics& kin, const Eigen::VectorXd& u,
                  const Vec3& g_W, const std::vector<Vec6>& wrench_L, DynamicsScratch& scratch, Eigen::VectorXd& out);

/// The loads' whole wrench on the articulation: gravity on every link and
/// `wrench_L` (as biasForces takes them), about W's origin in world axes.
Vec6 loadWrench_W(const ArticulationModel& model, const ArticulationKinematics& kin, const Vec3& g_W,
                  const std::vector<Vec6>& wrench_L);

/// Forward dynamics: u̇ = M⁻¹ (τ − c).
Eigen::VectorXd forwardDynamics(const ArticulationModel& model, const ArticulationState& state,
                                const Eigen::VectorXd& tau, const Vec3& g_W);

/// ½ uᵀ M u (J).
double kineticEnergy(const ArticulationModel& model, const ArticulationKinematics& kin);
/// −Σ mᵢ g·cᵢ (J), zero at the world origin.
double potentialEnergy(const ArticulationModel& model, const ArticulationKinematics& kin, const Vec3& g_W);
/// The whole articulation's mass (kg), its base's included.
double totalMass(const ArticulationModel& model);
/// The whole articulation's centre of mass in W (m).
Vec3 centreOfMass(const ArticulationModel& model, const ArticulationKinematics& kin);
/// Total momentum [angular about W's origin; linear], world axes.
Vec6 momentum_W(const ArticulationModel& model, const ArticulationKinematics& kin);

}  // namespace rigid_body_sim::core
