#include "rigid_body_sim/core/inertia.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
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

void validateInertia(const Mat3& I, const std::string& field, bool allow_zero) {
  if (!I.allFinite()) detail::fail(field, detail::str(I), "must be finite");
  const double scale = I.cwiseAbs().maxCoeff();
  // Relative tolerance for rounding: bodies on the boundary (a thin plate has
  // Izz = Ixx + Iyy exactly) must pass after a parallel-axis sum.
  const double tol = 1e-9 * scale;
  if ((I - I.transpose()).cwiseAbs().maxCoeff() > tol) detail::fail(field, detail::str(I), "must be symmetric");
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(I, Eigen::EigenvaluesOnly);
  const Vec3& m = eig.eigenvalues();  // ascending
  if (allow_zero ? m(0) < -tol : !(m(0) > tol)) {
    detail::fail(field, detail::str(I),
                 std::string("must be positive ") + (allow_zero ? "semi-definite" : "definite") +
                     " (smallest principal moment " + detail::str(m(0)) + " kg*m^2)");
  }
  if (m(0) + m(1) < m(2) - tol) {
    detail::fail(field, detail::str(I),
                 "violates the triangle inequality of principal moments: " + detail::str(m(0)) + " + " +
                     detail::str(m(1)) + " < " + detail::str(m(2)) + " kg*m^2 (no mass distribution has it)");
  }
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
