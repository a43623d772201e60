// rbsim's controls: the robots' control stage run as the node runs it
// (core::RobotControl: the controllers' efforts, the drives, the base
// drivers), their commands from the config's timeline, and each wheeled
// base's odometry written to a CSV file of its own at its publish_rate, as
// the node publishes it (docs/rbsim.md).
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "rbsim_sensors.h"
#include "rigid_body_sim/core/articulations/joint_effort_schedule.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/core/devices/velocity_driver.h"
#include "rigid_body_sim/io/controllers.h"
#include "rigid_body_sim/io/timeline.h"

namespace rigid_body_sim::tools {

/// The free bodies' velocity drivers (config `cmd_vel`), commanded by the
/// timeline's `body:` entries as sim_node's BodyPorts hold them, their
/// loads added as the node adds them.
class BodyDrives {
 public:
  /// A driver for each body of `model` whose `devices` (by index) give a cmd_vel.
  BodyDrives(const core::Model& model, const std::vector<BodyDevices>& devices);
  BodyDrives(const BodyDrives&) = delete;
  BodyDrives& operator=(const BodyDrives&) = delete;

  /// A body's driver by its name, for a Timeline.
  io::BodyDrivers byName();
  /// The drivers' loads on the bodies at `state` for the step [t, t + dt)
  /// into `loads`, cleared first (empty if no driver pushes).
  void loadsFor(const core::State& state, double t, core::Loads& loads);
  bool empty() const { return drivers_.empty(); }

 private:
  const core::Model& model_;
  std::vector<std::size_t> body_;              ///< drivers_[k]'s body
  std::vector<core::VelocityDriver> drivers_;  ///< one per driven body
};

class ControlRun {
 public:
  /// The robots of `scene` with their `controls`, each started from where
  /// `start` has it as the node starts a robot's (position targets where the
  /// joints are, odometry at zero), commanded by `timeline` (refused as
  /// Timeline refuses it), its `body:` entries given to `bodies`; with
  /// `out_dir`, each drive's odometry goes to
  /// OUT_DIR/ROBOT.CONTROLLER.odom.csv (a UsageError if it cannot).
  ControlRun(const core::Scene& scene, const core::SceneState& start, std::vector<io::RobotControls> controls,
             std::vector<io::TimedCommand> timeline, io::BodyDrivers bodies, const std::string& out_dir);
  ~ControlRun();
  ControlRun(const ControlRun&) = delete;
  ControlRun& operator=(const ControlRun&) = delete;

  /// Before the step that starts at t: the timeline's commands due, then
  /// each robot's loads into `loads` (one per robot).
  void loadsFor(const core::SceneState& state, double t, std::vector<core::ArticulationLoads>& loads);
  /// After step `steps` (its end at sim time t): the drives read their
  /// wheels, and those due write their odometry's row.
  void observe(const core::SceneState& state, long long steps, double t);
  /// Each drive's odometry row at sim time t (the start, as the node publishes at start).
  void write(double t);
  /// Closes the files; a UsageError if one could not be written whole.
  void finish();

 private:
  /// The rows due at step `steps` (every one for steps < 0), at sim time t.
  void rows(double t, long long steps);

  struct Log {
    std::size_t robot, drive;
    long long every;
    std::FILE* file;
  };
  const core::Scene& scene_;
  std::vector<io::RobotControls> controls_;
  std::vector<std::string> names_;
  io::Timeline timeline_;
  core::JointEffortSchedule efforts_;  ///< the timeline's joint efforts
  std::vector<Log> logs_;
  std::vector<std::string> said_;  ///< the timeline's notes, each said once
};

}  // namespace rigid_body_sim::tools
