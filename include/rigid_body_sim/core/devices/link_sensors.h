// A robot's sensors on its links (docs/physics.md §10.11): those that read
// a link's motion (IMUs, odometry exact or with its noise, GNSS receivers,
// magnetometers), those that cast rays into the world from it (lidars,
// range finders, depth cameras) and those that read the forces on it
// (force-torque sensors on its joint, contact sensors), each at a mount on
// a moving link, each sampled at its rate of sim time from the state and
// the contacts a step left. One robot's
// set is one object: the node turns its fresh samples into messages, rbsim
// into rows of a file, and both get the same numbers. ROS-free.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/articulations/articulation_step.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/core/contacts/contact_report.h"
#include "rigid_body_sim/core/devices/depth_camera.h"
#include "rigid_body_sim/core/devices/earth_sensors.h"
#include "rigid_body_sim/core/devices/force_torque.h"
#include "rigid_body_sim/core/devices/imu.h"
#include "rigid_body_sim/core/devices/lidar.h"
#include "rigid_body_sim/core/devices/odom_noise.h"
#include "rigid_body_sim/core/devices/range_finder.h"

namespace rigid_body_sim::core {

/// When a device samples: after every `every()` steps of the world's (its
/// rate of sim time rounded to whole steps, at least one), counted on the
/// world's step count, and when it last did.
class SampleClock {
 public:
  /// `rate` Hz of sim time (0: every step), with steps of `dt` s.
  SampleClock(double rate, double dt);
  long long every() const { return every_; }
  /// Hz of sim time it samples at: 1 / (every × dt).
  double rate() const { return 1.0 / (static_cast<double>(every_) * dt_); }
  /// Whether a sample is due after the world's step `steps` (1 the first).
  bool due(long long steps) const { return steps % every_ == 0; }
  /// s of sim time since its last sample (the first: one period), and t
  /// becomes the last.
  double elapsed(double t);

 private:
  long long every_;
  double dt_;
  double last_ = -1.0;  ///< s of sim time; < 0: none yet
};

/// Link `link`'s pose and twist in `kin` as a LinkState (the world's axes).
LinkState linkStateOf(const ArticulationKinematics& kin, int link);

/// A frame on a robot's moving link: link `link` (index in the model) and
/// the frame at X_LS in it.
struct LinkMount {
  int link = 0;
  Pose X_LS;
};

/// An IMU on a link: its reading of the period that ended at the last sample.
struct ImuChannel {
  Imu imu;
  int link = 0;  ///< the sensor frame is imu.settings().X_LS in it
  SampleClock clock;
  ImuReading reading;
};

/// A link's odometry (a robot's `odom_noise`, gazebo_ros_p3d, a base
/// plugin's): the report, with its noise if it has one, and the truth.
struct OdometryChannel {
  std::optional<OdomNoise> noise;  ///< none: the report is the truth
  LinkMount at;
  SampleClock clock;
  OdomReport report, truth;
};

struct GnssChannel {
  Gnss gnss;
  LinkMount at;
  SampleClock clock;
  GnssFix fix;
};

struct MagnetometerChannel {
  Magnetometer magnetometer;
  LinkMount at;
  SampleClock clock;
  Vec3 field_S = Vec3::Zero();  ///< in the sensor's axes
};

/// A lidar on a link, or a range finder (gazebo_ros_range): one reading,
/// the nearest of its lidar's rays.
struct LidarChannel {
  Lidar lidar;
  std::optional<RangeFinder> finder;
  LinkMount at;
  SampleClock clock;
  std::vector<double> ranges;  ///< the last scan cast: m per ray, fan by fan (REP 117's ±inf)
  double reading = kNoHit;     ///< a range finder's last (m, REP 117's ±inf)
};

struct DepthCameraChannel {
  DepthCamera camera;
  LinkMount at;
  SampleClock clock;
  std::vector<double> depth;  ///< the last image cast: m per pixel, row by row from the top left
};

/// A force-torque sensor on the joint of link sensor.link() (gazebo_ros_ft_sensor's).
struct ForceTorqueChannel {
  ForceTorqueSensor sensor;
  SampleClock clock;
  Vec6 wrench = Vec6::Zero();  ///< the last reading: [torque; force] in the link's axes about its origin (N·m, N)
};

/// A contact sensor on a link (gazebo_ros_bumper's): every pair touching it.
struct ContactChannel {
  LinkMount at;          ///< the frame the contacts are given in, unless in_world
  bool in_world = true;  ///< in the world's frame
  SampleClock clock;
  std::vector<ContactPairReport> pairs;  ///< the last sample's: the link on the `body` side, in the frame
};

/// What a step left for the sensors of forces beside the state: the loads
/// it put on the robot's links (none: none) and its contacts (needed when
/// a force-torque or contact sensor is due and read).
struct StepForces {
  const ArticulationLoads* loads = nullptr;
  StepContacts* contacts = nullptr;
};

/// One robot's link sensors, in the order they were added (each kind its
/// own list), and which of them the last sample() took.
class LinkSensors {
 public:
  /// Steps of `dt` s.
  explicit LinkSensors(double dt) : dt_(dt) {}

