// rbsim's run of a world of free bodies alone (a body from --urdf, or a
// config's bodies list with no robot): the core's step for bodies, its
// trajectory CSV, its JSON line and summary, the bodies' devices
// (rbsim_sensors.h) written with --out, their velocity drivers commanded by
// the config's timeline (docs/rbsim.md).
#pragma once

#include <vector>

#include "rbsim_scene.h"
#include "rbsim_sensors.h"
#include "rigid_body_sim/io/timeline.h"
#include "rigid_body_sim/io/world.h"

namespace rigid_body_sim::tools {

/// Runs `world` (`listed`: from a config's bodies list, whose CSV names
/// each body and whose JSON has no top-level `final`) for
/// options.duration, its bodies' `devices` sampled and their drivers
/// commanded by `timeline` (its `body:` entries; any other is refused, a
/// ConfigError, said before the world's notes are) as the node does, and
/// prints the JSON line; returns the exit code.
int runBodies(io::World world, bool listed, const RunOptions& options, const std::vector<BodyDevices>& devices,
              std::vector<io::TimedCommand> timeline);

}  // namespace rigid_body_sim::tools
