// rbsim's run of a world of bodies and robots, or of one robot: a scene
// stepped as the node steps it (docs/physics.md §11.9).
#pragma once

#include <string>
#include <vector>

#include "rbsim_sensors.h"
#include "rigid_body_sim/io/scene_loader.h"

namespace rigid_body_sim::tools {

/// What the command line asks of a run.
struct RunOptions {
  double duration = 0.0;  ///< s
  std::string csv;        ///< "" for none
  long long every = 1;    ///< one CSV row every this many steps
  bool quiet = false;
  /// "" for none: each drive's odometry, ROBOT.CONTROLLER.odom.csv, and
  /// each link sensor's samples, ROBOT.TOPIC.csv
  std::string out_dir;
  double publish_rate = 100.0;  ///< Hz: the config's (the node's) publish_rate, an odometry's with no rate of its own
};

/// Runs `setup` (io::buildScene for a config's bodies list, io::loadScene
/// for one robot given alone) and prints the JSON line: the world's
/// members, each entry of `bodies` in the config's order, a robot's base
/// link as its `final` with final.joints.NAME.position and .velocity. The
/// CSV has a row per body and robot, and a position and a velocity column
/// per robot joint (ROBOT/JOINT), filled on its robot's row; a robot alone
/// has no name column and its joints' own names.
/// The robots' controllers run as the node runs them, commanded by
/// `timeline` (rbsim_controls.h), and their link sensors are sampled
/// (rbsim_sensors.h).
/// Its free bodies' `devices` (rbsim_sensors.h's bodyDevices) are sampled too.
int runScene(io::SceneSetup setup, const RunOptions& options, std::vector<io::TimedCommand> timeline = {},
             const std::vector<BodyDevices>& devices = {});

}  // namespace rigid_body_sim::tools
