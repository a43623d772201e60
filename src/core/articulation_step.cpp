// One step of an articulation on its own: docs/physics.md §11.5.
#include "rigid_body_sim/core/articulation_step.h"

#include <Eigen/Cholesky>
#include <algorithm>

#include "joint_rows.h"
#include "rigid_body_sim/core/articulation_dynamics.h"

namespace rigid_body_sim::core {

namespace {

bool samePose(const Pose& a, const Pose& b) {
  return a.translation == b.translation && a.rotation.coeffs() == b.rotation.coeffs();
}

/// Whether the state is bit for bit the one the last step left.
bool carriedStillHolds(const ArticulationState& state) {
  const ArticulationState::Carried& c = state.carried;
  return c.valid && c.q.size() == state.q.size() && c.q == state.q && c.v == state.v && c.V_B == state.V_B &&
         samePose(c.X_WB, state.X_WB);
}

/// The generalized forces at zero velocity: gravity, the wrenches on the
/// links and the clipped efforts.
Eigen::VectorXd appliedForces(const ArticulationModel& model, const ArticulationState& state,
                              const ArticulationLoads& loads, const Vec3& g_W) {
  ArticulationState still = state;
  still.v.setZero();
  still.V_B.setZero();
  Eigen::VectorXd force = -biasForces(model, kinematics(model, still), still, g_W, loads.wrench_L);
  if (loads.effort.size() > 0) {
    for (int i = 1; i <= model.jointCount(); ++i) {
      const double limit = model.links[i].limits.effort;
      force(model.dofOf(i)) += std::clamp(loads.effort(i - 1), -limit, limit);
    }
  }
  return force;
}

}  // namespace

Pose advanceBase(const Pose& X_WB, const Vec6& V_B, double h) {
  Pose X = X_WB;
  X.translation += X_WB.rotation * (h * V_B.tail<3>());
  const Vec3 turn = h * V_B.head<3>();
  const double angle = turn.norm();
  if (angle > 0.0) X.rotation = (X_WB.rotation * Quat(Eigen::AngleAxisd(angle, turn / angle))).normalized();
  return X;
}

void stepArticulation(const ArticulationModel& model, ArticulationState& state, const ArticulationLoads& loads,
                      const Vec3& g_W, double h) {
  ArticulationKinematics kin = kinematics(model, state);
  Eigen::MatrixXd M = massMatrix(model, kin);
  const int nv = model.dofCount();
  const int base = model.fixed_base ? 0 : 6;
  const int nj = model.jointCount();
  // The momenta at the start: carried from the last step, or from the velocities.
  Eigen::VectorXd p_joints;
  Vec6 H_W = Vec6::Zero();
  Eigen::VectorXd u = generalizedVelocity(model, state);
  if (carriedStillHolds(state)) {
    p_joints = state.carried.p;
    H_W = state.carried.H_W;
  } else {
    const Eigen::VectorXd p = M * u;
    p_joints = p.tail(nj);
    if (base) H_W = kin.X_WL[0].forceToParent(p.head<6>());
  }
  const Eigen::VectorXd force = appliedForces(model, state, loads, g_W);
  // The base: the whole articulation's momentum changes by the impulse of the
  // loads on it, exactly; its rows of M u⁺ are that, in the base's axes now.
  Eigen::VectorXd rhs(nv);
  if (base) {
    H_W += h * kin.X_WL[0].forceToParent(force.head<6>());
    rhs.head<6>() = kin.X_WL[0].forceToChild(H_W);
  }
  // Joint damping at the new velocity: (M + h D) u⁺ = p + h (τ + ∂T/∂q), so
  // p⁺ = M u⁺ has lost h D u⁺.
  for (int i = 1; i <= nj; ++i) M(model.dofOf(i), model.dofOf(i)) += h * model.links[i].damping;
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  // The joints: symplectic Euler, p⁺ = p + h (τ + ∂T/∂q(q, u⁺)), implicit in
  // u⁺ through ∂T/∂q, solved by fixed-point iteration from the last u.
  Eigen::VectorXd u_next = u;
  for (int pass = 0; pass < 50; ++pass) {
    setTwists(model, u_next, kin);
    rhs.tail(nj) = p_joints + h * (force.tail(nj) + kineticEnergyGradient(model, kin).tail(nj));
    const Eigen::VectorXd u_new = llt.solve(rhs);
    const double change = (u_new - u_next).cwiseAbs().maxCoeff();
    u_next = u_new;
    if (change <= 1e-14 * (1.0 + u_next.cwiseAbs().maxCoeff())) break;
  }
  // The joints' limits, friction and mimics (§11.6): impulses on the joints
  // only, so the whole articulation's momentum stays as it is.
  std::vector<detail::JointRow> rows;
  detail::buildJointRows(model, state, u_next, h, rows);
  if (!rows.empty()) {
    Eigen::VectorXd impulse = Eigen::VectorXd::Zero(nv);
    detail::solveJointRows(llt, rows, u_next, impulse);
    rhs.tail(nj) += impulse.tail(nj);
  }
  for (int i = 1; i <= nj; ++i) rhs(model.dofOf(i)) -= h * model.links[i].damping * u_next(model.dofOf(i));
  setGeneralizedVelocity(model, u_next, state);
  state.q += h * state.v;
  // A joint stays within its limits: what the solve's tolerance leaves, or a
  // joint set beyond one, is put back (the positions only).
  for (int i = 1; i <= nj; ++i)
    state.q(i - 1) = std::clamp(state.q(i - 1), model.links[i].limits.lower, model.links[i].limits.upper);
  if (base) {
    // The centre of mass moves by h P⁺/m exactly, as a free body's does
    // (§3): the base's new place is shifted by what the joints' and the
    // base's first-order moves miss, O(h²).
    const Vec3 c_next = centreOfMass(model, kin) + h * H_W.tail<3>() / totalMass(model);
    state.X_WB = advanceBase(state.X_WB, state.V_B, h);
    state.X_WB.translation += c_next - centreOfMass(model, kinematics(model, state));
  }
  ArticulationState::Carried& c = state.carried;
  c.valid = true;
  c.p = rhs.tail(nj);
  c.H_W = H_W;
  c.q = state.q;
  c.v = state.v;
  c.V_B = state.V_B;
  c.X_WB = state.X_WB;
}

}  // namespace rigid_body_sim::core
