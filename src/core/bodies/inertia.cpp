#include "rigid_body_sim/core/bodies/inertia.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "validate.h"

namespace rigid_body_sim::core {

MassProperties pointMassProperties(const std::vector<double>& masses, const std::vector<Vec3>& positions) {
  if (masses.size() != positions.size()) {
    throw std::invalid_argument("point masses: " + std::to_string(masses.size()) + " masses but " +
                                std::to_string(positions.size()) + " positions");
  }
  MassProperties mp;
  for (std::size_t i = 0; i < masses.size(); ++i) {
    mp.mass += masses[i];
    mp.p_FC += masses[i] * positions[i];
  }
  if (!(mp.mass > 0.0)) detail::fail("point masses: total mass", detail::str(mp.mass), "must be > 0 kg");
  mp.p_FC /= mp.mass;
  for (std::size_t i = 0; i < masses.size(); ++i) {
    const Vec3 r = positions[i] - mp.p_FC;  // rᵢ from the centre of mass
    mp.I_C_F += masses[i] * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }
  return mp;
}

Mat3 parallelAxis(const Mat3& I_C, double mass, const Vec3& d) {
  return I_C + mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
}

MassProperties combine(const std::vector<MassProperties>& parts) {
  MassProperties total;
  for (const auto& p : parts) {
    total.mass += p.mass;
    total.p_FC += p.mass * p.p_FC;
  }
  if (total.mass > 0.0) total.p_FC /= total.mass;
  for (const auto& p : parts) total.I_C_F += parallelAxis(p.I_C_F, p.mass, p.p_FC - total.p_FC);
  return total;
}

namespace {

/// The rounding a valid tensor may carry: bodies on the boundary (a thin
/// plate has Izz = Ixx + Iyy exactly) must pass after a parallel-axis sum.
double roundingTolerance(const Mat3& I) { return 1e-9 * I.cwiseAbs().maxCoeff(); }

bool symmetric(const Mat3& I, double tol) { return (I - I.transpose()).cwiseAbs().maxCoeff() <= tol; }

/// Ascending principal moments m that meet the triangle inequality (and so are ≥ 0).
bool triangle(const Vec3& m, double tol) { return m(0) >= -tol && m(0) + m(1) >= m(2) - tol; }

}  // namespace

void validateInertia(const Mat3& I, const std::string& field, bool allow_zero) {
  if (!I.allFinite()) detail::fail(field, detail::str(I), "must be finite");
  const double tol = roundingTolerance(I);
  if (!symmetric(I, tol)) detail::fail(field, detail::str(I), "must be symmetric");
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(I, Eigen::EigenvaluesOnly);
  const Vec3& m = eig.eigenvalues();  // ascending
  if (allow_zero ? m(0) < -tol : !(m(0) > tol)) {
    detail::fail(field, detail::str(I),
                 std::string("must be positive ") + (allow_zero ? "semi-definite" : "definite") +
                     " (smallest principal moment " + detail::str(m(0)) + " kg*m^2)");
  }
  if (!triangle(m, tol)) {
    detail::fail(field, detail::str(I),
                 "violates the triangle inequality of principal moments: " + detail::str(m(0)) + " + " +
                     detail::str(m(1)) + " < " + detail::str(m(2)) + " kg*m^2 (no mass distribution has it)");
  }
}

namespace {

/// The point of the cone {m : mₐ + m_b ≥ m_c for every order} nearest to m
/// (§2.1): the cone is three half-spaces through the origin, so the nearest
/// point is m projected onto the span of one of its faces (none, one or
/// two active constraints, or the apex); of those projections that lie in
/// the cone, the nearest is the answer.
Vec3 projectOntoTriangleCone(const Vec3& m) {
  const Mat3 A = (Mat3() << 1, 1, -1, 1, -1, 1, -1, 1, 1).finished();  // rows: aᵢ·m ≥ 0
  const double tol = 1e-12 * m.cwiseAbs().maxCoeff();
  Vec3 best = Vec3::Zero();  // the apex: in the cone whatever m is
  double best_distance = m.norm();
  for (int set = 0; set < 7; ++set) {  // the subsets of the three constraints but all three
    Eigen::Matrix<double, Eigen::Dynamic, 3> active(0, 3);
    for (int i = 0; i < 3; ++i) {
      if ((set >> i) & 1) {
        active.conservativeResize(active.rows() + 1, Eigen::NoChange);
        active.row(active.rows() - 1) = A.row(i);
      }
    }
    Vec3 y = m;
    if (active.rows() > 0) {
      const Eigen::MatrixXd gram = active * active.transpose();
      y -= active.transpose() * gram.ldlt().solve(active * m);
    }
    if ((A * y).minCoeff() < -tol) continue;
    const double distance = (y - m).norm();
    if (distance < best_distance) {
      best = y;
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace

InertiaRepair nearestValidInertia(const Mat3& I, const std::string& field, double least) {
  if (!I.allFinite()) detail::fail(field, detail::str(I), "must be finite");
  InertiaRepair out;
  out.I = I;
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (I + I.transpose()));
  out.moments = eig.eigenvalues();
  out.repaired = out.moments;
  const double tol = roundingTolerance(I);
  const bool valid = symmetric(I, tol) && triangle(out.moments, tol);
  if (valid && out.moments(0) >= least * out.moments(2)) return out;
  out.repaired = valid ? out.moments : projectOntoTriangleCone(out.moments);
  out.repaired = out.repaired.cwiseMax(least * out.repaired.maxCoeff());
  const Mat3& R = eig.eigenvectors();
  out.I = R * out.repaired.asDiagonal() * R.transpose();
  out.I = 0.5 * (out.I + out.I.transpose());
  out.change = (out.I - I).norm();
  out.changed = true;
  return out;
}

Mat3 waterSphereInertia(double mass) {
  constexpr double kWater = 1000.0;  // kg/m³
  const double r = std::cbrt(3.0 * mass / (4.0 * M_PI * kWater));
  return (0.4 * mass * r * r) * Mat3::Identity();
}

bool pointMass(double mass, const Mat3& I) {
  return mass > 0.0 && I.cwiseAbs().maxCoeff() <= 1e-9 * waterSphereInertia(mass)(0, 0);
}

PrincipalAxes principalAxes(const Mat3& I) {
  PrincipalAxes pa;
  if (I(0, 1) == 0.0 && I(0, 2) == 0.0 && I(1, 2) == 0.0 && I(1, 0) == 0.0 && I(2, 0) == 0.0 && I(2, 1) == 0.0) {
    pa.moments = I.diagonal();
    pa.q_FP = Quat::Identity();
    return pa;
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(I);
  Mat3 R = eig.eigenvectors();
  if (R.determinant() < 0.0) R.col(2) = -R.col(2);  // a proper rotation
  pa.moments = eig.eigenvalues();
  pa.q_FP = Quat(R).normalized();
  return pa;
}

}  // namespace rigid_body_sim::core
