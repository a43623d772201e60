// A robot alone in a world, stepped by the one step (core::stepScene) as
// the node and rbsim step it: the articulation tests' way to advance one.
#pragma once

#include <utility>
#include <vector>

#include "rigid_body_sim/core/articulations/scene.h"

namespace rigid_body_sim::test {

/// A scene of `model` alone under g_W at steps of h, with `limits`; its
/// scene (ground, settings) from `spec` (its bodies ignored), none by
/// default.
class LoneRobot {
 public:
  LoneRobot(const core::ArticulationModel& model, const core::Vec3& g_W, double h, const core::SpeedLimits& limits = {},
            core::ModelSpec spec = {})
      : scene_(withSettings(std::move(spec), g_W, h, limits), {{"robot", model}}),
        now_(core::sceneState(scene_, {}, {core::restState(model)})) {}

  /// One step of `state` (taken in, given back) under `loads`; false when
  /// the guard put it back (§11.7).
  bool step(core::ArticulationState& state, const core::ArticulationLoads& loads = {}) {
    now_.robots[0] = std::move(state);  // its links are placed by the step
    try {
      core::stepScene(scene_, now_, {{}, {loads}}, ws_);
    } catch (...) {
      state = now_.robots[0];
      throw;
    }
    state = now_.robots[0];
    return ws_.robot_diverged[0] == 0;
  }

  const core::Scene& scene() const { return scene_; }
  /// The last step's contacts (links by their body index) and outputs.
  const core::SceneWorkspace& workspace() const { return ws_; }
  core::SceneWorkspace& workspace() { return ws_; }

 private:
  static core::ModelSpec withSettings(core::ModelSpec spec, const core::Vec3& g_W, double h,
                                      const core::SpeedLimits& limits) {
    spec.bodies.clear();
    spec.gravity_W = g_W;
    spec.dt = h;
    spec.limits = limits;
    return spec;
  }

  core::Scene scene_;
  core::SceneState now_;
  core::SceneWorkspace ws_;
};

/// One step of `model` alone (a LoneRobot made for it).
inline bool stepAlone(const core::ArticulationModel& model, core::ArticulationState& state,
                      const core::ArticulationLoads& loads, const core::Vec3& g_W, double h,
                      const core::SpeedLimits& limits = {}) {
  return LoneRobot(model, g_W, h, limits).step(state, loads);
}

}  // namespace rigid_body_sim::test
