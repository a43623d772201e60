// A stiff body's normal impulses in one exact solve (docs/physics.md §5.5).
#include "stiff_body.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cmath>

namespace rigid_body_sim::core::detail {
namespace {

constexpr int kMax = kMaxStiffBodyContacts;
using Rows = Eigen::Matrix<double, Eigen::Dynamic, 6, 0, 3 * kMax, 6>;
using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3 * kMax, 3 * kMax>;
using Column = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3 * kMax, 1>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

/// The side of a contact that moves, when exactly one does.
const SolverContact::Side* movingSide(const SolverContact& c, int& body, double& sign) {
  const bool a = c.a.inv_mass > 0.0, o = c.other >= 0 && c.o.inv_mass > 0.0;
  if (a == o) return nullptr;
  body = a ? c.body : c.other;
  sign = a ? 1.0 : -1.0;  // the contact's velocity is body's minus other's
  return a ? &c.a : &c.o;
}

/// The active set over least-norm solves of K: λ ≥ 0, u = b + K λ at or
/// above `target`, and at it where λ > 0. Starts from the contacts that
/// push in `start` or are below their target; drops the most negative
/// impulse, adds the most violated contact, until neither is left (at most
/// 2n + 2 rounds). False if it does not settle.
bool solvePushes(const Square& K, const Column& b, const Column& target, const Column& start, double tolerance,
                 Column& solved) {
  const int n = static_cast<int>(b.size());
  std::array<bool, kMax> active{};
  for (int i = 0; i < n; ++i) active[i] = start(i) > 0.0 || b(i) + K.row(i).dot(start) < target(i) - tolerance;
  solved = Column::Zero(n);
  for (int round = 0; round < 2 * n + 2; ++round) {
    std::array<int, kMax> index{};
    int m = 0;
    for (int i = 0; i < n; ++i) {
      if (active[i]) index[m++] = i;
    }
    Square K_A(m, m);
    Column rhs(m);
    for (int r = 0; r < m; ++r) {
      rhs(r) = target(index[r]) - b(index[r]);
      for (int c = 0; c < m; ++c) K_A(r, c) = K(index[r], index[c]);
    }
    solved.setZero();
    if (m > 0) {
      Eigen::CompleteOrthogonalDecomposition<Square> cod(K_A);
      const Column x = cod.solve(rhs);  // least-norm: the load spread where K leaves it open
      if (!x.allFinite()) return false;
      for (int r = 0; r < m; ++r) solved(index[r]) = x(r);
    }
    int worst = -1;
    double most = 0.0;
    for (int i = 0; i < n; ++i) {  // an impulse that pulls
      if (active[i] && solved(i) < most) most = solved(i), worst = i;
    }
    if (worst >= 0) {
      active[worst] = false;
      continue;
    }
    const Column u = b + K * solved;
    most = -tolerance;
    for (int i = 0; i < n; ++i) {  // a free contact below its target
      if (!active[i] && u(i) - target(i) < most) most = u(i) - target(i), worst = i;
    }
    if (worst >= 0) {
      active[worst] = true;
      continue;
    }
    // The active rows must be met: K_A may be singular with targets it cannot reach.
    for (int i = 0; i < n; ++i) {
      if (active[i] && std::abs(u(i) - target(i)) > tolerance) return false;
    }
    return true;
  }
  return false;
}

/// M⁻¹ of a body, world axes.
Eigen::Matrix<double, 6, 6> inverseMass(double inv_mass, const Mat3& inv_I_W) {
  Eigen::Matrix<double, 6, 6> inv_M = Eigen::Matrix<double, 6, 6>::Zero();
  inv_M.topLeftCorner<3, 3>() = inv_mass * Mat3::Identity();
  inv_M.bottomRightCorner<3, 3>() = inv_I_W;
  return inv_M;
}

}  // namespace

int stiffBody(const SolverSettings& settings, const std::vector<Mat3>& inverse_inertias_W, const SolverContact* begin,
              const SolverContact* end) {
  if (begin == end || end - begin > kMax) return -1;
  int body = -1;
  double arm2 = 0.0, inv_mass = 0.0;
  for (const SolverContact* c = begin; c != end; ++c) {
    int b = -1;
    double sign = 0.0;
    const SolverContact::Side* side = movingSide(*c, b, sign);
    if (side == nullptr || (body >= 0 && b != body)) return -1;  // two bodies, or one that moves nothing
    body = b;
    inv_mass = side->inv_mass;
    // |r × n|² + |r × t₁|² + |r × t₂|² = 2 |r|²
    arm2 = std::max(arm2, 0.5 * (side->rn.squaredNorm() + side->rt1.squaredNorm() + side->rt2.squaredNorm()));
  }
  const Mat3& inv_I = inverse_inertias_W[body];
  const double turn = Eigen::SelfAdjointEigenSolver<Mat3>(inv_I, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
  return turn * arm2 > settings.stiff_body_ratio * inv_mass ? body : -1;
}

namespace {

/// The pushing contacts held still, friction and all, in one least-norm
/// solve of their 3 rows each: taken when every one then pushes and lies
/// in its cone (a resting or rolling-to-rest stiff body; a sliding one is
/// left to the sweeps).
void stickPushingContacts(const SolverSettings& settings, const Mat3& inverse_inertia_W, int body, SolverContact* begin,
                          SolverContact* end, std::vector<BodyVelocity>& vel) {
  std::array<int, kMax> pushing{};
  int m = 0;
  for (SolverContact* c = begin; c != end; ++c) {
    if (c->normal_impulse > 0.0) pushing[m++] = static_cast<int>(c - begin);
  }
  if (m == 0) return;
  Rows J(3 * m, 6);
  Column error(3 * m);
  double inv_mass = 0.0;
  const Vec6 twist = (Vec6() << vel[body].v_W, vel[body].w_W).finished();
  for (int i = 0; i < m; ++i) {
    const SolverContact& c = begin[pushing[i]];
    int b = -1;
    double sign = 0.0;
    const SolverContact::Side* side = movingSide(c, b, sign);
    inv_mass = side->inv_mass;
    J.row(3 * i) << sign * c.normal_W.transpose(), sign * side->rn.transpose();
    J.row(3 * i + 1) << sign * c.tangent1_W.transpose(), sign * side->rt1.transpose();
    J.row(3 * i + 2) << sign * c.tangent2_W.transpose(), sign * side->rt2.transpose();
    error.segment<3>(3 * i) = Vec3(c.target_normal_velocity, 0.0, 0.0) - J.middleRows<3>(3 * i) * twist;
  }
  const Rows JM = J * inverseMass(inv_mass, inverse_inertia_W);
  const Square K = JM * J.transpose();
  Eigen::CompleteOrthogonalDecomposition<Square> cod(K);
  const Column change = cod.solve(error);
  if (!change.allFinite() || (K * change - error).lpNorm<Eigen::Infinity>() > settings.velocity_tolerance) return;
  for (int i = 0; i < m; ++i) {
    const SolverContact& c = begin[pushing[i]];
    const double normal = c.normal_impulse + change(3 * i);
    if (normal < 0.0 || (c.tangent_impulse + change.segment<2>(3 * i + 1)).norm() > c.friction * normal) return;
  }
  for (int i = 0; i < m; ++i) {
    SolverContact& c = begin[pushing[i]];
    c.normal_impulse += change(3 * i);
    c.tangent_impulse += change.segment<2>(3 * i + 1);
  }
  const Vec6 dv = JM.transpose() * change;
  vel[body].v_W += dv.head<3>();
  vel[body].w_W += dv.tail<3>();
}

}  // namespace

bool solveStiffBodyNormals(const SolverSettings& settings, const Mat3& inverse_inertia_W, int body,
                           SolverContact* begin, SolverContact* end, std::vector<BodyVelocity>& vel) {
  const int n = static_cast<int>(end - begin);
  // The normal rows J (n, r × n, times the side's sign), K = J M⁻¹ Jᵀ, and
  // b, the normal velocities with no normal impulse: u = b + K λ.
  Rows J(n, 6);
  Column lambda(n), target(n);
  double inv_mass = 0.0;
  for (int i = 0; i < n; ++i) {
    const SolverContact& c = begin[i];
    int b = -1;
    double sign = 0.0;
    const SolverContact::Side* side = movingSide(c, b, sign);
    J.row(i) << sign * c.normal_W.transpose(), sign * side->rn.transpose();
    inv_mass = side->inv_mass;
    lambda(i) = c.normal_impulse;
    target(i) = c.target_normal_velocity;
  }
  const Rows JM = J * inverseMass(inv_mass, inverse_inertia_W);
  const Square K = JM * J.transpose();
  const Vec6 twist = (Vec6() << vel[body].v_W, vel[body].w_W).finished();
  const Column b = J * twist - K * lambda;
  Column solved;
  if (!solvePushes(K, b, target, lambda, settings.velocity_tolerance, solved)) return false;
  const Column change = solved - lambda;
  for (int i = 0; i < n; ++i) begin[i].normal_impulse = solved(i);
  const Vec6 dv = JM.transpose() * change;  // M⁻¹ Jᵀ Δλ
  vel[body].v_W += dv.head<3>();
  vel[body].w_W += dv.tail<3>();
  stickPushingContacts(settings, inverse_inertia_W, body, begin, end, vel);
  return true;
}

void correctStiffBody(const BodyModel& model, BodyState& state, int body, const std::vector<Contact>& contacts,
                      const std::vector<int>& indices, double slop, double tolerance) {
  const int n = static_cast<int>(indices.size());
  if (n == 0 || n > kMax) return;
  Rows J(n, 6);
  Column depth(n), target = Column::Constant(n, -slop);
  for (int i = 0; i < n; ++i) {
    const Contact& c = contacts[indices[i]];
    const bool own = c.body == body;  // else the body is the other side: the rows change sign
    const double sign = own ? 1.0 : -1.0;
    const Vec3& r = own ? c.r_W : c.r_other_W;
    J.row(i) << sign * c.normal_W.transpose(), sign * r.cross(c.normal_W).transpose();
    depth(i) = c.predicted_separation;
  }
  const Mat3 inv_I = worldInverseInertia(model, state.q_WB);
  const Rows JM = J * inverseMass(model.inv_mass, inv_I);
  const Square K = JM * J.transpose();
  Column solved;
  if (!solvePushes(K, depth, target, Column::Zero(n), tolerance, solved)) return;
  const Vec6 dx = JM.transpose() * solved;  // M⁻¹ Jᵀ λ: a translation and a turn
  if (!dx.allFinite()) return;
  state.p_WB += dx.head<3>();
  const Vec3 half_turn = 0.5 * dx.tail<3>();
  state.q_WB = Quat(1.0, half_turn.x(), half_turn.y(), half_turn.z()) * state.q_WB;
  state.q_WB.normalize();
}

}  // namespace rigid_body_sim::core::detail
