// The model: everything that does not change while the simulation runs.
//
// Following MuJoCo's mjModel/mjData split, a Model is built once from a
// ModelSpec (creation settings, as Jolt's BodyCreationSettings), validated on
// construction, and never modified; step() takes it by const reference.
#pragma once

#include <string>
#include <vector>

#include "rigid_body_sim/core/types.h"

namespace rigid_body_sim::core {

/// Velocity damping. Two forms, which add up:
///  - a decay rate k (1/s): v ← v·exp(−k Δt) each step, so v(t) = v₀ e^(−k t)
///    whatever Δt is (the notes' "v_{n+1} = α v_n" with α = e^(−k Δt));
///  - the notes' drag force f = −σ v (and τ = −σ_ω ω), integrated explicitly
///    like every other force, so its effect depends on Δt.
struct Damping {
  double linear_rate = 0.0;   ///< 1/s
  double angular_rate = 0.0;  ///< 1/s
  double linear_drag = 0.0;   ///< σ, N·s/m
  double angular_drag = 0.0;  ///< σ_ω, N·m·s/rad
};

/// Creation settings of one rigid body (what a URDF provides).
struct BodySpec {
  std::string name = "body";  ///< the URDF root link name
  double mass = 1.0;          ///< kg
  Vec3 p_LC = Vec3::Zero();   ///< centre of mass in the link frame L (m)
  /// Inertia about the centre of mass, axes of L (kg·m²).
  Mat3 I_C_L = Mat3::Identity();
};

/// Creation settings of the whole model.
struct ModelSpec {
  std::vector<BodySpec> bodies;
  double dt = 1e-3;                      ///< time step Δt (s)
  Vec3 gravity_W = Vec3(0.0, 0.0, -9.81);  ///< m/s², world frame
  Damping damping;
  /// Integrate the gyroscopic term −ω × (I ω) of Euler's equation. Off
  /// reproduces the notes exactly (ω_{n+1} = ω_n + Δt I⁻¹ τ), which is only
  /// right for bodies with isotropic inertia (spheres, cubes).
  bool gyroscopic = true;
};

/// One body as the integrator uses it: derived and validated quantities.
struct BodyModel {
  std::string name;
  double mass = 1.0;                      ///< kg
  double inv_mass = 1.0;                  ///< 1/kg
  Vec3 inertia_B = Vec3::Ones();          ///< principal moments, kg·m²
  Vec3 inv_inertia_B = Vec3::Ones();      ///< 1/(kg·m²)
  Vec3 p_LB = Vec3::Zero();               ///< B's origin (the centre of mass) in L (m)
  Quat q_LB = Quat::Identity();           ///< principal axes B in L
  Mat3 I_C_L = Mat3::Identity();          ///< inertia about the centre of mass in L axes, as given
};

class Model {
 public:
  /// Validates `spec` and derives the principal-axes form of every body.
  /// Throws std::invalid_argument whose message names the field and value.
  explicit Model(const ModelSpec& spec);

  const std::vector<BodyModel>& bodies() const { return bodies_; }
  const BodyModel& body(std::size_t i) const { return bodies_.at(i); }
  std::size_t bodyCount() const { return bodies_.size(); }
  double dt() const { return dt_; }
  const Vec3& gravity() const { return gravity_W_; }
  const Damping& damping() const { return damping_; }
  bool gyroscopic() const { return gyroscopic_; }
  /// Per-step decay factors α = e^(−k Δt) of the damping rates.
  double linearDecay() const { return linear_decay_; }
  double angularDecay() const { return angular_decay_; }

 private:
  std::vector<BodyModel> bodies_;
  double dt_;
  Vec3 gravity_W_;
  Damping damping_;
  bool gyroscopic_;
  double linear_decay_;
  double angular_decay_;
};

}  // namespace rigid_body_sim::core
