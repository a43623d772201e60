// The robots the controller suites drive (joint_control_test,
// robot_control_test): a pendulum, and a robot alone in a scene stepped as
// the node and rbsim step one.
#pragma once

#include "../articulations/articulation_models.h"
#include "rigid_body_sim/core/articulations/articulation_step.h"
#include "rigid_body_sim/core/articulations/scene.h"

namespace rigid_body_sim::test {

using core::ArticulationLoads;
using core::ModelSpec;
using core::Scene;
using core::SceneState;
using core::SceneWorkspace;

inline constexpr double kStep = 1e-3;  ///< s

/// A 1 kg point-like bob on a 0.5 m massless arm about y, hinge at the
/// origin: gravity's torque about the hinge at angle q is m g l sin q (q
/// from hanging straight down, positive turning the bob toward +x... its
/// sign read off the model below).
inline ArticulationModel pendulum(double effort_limit) {
  ArticulationModel model = oneJoint(JointType::Revolute, "bob", "hinge", Vec3::Zero(), Vec3::UnitY());
  ArticulatedLink& bob = model.links[1];
  bob.limits.lower = -3.0;
  bob.limits.upper = 3.0;
  bob.limits.effort = effort_limit;
  bob.mass.mass = 1.0;
  bob.mass.p_FC = Vec3(0.0, 0.0, -0.5);
  bob.mass.I_C_F = 1e-4 * Mat3::Identity();
  core::checkArticulation(model);
  return model;
}

/// `model` alone in a scene with gravity `g` and no ground, stepped as the
/// node and rbsim step a robot (stepScene).
struct Alone {
  Scene scene;
  SceneState state;
  SceneWorkspace ws;

  Alone(const ArticulationModel& model, const Vec3& g)
      : scene(spec(g), {{"robot", model}}), state(core::sceneState(scene, {}, {core::restState(model)})) {}
  static ModelSpec spec(const Vec3& g) {
    ModelSpec s;
    s.dt = kStep;
    s.gravity_W = g;
    return s;
  }
  core::ArticulationState& robot() { return state.robots[0]; }
  void step(const ArticulationLoads& loads) { core::stepScene(scene, state, {{}, {loads}}, ws); }
};

}  // namespace rigid_body_sim::test
