// An articulation's step in two halves, around the solve of the one step
// (step.cpp): docs/physics.md §11.5.
#include "rigid_body_sim/core/articulations/articulation_step.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "articulation_integrators.h"
#include "articulation_phases.h"
#include "joint_rows.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"

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

}  // namespace

Pose advanceBase(const Pose& X_WB, const Vec6& V_B, double h) {
  Pose X = X_WB;
  X.translation += X_WB.rotation * (h * V_B.tail<3>());
  const Vec3 turn = h * V_B.head<3>();
  const double angle = turn.norm();
  if (angle > 0.0) X.rotation = (X_WB.rotation * Quat(Eigen::AngleAxisd(angle, turn / angle))).normalized();
  return X;
}

namespace {

bool finite(const ArticulationState& s) {
  return s.q.allFinite() && s.v.allFinite() && s.V_B.allFinite() && s.X_WB.translation.allFinite() &&
         s.X_WB.rotation.coeffs().allFinite();
}

/// Slows what is faster than the limits; returns whether anything was.
bool limitSpeeds(const ArticulationModel& model, const SpeedLimits& limits, Eigen::VectorXd& u) {
  bool limited = false;
  const auto cap = [&limited](auto&& v, double most) {
    const double speed = v.stableNorm();  // |3e305| squared would overflow
    if (speed > most) {
      v *= most / speed;
      limited = true;
    }
  };
  if (!model.fixed_base) {
    cap(u.segment<3>(0), limits.max_angular_speed);
    cap(u.segment<3>(3), limits.max_linear_speed);
  }
  for (int i = 1; i <= model.jointCount(); ++i) {
    const bool slides = model.links[i].type == JointType::Prismatic;
    cap(u.segment<1>(model.dofOf(i)), slides ? limits.max_linear_speed : limits.max_angular_speed);
  }
  return limited;
}

}  // namespace

