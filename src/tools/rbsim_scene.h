// rbsim's run of a world whose bodies list holds robots: a scene of free
// bodies and robots stepped together (docs/physics.md §11.9).
#pragma once

#include "rbsim_robot.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::tools {

/// Runs the config's bodies list as a scene (io::buildScene) and prints the
/// JSON line: the world's members, each entry of `bodies` in the config's
/// order, a robot's base link as its `final` with final.joints.NAME.position
/// and .velocity. The CSV has a row per body and robot, and a position and
/// a velocity column per robot joint (ROBOT/JOINT), filled on its robot's row.
int runScene(const io::SimConfig& config, const RunOptions& options);

}  // namespace rigid_body_sim::tools
