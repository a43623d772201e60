// rbsim's run of a robot (a URDF with moving joints): its articulation
// stepped alone against the config's scene (docs/physics.md §11).
#pragma once

#include <string>

#include "rigid_body_sim/core/articulation.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::tools {

/// What the command line asks of a run.
struct RunOptions {
  double duration = 0.0;  ///< s
  std::string csv;        ///< "" for none
  long long every = 1;    ///< one CSV row every this many steps
  bool quiet = false;
};

/// Runs `model` with `config`'s settings and start (io::buildRobot) and
/// prints the JSON line: the one-body line's members, its base link as the
/// body, and final.joints.NAME.position and .velocity for every joint.
/// The CSV gains a position and a velocity column per joint.
int runRobot(const io::SimConfig& config, core::ArticulationModel model, const RunOptions& options);

}  // namespace rigid_body_sim::tools
