// What every fuzzer does with a body or config the loader accepted: build
// the model (its validation is part of what is fuzzed) and take a few steps,
// which must stay finite. A refusal is an exception, never a crash.
#pragma once

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/core/step/step.h"
#include "rigid_body_sim/io/scene_loader.h"

namespace rigid_body_sim::fuzz {

inline void stepAFew(const core::ModelSpec& spec, const core::State* start = nullptr) {
  try {
    const core::Model model(spec);
    core::State state = start != nullptr ? *start : core::restState(model);
    core::Workspace ws;
    ws.threads = 1;
    for (int n = 0; n < 5; ++n) core::step(model, state, {}, &ws);
    for (const core::BodyState& b : state.bodies) {
      if (!b.p_WB.allFinite() || !b.v_WB.allFinite() || !b.q_WB.coeffs().allFinite() || !b.w_B.allFinite()) {
        std::abort();  // the guard must never let this through
      }
    }
  } catch (const std::invalid_argument&) {
    // refused by the model's validation: fine
  }
}

/// The devices and drives of a robot the scene loader took (from a config's
/// keys or a URDF's Gazebo markup): every sensor's settings pass the core's
/// checks (so nothing it publishes is non-finite), its rate and pose are in
/// range, the devices fit the memory budget, and every drive's limits let a
/// zero command stay zero. Anything else is a bug: abort.
inline void checkDevices(const io::SceneSetup& setup, std::uintmax_t budget) {
  std::uintmax_t bytes = 0;
  const auto rate = [](double hz) { return hz >= core::ranges::kMinRate && hz <= core::ranges::kMaxPublishRate; };
  for (const io::RobotSensors& s : setup.sensors) {
    for (const io::RobotLidar& l : s.lidars) {
      core::checkLidar(l.entry.settings);  // throws: a bug, since the loader took it
      if (!rate(l.entry.rate) || !(l.X_LS.translation.norm() < 1e4)) std::abort();
    }
    for (const io::RobotCamera& c : s.cameras) {
      core::checkDepthCamera(c.entry.settings);
      if (!rate(c.entry.rate) || !(c.X_LS.translation.norm() < 1e4)) std::abort();
    }
    bytes += s.bytes;
  }
  if (bytes > budget) std::abort();
  for (const io::RobotControls& c : setup.controls) {
    for (const core::DiffDrive& d : c.drives) {
      const core::DiffDriveSettings& k = d.spec().settings;
      if (!(k.max_wheel_torque > 0.0)) std::abort();
      for (const core::TwistLimiter* l : {&k.linear, &k.angular}) {
        if (l->has_velocity_limits && !(l->min_velocity <= 0.0 && l->max_velocity >= 0.0)) std::abort();
        if (l->has_acceleration_limits && !(l->min_acceleration <= 0.0 && l->max_acceleration >= 0.0)) std::abort();
        if (l->has_jerk_limits && !(l->min_jerk <= 0.0 && l->max_jerk >= 0.0)) std::abort();
      }
    }
  }
}

}  // namespace rigid_body_sim::fuzz