namespace detail {

void predictArticulation(const ArticulationModel& model, const ArticulationState& state, const ArticulationLoads& loads,
                         const Vec3& g_W, double h, ArticulationIntegrator integrator, ArticulationWorkspace& ws) {
  const ArticulationKinematics& kin = ws.kin;  // at `state` already (the caller's placement computed it)
  const int base = model.fixed_base ? 0 : 6;
  const int nj = model.jointCount();
  // A = M + h D: joint damping taken at the new velocity.
  Eigen::MatrixXd& A = ws.A;
  massMatrix(model, kin, ws.dynamics, A);
  Eigen::VectorXd& u = ws.u;
  u = generalizedVelocity(model, state);
  // The momenta at the start: carried from the last step, or from the
  // velocities. Verlet carries the base's alone (H_W); symplectic Euler
  // the joints' too.
  const bool verlet = integrator == ArticulationIntegrator::kVerlet;
  ws.carries_joint_momenta = !verlet;
  const bool fresh = !(carriedStillHolds(state) && (verlet || state.carried.p.size() == nj));
  Eigen::VectorXd& p_joints = ws.p;
  Vec6& H_W = ws.H_W;
  H_W.setZero();
  int& predict_only = ws.predict_only;
  predict_only = 0;
  if (!fresh) {
    p_joints = state.carried.p;
    H_W = state.carried.H_W;
    predict_only = state.carried.predict_only;
  } else {
    ws.rhs.noalias() = A * u;
    p_joints = ws.rhs.tail(nj);
    if (base) H_W = kin.X_WL[0].forceToParent(ws.rhs.head<6>());
  }
  for (int i = 1; i <= nj; ++i) A(model.dofOf(i), model.dofOf(i)) += h * model.links[i].damping;
  ws.factor.compute(A, model);
  // The generalized forces at rest: gravity, the wrenches on the links and
  // the efforts, each clipped to its joint's limit.
  Eigen::VectorXd& force = ws.force;
  const std::vector<Vec6>* wrench_L = &loads.wrench_L;
  if (!loads.impulse_L.empty()) {  // an impulse acts as impulse / h over the step
    ws.wrench_L.assign(model.links.size(), Vec6::Zero());
    for (std::size_t i = 0; i < model.links.size(); ++i) {
      ws.wrench_L[i] = loads.impulse_L[i] / h;
      if (!loads.wrench_L.empty()) ws.wrench_L[i] += loads.wrench_L[i];
    }
    wrench_L = &ws.wrench_L;
  }
  // Verlet takes gravity and the wrenches in the bias's pass (below), each
  // time it evaluates the bias; symplectic Euler here, once.
  if (verlet) {
    force.setZero(model.dofCount());
  } else {
    biasForces(model, kin, g_W, *wrench_L, false, ws.dynamics, force);
    force = -force;
  }
  if (loads.effort.size() > 0) {
    for (int i = 1; i <= nj; ++i) {
      force(model.dofOf(i)) += model.links[i].limits.heldEffort(loads.effort(i - 1));
    }
  }
  // The base: the whole articulation's momentum changes by the impulse of the
  // loads on it, exactly; its rows of M u⁺ are that, in the base's axes now.
  Eigen::VectorXd& rhs = ws.rhs;
  rhs.resize(model.dofCount());
  if (base) {
    const Vec6 load_W = verlet ? loadWrench_W(model, kin, g_W, *wrench_L) : kin.X_WL[0].forceToParent(force.head<6>());
    if (verlet && fresh) {
      // Verlet's momentum is the step's, at its middle: a state the caller
      // set has its momentum now, half a step after the last step's middle
      // (its loads without this step's impulses, as for the velocity).
      H_W -= 0.5 * h * (loads.impulse_L.empty() ? load_W : loadWrench_W(model, kin, g_W, loads.wrench_L));
    }
    H_W += h * load_W;
    rhs.head<6>() = kin.X_WL[0].forceToChild(H_W);
  }
  // The semi-implicit step in velocities, u⁺ = u + h A⁻¹ (τ − c(q, u) − D u):
  // each integrator's first guess. Verlet's, carried on, takes c at the
  // step's start instead, u + ½ (the last step's gain): O(h²) from its
  // solution, which makes it second order without a pass.
  if (verlet) {
    const bool extrapolated = !fresh && state.carried.gain.size() == u.size();
    if (extrapolated) {
      ws.mid = u + 0.5 * state.carried.gain;
    } else {
      ws.mid = u;
    }
    biasForcesAt(model, kin, ws.mid, g_W, *wrench_L, ws.dynamics, ws.bias);
  } else {
    biasForces(model, kin, Vec3::Zero(), {}, true, ws.dynamics, ws.bias);
  }
  Eigen::VectorXd& predicted = ws.predicted;
  predicted = h * (force - ws.bias);
  for (int i = 1; i <= nj; ++i) predicted(model.dofOf(i)) -= h * model.links[i].damping * u(model.dofOf(i));
  ws.factor.solveInPlace(predicted);
  predicted += u;
  const bool converged =
      verlet ? verletPasses(model, loads, g_W, *wrench_L, h, fresh, ws) : symplecticPasses(model, h, ws);
  if (!converged) ws.next = predicted;
  if (verlet) {
    if (base) middleMomentum(model, state, h, ws);
  } else if (!converged) {
    // The base twist put right so that the base's rows hold the whole
    // momentum exactly (a 6 × 6 solve).
    Eigen::VectorXd& u_next = ws.next;
    if (base) {
      const Vec6 joints_part = A.bottomLeftCorner(nj, 6).transpose() * u_next.tail(nj);
      u_next.head<6>() = A.topLeftCorner<6, 6>().llt().solve(rhs.head<6>() - joints_part);
    }
    rhs.tail(nj).noalias() = A.bottomRows(nj) * u_next;
  }
}

void finishArticulation(const ArticulationModel& model, const SpeedLimits& limits, double h,
                        const Eigen::VectorXd* impulse, const Eigen::VectorXd* pseudo, ArticulationState& state,
                        ArticulationWorkspace& ws) {
  const int base = model.fixed_base ? 0 : 6;
  const int nj = model.jointCount();
  ArticulationKinematics& kin = ws.kin;
  Eigen::VectorXd& u_next = ws.next;
  Eigen::VectorXd& rhs = ws.rhs;
  Vec6& H_W = ws.H_W;
  // The rows' impulses: the joints' act on the joints only, so the whole
  // articulation's momentum changes by the contacts' alone.
  if (impulse != nullptr && base) H_W += kin.X_WL[0].forceToParent(impulse->head<6>());
  if (ws.carries_joint_momenta) {
    if (impulse != nullptr) rhs.tail(nj) += impulse->tail(nj);
    for (int i = 1; i <= nj; ++i) rhs(model.dofOf(i)) -= h * model.links[i].damping * u_next(model.dofOf(i));
  }
  // Slowed to the limits, the velocities no longer carry the momenta: the
  // next step takes them from the velocities.
  const bool limited = limitSpeeds(model, limits, u_next);
  ws.speed_limited = limited;
  setGeneralizedVelocity(model, u_next, state);
  state.q += h * state.v;
  // A joint stays within its limits: what the solve's tolerance leaves, or a
  // joint set beyond one, is put back (the positions only).
  for (int i = 1; i <= nj; ++i) {
    state.q(i - 1) = std::clamp(state.q(i - 1), model.links[i].limits.lower, model.links[i].limits.upper);
  }
  if (base) {
    // The centre of mass moves by h P⁺/m exactly, as a free body's does
    // (§3): the base's new place is shifted by what the joints' and the
    // base's first-order moves miss, O(h²).
    const Vec3 c_next = centreOfMass(model, kin) + h * H_W.tail<3>() / totalMass(model);
    state.X_WB = advanceBase(state.X_WB, state.V_B, h);
    kinematics(model, state, kin);
    state.X_WB.translation += c_next - centreOfMass(model, kin);
  }
  if (pseudo != nullptr) {
    // A lift is a velocity of the positions: no faster than the limits.
    Eigen::VectorXd& lift = ws.lift;
    lift = *pseudo;
    limitSpeeds(model, limits, lift);
    moveRobot(model, lift, h, state);
  }
  ArticulationState::Carried& c = state.carried;
  c.valid = !limited;
  if (ws.carries_joint_momenta) {
    c.p = rhs.tail(nj);
  } else {
    c.p.resize(0);
  }
  c.H_W = H_W;
  c.q = state.q;
  c.v = state.v;
  c.V_B = state.V_B;
  c.X_WB = state.X_WB;
  c.predict_only = ws.predict_only;
  c.gain = ws.gain;
}

}  // namespace detail

