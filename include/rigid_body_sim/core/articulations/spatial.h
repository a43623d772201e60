// Spatial (6D) vectors for articulated bodies (docs/physics.md §11.2): a
// motion vector is [ω; v] (angular first, v the velocity of the frame's
// origin), a force vector [n; f] (moment about the frame's origin first).
// Both are expressed in one frame's axes. Eigen only.
#pragma once

#include "rigid_body_sim/core/bodies/geometry.h"
#include "rigid_body_sim/core/bodies/inertia.h"
#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

/// The placement of a child frame C in a parent frame P as a rotation matrix
/// and a translation (cheaper to apply many times than a quaternion).
struct Placement {
  Mat3 R_PC = Mat3::Identity();  ///< C's axes in P
  Vec3 p_PC = Vec3::Zero();      ///< C's origin in P (m)

  static Placement of(const Pose& X_PC) { return {X_PC.rotation.toRotationMatrix(), X_PC.translation}; }
  Placement operator*(const Placement& X_CD) const { return {R_PC * X_CD.R_PC, p_PC + R_PC * X_CD.p_PC}; }

  /// A motion vector given in P, re-expressed in C (about C's origin).
  Vec6 motionToChild(const Vec6& m_P) const {
    Vec6 out;
    out.head<3>() = R_PC.transpose() * m_P.head<3>();
    out.tail<3>() = R_PC.transpose() * (m_P.tail<3>() - p_PC.cross(m_P.head<3>()));
    return out;
  }
  /// A motion vector given in C (about C's origin), re-expressed in P.
  Vec6 motionToParent(const Vec6& m_C) const {
    Vec6 out;
    out.head<3>() = R_PC * m_C.head<3>();
    out.tail<3>() = R_PC * m_C.tail<3>() + p_PC.cross(out.head<3>());
    return out;
  }
  /// A force vector given in C (moment about C's origin), re-expressed in P.
  Vec6 forceToParent(const Vec6& f_C) const {
    Vec6 out;
    out.tail<3>() = R_PC * f_C.tail<3>();
    out.head<3>() = R_PC * f_C.head<3>() + p_PC.cross(out.tail<3>());
    return out;
  }
  /// A force vector given in P, re-expressed in C (moment about C's origin).
  Vec6 forceToChild(const Vec6& f_P) const {
    Vec6 out;
    out.head<3>() = R_PC.transpose() * (f_P.head<3>() - p_PC.cross(f_P.tail<3>()));
    out.tail<3>() = R_PC.transpose() * f_P.tail<3>();
    return out;
  }
  /// The 6×6 matrix of motionToChild, X = [Rᵀ 0; −Rᵀ[p]× Rᵀ]; its
  /// transpose is forceToParent's.
  Mat6 motionToChildMatrix() const {
    Mat6 X = Mat6::Zero();
    X.topLeftCorner<3, 3>() = R_PC.transpose();
    X.bottomRightCorner<3, 3>() = R_PC.transpose();
    X.bottomLeftCorner<3, 3>() = -R_PC.transpose() * skew(p_PC);
    return X;
  }
};

/// m₁ ×ₘ m₂, the derivative of motion vector m₂ in a frame moving with m₁.
inline Vec6 crossMotion(const Vec6& m1, const Vec6& m2) {
  Vec6 out;
  out.head<3>() = m1.head<3>().cross(m2.head<3>());
  out.tail<3>() = m1.head<3>().cross(m2.tail<3>()) + m1.tail<3>().cross(m2.head<3>());
  return out;
}

/// m ×_f f, the derivative of force vector f in a frame moving with m.
inline Vec6 crossForce(const Vec6& m, const Vec6& f) {
  Vec6 out;
  out.head<3>() = m.head<3>().cross(f.head<3>()) + m.tail<3>().cross(f.tail<3>());
  out.tail<3>() = m.head<3>().cross(f.tail<3>());
  return out;
}

/// A body's spatial inertia about its frame's origin O:
/// I = [I_O  [h]×; [h]×ᵀ  m𝟙] with h = m c (c the centre of mass in the
/// frame) and I_O = I_c + m (cᵀc 𝟙 − c cᵀ).
struct SpatialInertia {
  double mass = 0.0;        ///< kg
  Vec3 h = Vec3::Zero();    ///< first moment m c (kg·m)
  Mat3 I_O = Mat3::Zero();  ///< rotational inertia about O (kg·m²)

  static SpatialInertia of(const MassProperties& mp) {
    return {mp.mass, mp.mass * mp.p_FC, parallelAxis(mp.I_C_F, mp.mass, -mp.p_FC)};
  }
  /// The momentum of a body moving with twist m: [I_O ω + h × v; m v − h × ω].
  Vec6 operator*(const Vec6& m) const {
    Vec6 out;
    out.head<3>() = I_O * m.head<3>() + h.cross(m.tail<3>());
    out.tail<3>() = mass * m.tail<3>() - h.cross(m.head<3>());
    return out;
  }
  /// The same inertia about the parent's origin, in the parent's axes,
  /// given this body's frame C placed at X_PC: the first moment rotated and
  /// moved, I_O rotated and carried by the parallel-axis theorem through
  /// the centre of mass (Xᵀ I X for the matrices, in about 60 flops).
  SpatialInertia toParent(const Placement& X_PC) const {
    SpatialInertia out;
    out.mass = mass;
    const Vec3 h_rot = X_PC.R_PC * h;
    out.h = h_rot + mass * X_PC.p_PC;
    out.I_O = X_PC.R_PC * I_O * X_PC.R_PC.transpose();
    // I about P's origin = I about C's origin + m ([c_P]×ᵀ[c_P]× − [c_C]×ᵀ[c_C]×)
    // with c_C = h/m (from C's origin) and c_P = p + c_C: written with h
    // so that a massless body adds nothing.
    const Vec3& p = X_PC.p_PC;
    const double cross = mass * p.squaredNorm() + 2.0 * p.dot(h_rot);
    out.I_O.diagonal().array() += cross;
    out.I_O -= mass * p * p.transpose() + p * h_rot.transpose() + h_rot * p.transpose();
    return out;
  }
  SpatialInertia& operator+=(const SpatialInertia& other) {
    mass += other.mass;
    h += other.h;
    I_O += other.I_O;
    return *this;
  }
  Mat6 matrix() const {
    Mat6 I;
    I.topLeftCorner<3, 3>() = I_O;
    I.topRightCorner<3, 3>() = skew(h);
    I.bottomLeftCorner<3, 3>() = skew(h).transpose();
    I.bottomRightCorner<3, 3>() = mass * Mat3::Identity();
    return I;
  }
};

}  // namespace rigid_body_sim::core
