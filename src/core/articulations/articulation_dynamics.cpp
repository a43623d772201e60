// An articulation's kinematics, mass matrix (composite rigid bodies) and
// generalized forces (recursive Newton-Euler): docs/physics.md §11.2–11.4.
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

namespace rigid_body_sim::core {

namespace {

Vec6 motionAxis(const ArticulatedLink& link) {
  Vec6 S = Vec6::Zero();
  if (link.type == JointType::Prismatic) {
    S.tail<3>() = link.axis_J;
  } else {
    S.head<3>() = link.axis_J;
  }
  return S;
}

}  // namespace

Placement jointPlacement(const ArticulatedLink& link, double q) {
  Placement X = Placement::of(link.X_PJ);
  if (link.type == JointType::Prismatic) {
    X.p_PC += X.R_PC * (q * link.axis_J);
  } else {
    X.R_PC = X.R_PC * Eigen::AngleAxisd(q, link.axis_J).toRotationMatrix();
  }
  return X;
}

ArticulationKinematics kinematics(const ArticulationModel& model, const ArticulationState& state) {
  ArticulationKinematics kin;
  kinematics(model, state, kin);
  return kin;
}

void kinematics(const ArticulationModel& model, const ArticulationState& state, ArticulationKinematics& kin) {
  const int n = static_cast<int>(model.links.size());
  kin.X_PL.resize(n);
  kin.X_WL.resize(n);
  kin.V_L.resize(n);
  kin.S_L.resize(n);
  kin.I_L.resize(n);
  kin.X_BL.resize(n);
  kin.S_B.resize(n);
  kin.I_B.resize(n);
  for (int i = 0; i < n; ++i) kin.I_L[i] = SpatialInertia::of(model.links[i].mass);
  kin.X_PL[0] = Placement::of(state.X_WB);
  kin.X_WL[0] = kin.X_PL[0];
  kin.V_L[0] = model.fixed_base ? Vec6::Zero() : state.V_B;
  kin.S_L[0] = Vec6::Zero();
  kin.X_BL[0] = Placement();
  kin.S_B[0] = Vec6::Zero();
  kin.I_B[0] = kin.I_L[0];
  for (int i = 1; i < n; ++i) {
    const ArticulatedLink& link = model.links[i];
    kin.X_PL[i] = jointPlacement(link, state.q(i - 1));
    kin.X_WL[i] = kin.X_WL[link.parent] * kin.X_PL[i];
    kin.S_L[i] = motionAxis(link);
    kin.V_L[i] = kin.X_PL[i].motionToChild(kin.V_L[link.parent]) + kin.S_L[i] * state.v(i - 1);
    kin.X_BL[i] = kin.X_BL[link.parent] * kin.X_PL[i];
    kin.S_B[i] = kin.X_BL[i].motionToParent(kin.S_L[i]);
    kin.I_B[i] = kin.I_L[i].toParent(kin.X_BL[i]);
  }
}

void setTwists(const ArticulationModel& model, const Eigen::VectorXd& u, ArticulationKinematics& kin) {
  kin.V_L[0] = model.fixed_base ? Vec6::Zero() : Vec6(u.head<6>());
  for (std::size_t i = 1; i < model.links.size(); ++i) {
    kin.V_L[i] =
        kin.X_PL[i].motionToChild(kin.V_L[model.links[i].parent]) + kin.S_L[i] * u(model.dofOf(static_cast<int>(i)));
  }
}

Eigen::VectorXd kineticEnergyGradient(const ArticulationModel& model, const ArticulationKinematics& kin) {
  DynamicsScratch scratch;
  Eigen::VectorXd gradient;
  kineticEnergyGradient(model, kin, scratch, gradient);
  return gradient;
}

void kineticEnergyGradient(const ArticulationModel& model, const ArticulationKinematics& kin, DynamicsScratch& scratch,
                           Eigen::VectorXd& gradient) {
  const int n = static_cast<int>(model.links.size());
  std::vector<Vec6>& H = scratch.f;
  H.resize(n);
  for (int i = 0; i < n; ++i) H[i] = kin.I_L[i] * kin.V_L[i];
  gradient.setZero(model.dofCount());
  for (int i = n - 1; i > 0; --i) {
    gradient(model.dofOf(i)) = -kin.S_L[i].dot(crossForce(kin.V_L[i], H[i]));
    H[model.links[i].parent] += kin.X_PL[i].forceToParent(H[i]);
  }
}

Eigen::MatrixXd massMatrix(const ArticulationModel& model, const ArticulationKinematics& kin) {
  DynamicsScratch scratch;
  Eigen::MatrixXd M;
  massMatrix(model, kin, scratch, M);
  return M;
}

double jointResponse(const ArticulationModel& model, const ArticulationKinematics& kin, int link) {
  const Eigen::LLT<Eigen::MatrixXd> llt(massMatrix(model, kin));
  if (llt.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
  Eigen::VectorXd unit = Eigen::VectorXd::Unit(model.dofCount(), model.dofOf(link));
  const double r = unit.dot(llt.solve(unit));
  return std::isfinite(r) && r > 0.0 ? r : std::numeric_limits<double>::infinity();
}

void massMatrix(const ArticulationModel& model, const ArticulationKinematics& kin, DynamicsScratch& scratch,
                Eigen::MatrixXd& M) {
  // In the base's frame B, where a subtree's inertia is the plain sum of
  // its links' and M's entries are dot products (§11.3).
  const int n = static_cast<int>(model.links.size());
  std::vector<SpatialInertia>& Ic = scratch.composite;
  Ic.assign(kin.I_B.begin(), kin.I_B.end());
  for (int i = n - 1; i > 0; --i) Ic[model.links[i].parent] += Ic[i];
  M.setZero(model.dofCount(), model.dofCount());
  if (!model.fixed_base) M.topLeftCorner<6, 6>() = Ic[0].matrix();
  for (int i = 1; i < n; ++i) {
    // The force that accelerates joint i's subtree at unit rate: its
    // projection on each ancestor's axis is M's entry.
    const Vec6 F = Ic[i] * kin.S_B[i];
    const int di = model.dofOf(i);
    M(di, di) = kin.S_B[i].dot(F);
    for (int j = model.links[i].parent; j > 0; j = model.links[j].parent) {
      M(di, model.dofOf(j)) = M(model.dofOf(j), di) = kin.S_B[j].dot(F);
    }
    if (!model.fixed_base) {
      M.block<6, 1>(0, di) = F;
      M.block<1, 6>(di, 0) = F.transpose();
    }
  }
}

namespace {

/// Recursive Newton-Euler over the tree (§11.4): the generalized forces for
/// the accelerations `udot` (none: zero), at the twists of `kin` or, when
/// `moving` is false, at rest.
void newtonEuler(const ArticulationModel& model, const ArticulationKinematics& kin, const Eigen::VectorXd* udot,
                 const Vec3& g_W, const std::vector<Vec6>& wrench_L, bool moving, DynamicsScratch& scratch,
                 Eigen::VectorXd& tau) {
  const int n = static_cast<int>(model.links.size());
  std::vector<Vec6>& a = scratch.a;
  std::vector<Vec6>& f = scratch.f;
  a.resize(n);
  f.resize(n);
  a[0] = Vec6::Zero();
  if (!model.fixed_base && udot != nullptr) a[0] = udot->head<6>();
  a[0].tail<3>() -= kin.X_WL[0].R_PC.transpose() * g_W;
  for (int i = 0; i < n; ++i) {
    const SpatialInertia& I = kin.I_L[i];
    if (i > 0) {
      const Placement& X = kin.X_PL[i];
      const int parent = model.links[i].parent;
      a[i] = X.motionToChild(a[parent]);
      if (udot != nullptr) a[i] += kin.S_L[i] * (*udot)(model.dofOf(i));
      // The joint's own motion seen from the moving link: Vᵢ ×ₘ Sᵢ vᵢ, with
      // Sᵢ vᵢ = Vᵢ − X Vₚ.
      if (moving) a[i] += crossMotion(kin.V_L[i], kin.V_L[i] - X.motionToChild(kin.V_L[parent]));
    }
    f[i] = I * a[i];
    if (moving) f[i] += crossForce(kin.V_L[i], I * kin.V_L[i]);
    if (!wrench_L.empty()) f[i] -= wrench_L[i];
  }
  tau.resize(model.dofCount());
  for (int i = n - 1; i > 0; --i) {
    tau(model.dofOf(i)) = kin.S_L[i].dot(f[i]);
    f[model.links[i].parent] += kin.X_PL[i].forceToParent(f[i]);
  }
  if (!model.fixed_base) tau.head<6>() = f[0];
}

Eigen::VectorXd newtonEuler(const ArticulationModel& model, const ArticulationKinematics& kin,
                            const Eigen::VectorXd* udot, const Vec3& g_W, const std::vector<Vec6>& wrench_L,
                            bool moving) {
  DynamicsScratch scratch;
  Eigen::VectorXd tau;
  newtonEuler(model, kin, udot, g_W, wrench_L, moving, scratch, tau);
  return tau;
}

}  // namespace

Eigen::VectorXd inverseDynamics(const ArticulationModel& model, const ArticulationKinematics& kin,
                                const Eigen::VectorXd& udot, const Vec3& g_W, const std::vector<Vec6>& wrench_L) {
  return newtonEuler(model, kin, &udot, g_W, wrench_L, true);
}

std::vector<Vec6> jointWrenches(const ArticulationModel& model, const ArticulationKinematics& kin,
                                const Eigen::VectorXd& udot, const Vec3& g_W, const std::vector<Vec6>& wrench_L) {
  // The backward pass leaves each link's f as its subtree's sum, which its
  // joint carries: its children are added before it is (a parent's index
  // is below its children's).
  DynamicsScratch scratch;
  Eigen::VectorXd tau;
  newtonEuler(model, kin, &udot, g_W, wrench_L, true, scratch, tau);
  return scratch.f;
}

Eigen::VectorXd biasForces(const ArticulationModel& model, const ArticulationKinematics& kin, const Vec3& g_W,
                           const std::vector<Vec6>& wrench_L) {
  return newtonEuler(model, kin, nullptr, g_W, wrench_L, true);
}

Eigen::VectorXd restForces(const ArticulationModel& model, const ArticulationKinematics& kin, const Vec3& g_W,
                           const std::vector<Vec6>& wrench_L) {
  return newtonEuler(model, kin, nullptr, g_W, wrench_L, false);
}

void biasForces(const ArticulationModel& model, const ArticulationKinematics& kin, const Vec3& g_W,
                const std::vector<Vec6>& wrench_L, bool moving, DynamicsScratch& scratch, Eigen::VectorXd& out) {
  newtonEuler(model, kin, nullptr, g_W, wrench_L, moving, scratch, out);
}

void biasForcesAt(const ArticulationModel& model, const ArticulationKinematics& kin, const Eigen::VectorXd& u,
                  const Vec3& g_W, const std::vector<Vec6>& wrench_L, DynamicsScratch& scratch, Eigen::VectorXd& out) {
  // In the base's frame B (§11.4): a link's twist is its parent's plus its
  // joint's, and a subtree's force the plain sum of its links'.
  const int n = static_cast<int>(model.links.size());
  std::vector<Vec6>& v = scratch.v;
  std::vector<Vec6>& a = scratch.a;
  std::vector<Vec6>& f = scratch.f;
  v.resize(n);
  a.resize(n);
  f.resize(n);
  v[0] = model.fixed_base ? Vec6::Zero() : Vec6(u.head<6>());
  a[0].head<3>().setZero();
  a[0].tail<3>() = -(kin.X_WL[0].R_PC.transpose() * g_W);  // gravity as the base's acceleration upwards
  for (int i = 0; i < n; ++i) {
    const SpatialInertia& I = kin.I_B[i];
    if (i > 0) {
      const int parent = model.links[i].parent;
      const Vec6 joint = kin.S_B[i] * u(model.dofOf(i));  // Sᵢ vᵢ
      v[i] = v[parent] + joint;
      a[i] = a[parent] + crossMotion(v[i], joint);
    }
    f[i] = I * a[i] + crossForce(v[i], I * v[i]);
    if (!wrench_L.empty()) f[i] -= kin.X_BL[i].forceToParent(wrench_L[i]);
  }
  out.resize(model.dofCount());
  for (int i = n - 1; i > 0; --i) {
    out(model.dofOf(i)) = kin.S_B[i].dot(f[i]);
    f[model.links[i].parent] += f[i];
  }
  if (!model.fixed_base) out.head<6>() = f[0];
}

Vec6 loadWrench_W(const ArticulationModel& model, const ArticulationKinematics& kin, const Vec3& g_W,
                  const std::vector<Vec6>& wrench_L) {
  Vec6 total = Vec6::Zero();
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const Placement& X = kin.X_WL[i];
    const MassProperties& mp = model.links[i].mass;
    const Vec3 weight = mp.mass * g_W;
    total.head<3>() += (X.p_PC + X.R_PC * mp.p_FC).cross(weight);
    total.tail<3>() += weight;
    if (!wrench_L.empty()) total += X.forceToParent(wrench_L[i]);
  }
  return total;
}

Eigen::VectorXd forwardDynamics(const ArticulationModel& model, const ArticulationState& state,
                                const Eigen::VectorXd& tau, const Vec3& g_W) {
  const ArticulationKinematics kin = kinematics(model, state);
  return massMatrix(model, kin).llt().solve(tau - biasForces(model, kin, g_W));
}

double kineticEnergy(const ArticulationModel& model, const ArticulationKinematics& kin) {
  double energy = 0.0;
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    energy += 0.5 * kin.V_L[i].dot(kin.I_L[i] * kin.V_L[i]);
  }
  return energy;
}

double potentialEnergy(const ArticulationModel& model, const ArticulationKinematics& kin, const Vec3& g_W) {
  double energy = 0.0;
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const MassProperties& mp = model.links[i].mass;
    const Placement& X = kin.X_WL[i];
    energy -= mp.mass * g_W.dot(X.p_PC + X.R_PC * mp.p_FC);
  }
  return energy;
}

double totalMass(const ArticulationModel& model) {
  double mass = 0.0;
  for (const ArticulatedLink& link : model.links) mass += link.mass.mass;
  return mass;
}

Vec3 centreOfMass(const ArticulationModel& model, const ArticulationKinematics& kin) {
  Vec3 first_moment = Vec3::Zero();
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const MassProperties& mp = model.links[i].mass;
    first_moment += mp.mass * (kin.X_WL[i].p_PC + kin.X_WL[i].R_PC * mp.p_FC);
  }
  return first_moment / totalMass(model);
}

Vec6 momentum_W(const ArticulationModel& model, const ArticulationKinematics& kin) {
  Vec6 total = Vec6::Zero();
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    total += kin.X_WL[i].forceToParent(kin.I_L[i] * kin.V_L[i]);
  }
  return total;
}

}  // namespace rigid_body_sim::core