namespace detail {

bool loaded(const ArticulationLoads& loads) {
  const bool effort = loads.effort.size() > 0 && (loads.effort.array() != 0.0).any();
  const auto any = [](const std::vector<Vec6>& ws) {
    return std::any_of(ws.begin(), ws.end(), [](const Vec6& w) { return (w.array() != 0.0).any(); });
  };
  return effort || any(loads.wrench_L) || any(loads.impulse_L);
}

bool updateStillTime(const ArticulationModel& model, const SleepSettings& sleep, bool touching, double h,
                     ArticulationState& state) {
  bool still = sleep.enabled && touching && state.V_B.head<3>().norm() < sleep.angular_velocity &&
               state.V_B.tail<3>().norm() < sleep.linear_velocity;
  for (int i = 1; i <= model.jointCount() && still; ++i) {
    const bool slides = model.links[i].type == JointType::Prismatic;
    still = std::abs(state.v(i - 1)) < (slides ? sleep.linear_velocity : sleep.angular_velocity);
  }
  state.still_time = still ? state.still_time + h : 0.0;
  return still && state.still_time >= sleep.time;
}

void fallAsleep(ArticulationState& state) {
  state.asleep = true;
  state.v.setZero();
  state.V_B.setZero();
  state.carried = {};
}

void checkLoads(const ArticulationModel& model, const ArticulationLoads& loads) {
  const auto sized = [](long size, long wanted, const char* what) {
    if (size != 0 && size != wanted) {
      throw std::invalid_argument(std::string("articulation loads: ") + what + " has " + std::to_string(size) +
                                  " entries, the model " + std::to_string(wanted));
    }
  };
  sized(loads.effort.size(), model.jointCount(), "effort");
  sized(static_cast<long>(loads.wrench_L.size()), static_cast<long>(model.links.size()), "wrench_L");
  sized(static_cast<long>(loads.impulse_L.size()), static_cast<long>(model.links.size()), "impulse_L");
}

bool guardArticulation(const ArticulationModel& model, const ArticulationState& start, ArticulationState& state) {
  if (finite(state)) return true;
  // Undone: where the step began, at rest, nothing carried (§11.7).
  if (start.q.allFinite() && start.X_WB.translation.allFinite() && start.X_WB.rotation.coeffs().allFinite()) {
    state.q = start.q;
    state.X_WB = start.X_WB;
  } else {
    state = restState(model);
  }
  state.v.setZero();
  state.V_B.setZero();
  state.carried = {};
  return false;
}

}  // namespace detail

}  // namespace rigid_body_sim::core