  /// An IMU on link `link` of `model` (its pose settings.X_LS there), its
  /// first period starting from `now`.
  void addImu(const ImuSettings& settings, int link, const ArticulationModel& model, const ArticulationState& now);
  /// Odometry at `at`, `rate` Hz; with `noise`, its report carries it.
  void addOdometry(const std::optional<OdomNoiseSettings>& noise, const LinkMount& at, double rate);
  void addGnss(const GnssSettings& settings, const LinkMount& at, double rate);
  void addMagnetometer(const MagnetometerSettings& settings, const LinkMount& at, double rate);
  /// A lidar at `at`, `rate` Hz; with `finder`, a range finder of its rays.
  void addLidar(const LidarSettings& settings, const std::optional<RangeFinderSettings>& finder, const LinkMount& at,
                double rate);
  void addDepthCamera(const DepthCameraSettings& settings, const LinkMount& at, double rate);
  /// A force-torque sensor on the joint of link `link` (> 0), `rate` Hz (0: every step).
  void addForceTorque(const ForceTorqueSettings& settings, int link, double rate);
  /// A contact sensor on `at`'s link, its contacts in the world's frame or
  /// (not `in_world`) in the frame at `at`; `rate` Hz (0: every step).
  void addContactSensor(const LinkMount& at, bool in_world, double rate);

  /// Before a step of the robot from `state`: the velocities a force-torque
  /// sensor reads the step's acceleration from.
  void before(const ArticulationModel& model, const ArticulationState& state);

  /// After the world's step `steps` (1 the first), which left robot r of
  /// `scene` at `state` and the world's bodies at `bodies`, at sim time t:
  /// every sensor due samples, its channel holds the sample and fresh()
  /// says so. A ray device casts into the world, its robot's own links
  /// unseen; a force sensor reads the step's `forces` (a std::invalid_argument
  /// if it needs contacts and has none). Either is left out when
  /// want(kind, i, false) said nobody reads it this time: then it passes
  /// (its next sample's noise is the same either way; a motion sensor's
  /// noise is drawn whether or not anyone reads it). Returns whether any
  /// was due.
  bool sample(const Scene& scene, std::size_t r, const State& bodies, const ArticulationState& state, long long steps,
              double t, const StepForces& forces = {});

  /// The robot was put somewhere (set_model_configuration, a reset): each
  /// IMU's next period starts at `now` (a jump is no acceleration).
  void restartImus(const ArticulationModel& model, const ArticulationState& now);
  /// A reset: each odometry's drift from zero, each receiver's,
  /// magnetometer's and ray device's noise from its seed (the world's clock
  /// runs on, and with it theirs).
  void restartNoise();

  const std::vector<ImuChannel>& imus() const { return imus_; }
  const std::vector<OdometryChannel>& odometry() const { return odometry_; }
  const std::vector<GnssChannel>& gnss() const { return gnss_; }
  const std::vector<MagnetometerChannel>& magnetometers() const { return magnetometers_; }
  const std::vector<LidarChannel>& lidars() const { return lidars_; }
  const std::vector<DepthCameraChannel>& depthCameras() const { return depth_cameras_; }
  const std::vector<ForceTorqueChannel>& forceTorques() const { return force_torques_; }
  const std::vector<ContactChannel>& contactSensors() const { return contact_sensors_; }
  enum class Kind { kImu, kOdometry, kGnss, kMagnetometer, kLidar, kDepthCamera, kForceTorque, kContacts };
  /// Whether the last sample() took the channel (`kind`'s i-th); a ray
  /// device's or force sensor's was read if fresh and wanted(kind, i) too.
  bool fresh(Kind kind, std::size_t i) const { return fresh_[static_cast<std::size_t>(kind)].at(i) != 0; }
  /// Whether ray device or force sensor `kind`'s i-th is read when due (as added: yes).
  bool wanted(Kind kind, std::size_t i) const { return wanted_[static_cast<std::size_t>(kind)].at(i) != 0; }
  void want(Kind kind, std::size_t i, bool yes) { wanted_[static_cast<std::size_t>(kind)].at(i) = yes ? 1 : 0; }
  bool empty() const {
    return imus_.empty() && odometry_.empty() && gnss_.empty() && magnetometers_.empty() && lidars_.empty() &&
           depth_cameras_.empty() && force_torques_.empty() && contact_sensors_.empty();
  }

 private:
  double dt_;
  std::vector<ImuChannel> imus_;
  std::vector<OdometryChannel> odometry_;
  std::vector<GnssChannel> gnss_;
  std::vector<MagnetometerChannel> magnetometers_;
  std::vector<LidarChannel> lidars_;
  std::vector<DepthCameraChannel> depth_cameras_;
  std::vector<ForceTorqueChannel> force_torques_;
  std::vector<ContactChannel> contact_sensors_;
  static constexpr std::size_t kKinds = 8;
  std::array<std::vector<char>, kKinds> fresh_;   ///< per Kind, per channel
  std::array<std::vector<char>, kKinds> wanted_;  ///< per Kind, per channel (the ray devices' and force sensors')
  Eigen::VectorXd u_before_;                      ///< the robot's velocities before the last step (before())
  /// sample()'s force-torque and contact sensors; its links placed in kin_ unless `placed`, which it then sets.
  void sampleForces(const Scene& scene, std::size_t r, const State& bodies, const ArticulationState& state,
                    long long steps, const StepForces& forces, bool& placed);
  // Reused by every sample.
  ArticulationKinematics kin_;
  std::vector<char> skip_;  ///< per body of the world: the robot's own
};

}  // namespace rigid_body_sim::core
