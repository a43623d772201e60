// rbsim's sensors: each robot's link sensors (core::LinkSensors: IMUs,
// odometry, GNSS receivers, magnetometers, lidars, range finders, depth
// cameras, force-torque and contact sensors) sampled after each step as
// the node samples them, and with --out each one's samples written to a
// file of its own (docs/rbsim.md): a CSV row per sample, a depth image a
// PFM file beside it, a contact sensor's pairs a JSON line. Without --out
// no ray is cast and no force read (the noise of what is read later is
// the same). And each free body's (core::BodySensors: its IMU and noisy
// odometry), as the node samples and publishes them.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/core/contacts/contact_report.h"
#include "rigid_body_sim/core/devices/body_sensors.h"
#include "rigid_body_sim/core/devices/link_sensors.h"
#include "rigid_body_sim/core/devices/velocity_driver.h"
#include "rigid_body_sim/io/sensor_mount.h"

namespace rigid_body_sim::tools {

class SensorRun {
 public:
  /// The link sensors of each robot of `scene` (`sensors`, one per robot),
  /// started from `start`; an odometry with no rate of its own at
  /// `publish_rate` Hz. With `out_dir`, each writes its samples to
  /// OUT_DIR/ROBOT.TOPIC.csv (its topic's '/' as '.'; a UsageError if it
  /// cannot, or if two would share a file).
  SensorRun(const core::Scene& scene, const core::SceneState& start, const std::vector<io::RobotSensors>& sensors,
            double publish_rate, const std::string& out_dir);
  ~SensorRun();
  SensorRun(const SensorRun&) = delete;
  SensorRun& operator=(const SensorRun&) = delete;

  /// Before a step from `state`: what the force-torque sensors read the step's acceleration from.
  void before(const core::SceneState& state);
  /// After step `steps` (its end at sim time t, under `loads`, with the
  /// workspace `ws` it left): the sensors due sample, and their rows are written.
  void sample(const core::SceneState& state, const core::SceneLoads& loads, const core::SceneWorkspace& ws,
              long long steps, double t);
  /// Closes the files; a UsageError if one could not be written whole.
  void finish();

 private:
  /// A file of one channel of robot `robot`: channel `index` of `kind`
  /// (its odometry's truth if `truth`).
  struct Log {
    std::size_t robot;
    core::LinkSensors::Kind kind;
    std::size_t index;
    bool truth;
    std::FILE* file;
    std::string stem;  ///< OUT_DIR/ROBOT.TOPIC: a depth camera's images are STEM.STEPS.pfm
  };
  /// Opens OUT_DIR/ROBOT.TOPIC.csv with `header` for robot `robot`'s
  /// channel `index` of `kind` (its odometry's truth if `truth`).
  void open(const std::string& out_dir, std::size_t robot, const std::string& topic, const std::string& header,
            core::LinkSensors::Kind kind, std::size_t index, bool truth = false);
  void row(const Log& log, long long steps, double t) const;
  /// A depth camera's image after step `steps`: OUT_DIR/ROBOT.TOPIC.STEPS.pfm; its name.
  std::string writeImage(const Log& log, long long steps) const;

  const core::Scene& scene_;
  std::vector<core::LinkSensors> sensors_;
  core::ContactLedger ledger_;  ///< what sleeping bodies touch, as the node's
  std::vector<Log> logs_;
  std::vector<std::string> paths_;
};

/// A free body's devices as its config gives them (`imu`, `odom_noise`,
/// `cmd_vel`'s velocity driver; `bodies[i]`'s in a world).
struct BodyDevices {
  std::optional<io::ImuEntry> imu;
  std::optional<core::OdomNoiseSettings> odom_noise;
  std::optional<core::DriverSettings> cmd_vel;
};

/// Each free body's devices by its index in the world: the config's one
/// body's (no bodies list) or its `bodies` entries' (entry k being body
/// `entry[k]`, a robot's < 0; without `entry`, body k).
std::vector<BodyDevices> bodyDevices(const io::SimConfig& config, const std::vector<int>& entry = {});

class BodySensorRun {
 public:
  /// The devices of each body of `model` (`devices[i]` body i's, none past
  /// its end), started from `start` at t = 0; the IMU at its rate, the
  /// noisy odometry every publish period (`publish_rate` Hz, the node's
  /// ~publish_rate) from the start, as the node publishes them. An IMU on
  /// no link of its body is refused (io::ConfigError). With `out_dir`,
  /// each writes OUT_DIR/BODY.TOPIC.csv: the IMU's topic, and `odom` and
  /// `ground_truth` for odometry with noise (a UsageError if it cannot).
  BodySensorRun(const core::Model& model, const core::State& start, const std::vector<BodyDevices>& devices,
                double publish_rate, const std::string& out_dir);
  ~BodySensorRun();
  BodySensorRun(const BodySensorRun&) = delete;
  BodySensorRun& operator=(const BodySensorRun&) = delete;

  /// After step `steps` (0: the start) left the bodies at `state`, at sim
  /// time t: those due sample, and their rows are written (nothing without out_dir).
  void sample(const core::State& state, long long steps, double t);
  /// Closes the files; a UsageError if one could not be written whole.
  void finish();

 private:
  struct Log {
    std::size_t body;
    enum class What { kImu, kOdometry, kTruth } what;
    std::FILE* file;
  };
  const core::Model& model_;
  std::vector<core::BodySensors> sensors_;  ///< per body with devices
  std::vector<std::size_t> body_;           ///< sensors_[k]'s body
  long long publish_every_;                 ///< steps per odometry report
  std::vector<Log> logs_;                   ///< sensors_[log.body]'s
  std::vector<core::OdomReport> reports_;   ///< sensors_[k]'s latest noisy report
};

}  // namespace rigid_body_sim::tools
