// Mass properties: point-mass inertia, the parallel-axis theorem, lumping
// rigidly joined parts, and the physical validity of an inertia tensor.
#pragma once

#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

/// Mass, centre of mass and inertia of a rigid part, all in one frame F.
struct MassProperties {
  double mass = 0.0;          ///< kg
  Vec3 p_FC = Vec3::Zero();   ///< centre of mass C in F (m)
  Mat3 I_C_F = Mat3::Zero();  ///< inertia about C, axes of F (kg·m²)
};

/// Inertia of point masses mᵢ at rᵢ about their centre of mass (docs/physics.md
/// §2): I = Σ mᵢ (rᵢᵀrᵢ 𝐈 − rᵢrᵢᵀ), rᵢ measured from the
/// centre of mass. Positions may be given in any frame; they are re-centred.
MassProperties pointMassProperties(const std::vector<double>& masses, const std::vector<Vec3>& positions);

/// Parallel-axis theorem: inertia about a point O displaced by d = p_O − p_C
/// from the centre of mass C: I_O = I_C + m (dᵀd 𝐈 − d dᵀ).
Mat3 parallelAxis(const Mat3& I_C, double mass, const Vec3& d);

/// Combined mass properties of rigidly joined parts expressed in one frame.
MassProperties combine(const std::vector<MassProperties>& parts);

/// Checks that I is an inertia tensor a real mass distribution can have:
/// finite, symmetric, positive definite (positive semi-definite if
/// allow_zero), and its principal moments meeting the triangle inequality
/// I₁ + I₂ ≥ I₃ and its rotations. Throws std::invalid_argument naming
/// `field` and the offending values.
void validateInertia(const Mat3& I, const std::string& field, bool allow_zero = false);

/// The physically valid inertia nearest to a tensor that is not one (a CAD
/// export's rounding: principal moments 0.001, 0.001, 0.01, or −3.5e-8).
struct InertiaRepair {
  Mat3 I = Mat3::Zero();         ///< the nearest valid tensor (the input itself when it was valid)
  Vec3 moments = Vec3::Zero();   ///< the input's principal moments, ascending (kg·m²)
  Vec3 repaired = Vec3::Zero();  ///< the result's, in the same order (kg·m²)
  double change = 0.0;           ///< ‖I − input‖ in the Frobenius norm (kg·m²)
  bool changed = false;          ///< false: the input passed validateInertia(allow_zero = true)
};

/// The valid tensor nearest to a finite symmetric `I` in the Frobenius norm
/// (docs/physics.md §2.1): same principal axes, the principal moments
/// projected onto the cone of the triangle inequality (which also makes
/// them ≥ 0). A tensor validateInertia accepts (allow_zero) comes back
/// unchanged, bit for bit, unless a moment is below `least` × the largest:
/// such a moment is raised to it, in a valid tensor or a repaired one
/// (raising the smallest keeps the inequality), so that a body can be made
/// of it (0: the exact projection, which may leave a moment of 0). Throws std::invalid_argument naming `field` for a
/// tensor that is not finite.
InertiaRepair nearestValidInertia(const Mat3& I, const std::string& field, double least = 0.0);

/// The inertia about its centre of a solid sphere of water (1000 kg/m³)
/// of mass m: (2/5) m r², r = (3m / 4πρ)^(1/3). What a part with mass but no
/// inertia (a point mass, which a rigid body being simulated cannot be) is
/// given (§2.1).
Mat3 waterSphereInertia(double mass);

/// Whether a part of mass m > 0 has, to rounding, no inertia at all: its
/// largest principal moment below 1e-9 of waterSphereInertia's.
bool pointMass(double mass, const Mat3& I);

/// Principal axes: I = R diag(moments) Rᵀ with R a proper rotation. When I
/// is already diagonal, R is exactly the identity (no eigen-solver rounding).
struct PrincipalAxes {
  Vec3 moments;  ///< kg·m²
  Quat q_FP;     ///< orientation of the principal frame P in the frame F of I
};
PrincipalAxes principalAxes(const Mat3& I);

}  // namespace rigid_body_sim::core
