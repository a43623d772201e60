// A velocity driver (docs/physics.md §10.4): a force and torque controller
// that drives a body toward a commanded twist while gravity, contacts and
// friction still act, as a robot's motors would; not a teleport. ROS-free;
// the node feeds it from `cmd_vel`, and both it and rbsim from a timeline.
#pragma once

#include <cstddef>
#include <string>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/loads.h"

namespace rigid_body_sim::core {

/// Config `cmd_vel` (`bodies[i].cmd_vel`).
struct DriverSettings {
  double max_force = 10.0;               ///< N: |F| at most
  double max_torque = 5.0;               ///< N·m: |τ| at most
  double linear_gain = 50.0;             ///< 1/s: F = m (k_p e + k_i ∫e), e the velocity error
  double linear_integral_gain = 625.0;   ///< 1/s² (k_p²/4: critically damped)
  double angular_gain = 50.0;            ///< 1/s: τ = I (k_p e + k_i ∫e)
  double angular_integral_gain = 625.0;  ///< 1/s²
  double max_linear_speed = 1.0;         ///< m/s: faster commands are clipped to it
  double max_angular_speed = 2.0;        ///< rad/s
  double timeout = 0.5;                  ///< s of sim time a command is held; 0: until replaced
  bool planar = false;                   ///< x, y and yaw only, in the body's heading (a ground robot)
};

/// Throws std::invalid_argument naming `key`.FIELD.
void validateDriver(const DriverSettings& s, const std::string& key);

class VelocityDriver {
 public:
  explicit VelocityDriver(const DriverSettings& settings) : settings_(settings) {}

  /// A command at sim time t: the root link's velocity v_L (m/s) and
  /// angular velocity w_L (rad/s) in its own axes (planar: x, y and the
  /// yaw rate z only). Clipped to the speed limits, never refused; true if clipped.
  bool command(const Vec3& v_L, const Vec3& w_L, double t);

  /// The load of the step [t, t + h) for `body` in state `s`: zero before the
  /// first command and after the timeout (which also clears the integrals).
  BodyLoad load(const BodyModel& body, const BodyState& s, double t, double h);
  /// The same for a link in state `link` carrying `mass` (kg) with inertia
  /// I_C_L (kg·m², about its centre of mass, in the link's axes): a force
  /// through that centre and a torque.
  BodyLoad load(const LinkState& link, double mass, const Mat3& I_C_L, double t, double h);

  /// Whether a command is in force at t.
  bool active(double t) const;
  const DriverSettings& settings() const { return settings_; }

 private:
  DriverSettings settings_;
  bool commanded_ = false;
  double received_ = 0.0;
  Vec3 v_cmd_ = Vec3::Zero(), w_cmd_ = Vec3::Zero();
  Vec3 v_integral_ = Vec3::Zero(), w_integral_ = Vec3::Zero();  ///< ∫e dt, in the frame the error is taken in
};

/// Adds `driver`'s load on free body i of `model` at `state` for the step
/// [t, t + h) to loads[i], first sizing `loads` to the model's bodies (each
/// zero) if it is empty and the load is not zero: how the node and rbsim
/// alike drive a body by its cmd_vel.
void addDriverLoad(VelocityDriver& driver, const Model& model, const State& state, std::size_t i, double t, double h,
                   Loads& loads);

/// The whole robot at `kin` as one body, about its base link's origin in
/// the base's axes: each link's inertia carried there (§11.3's composite).
SpatialInertia robotInertia_B(const ArticulationModel& model, const ArticulationKinematics& kin);

/// The driver's load on a robot's floating base (`cmd_vel` on a robot):
/// the whole robot at `kin` taken as one body (its mass, centre of mass and
/// inertia about it, with its joints as they are), the error on the base
/// link's twist; as a wrench on the base link in its axes, moment about
/// its origin (ArticulationLoads::wrench_L[0]: [moment; force]).
Vec6 baseLoad(VelocityDriver& driver, const ArticulationModel& model, const ArticulationKinematics& kin, double t,
              double h);

}  // namespace rigid_body_sim::core
