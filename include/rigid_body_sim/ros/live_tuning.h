// Live tuning: what a ~physics request (dynamic_reconfigure, cfg/Physics.cfg)
// changes. The model's settings (gravity, the surface, damping) go all or
// none through core::Simulation::retune, validated as a config is; the
// node's (~realtime_factor, ~publish_rate) each checked as its parameter is
// at start. A value refused is put back in the request to the one in force,
// so the server shows what holds. Plain functions, tested without a master;
// the server itself is the node's (reconfigure.cpp).
#pragma once

#include <string>
#include <vector>

#include "rigid_body_sim/PhysicsConfig.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/ros/params.h"

namespace rigid_body_sim::node {

/// The settings ~physics shows: the model's and the node's as they are now.
PhysicsConfig physicsNow(const core::Model& model, const NodeSettings& settings, bool paused);

/// What applying a request changed, and what it refused.
struct TuningResult {
  bool model = false;                ///< the model was retuned (every body woke)
  bool realtime_factor = false;      ///< settings.realtime_factor changed: the pacing starts again from now
  bool publish_rate = false;         ///< settings.publish_rate was set
  std::vector<std::string> refused;  ///< a message per refused group, naming the key
};

/// Applies `config` to `sim` and `settings` between steps (its `paused`
/// is the caller's). `paused` is only shown back where a value is put back.
TuningResult applyTuning(PhysicsConfig& config, core::Simulation& sim, NodeSettings& settings, bool paused);

}  // namespace rigid_body_sim::node
