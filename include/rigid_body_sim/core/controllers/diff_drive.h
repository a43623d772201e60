// A wheeled base's controller, as ros_controllers'
// diff_drive_controller/DiffDriveController runs one (docs/physics.md
// §11.12), or mecanum_drive_controller/MecanumDriveController on four
// mecanum wheels (§11.13), or a steered base's (§11.14:
// ackermann_steering_controller, gazebo_ros_tricycle_drive, whose command's
// angular z is the steering angle): a body twist (v, ω), and a mecanum base's
// sideways v_y, becomes the wheels' speeds, within
// its speed, acceleration and jerk limits and zero once the command is
// older than its timeout; each wheel tracks its speed through a PID on
// effort (never by setting the joint), implicit in its proportional term
// and held from winding up, so it stays stable when a wheel lifts or
// slips (Pid::servo); the odometry is integrated from the
// wheels' joint positions, so it drifts when a wheel slips, as a real
// one's does. ROS-free: the node feeds the twist and publishes the odometry.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/controllers/joint_control.h"
#include "rigid_body_sim/core/controllers/steering.h"

namespace rigid_body_sim::core {

struct ArticulationKinematics;

/// One axis of the twist (linear x, angular z), as ros_controllers'
/// SpeedLimiter: velocity within [min_velocity, max_velocity], its change
/// per step within the acceleration bounds × dt, the change of that change
/// within the jerk bounds × 2 dt².
struct TwistLimiter {
  bool has_velocity_limits = false;
  bool has_acceleration_limits = false;
  bool has_jerk_limits = false;
  double min_velocity = 0.0, max_velocity = 0.0;          ///< m/s or rad/s
  double min_acceleration = 0.0, max_acceleration = 0.0;  ///< m/s² or rad/s²
  double min_jerk = 0.0, max_jerk = 0.0;                  ///< m/s³ or rad/s³

  /// v held to the limits, v0 and v1 the last two limited values, dt (s) the step.
  double limit(double v, double v0, double v1, double dt) const;
};

/// What a DiffDriveController is given besides its wheels (its YAML's keys).
struct DiffDriveSettings {
  double wheel_separation_multiplier = 1.0;
  double left_wheel_radius_multiplier = 1.0;
  double right_wheel_radius_multiplier = 1.0;
  /// s: an older command is zero (the base brakes); infinite: the last
  /// command is held, as gazebo_ros_diff_drive does
  double cmd_vel_timeout = 0.5;
  int velocity_rolling_window_size = 10;  ///< steps the odometry's velocity is averaged over
  bool open_loop = false;                 ///< odometry from the commands, not the wheels
  /// N·m: each wheel's effort at most this, beside its joint's limit
  /// (gazebo_ros_diff_drive's wheelTorque)
  double max_wheel_torque = std::numeric_limits<double>::infinity();
  TwistLimiter linear;   ///< linear/x/*
  TwistLimiter angular;  ///< angular/z/*
  TwistLimiter lateral;  ///< linear/y/* (a mecanum base's; a differential one takes no v_y)
};

struct DiffDriveSpec {
  std::string name;        ///< the controller's (config key, topic namespace)
  std::vector<int> left;   ///< the left wheels' joints (link indices), one or more; mecanum: front, back
  std::vector<int> right;  ///< the right wheels', as many; mecanum: front, back
  /// m, before its multiplier: the two sides apart; mecanum: its wheels'
  /// lengthwise and sideways spans added (twice mecanum_drive_controller's
  /// k, each wheel's |x| + |y| from the centre)
  double wheel_separation;
  double wheel_radius;  ///< m, before the multipliers
  /// Four mecanum wheels, their rollers at 45 degrees as mecanum_drive_controller
  /// has them: the front left and back right roll the base along x − y, the
  /// others along x + y.
  bool mecanum = false;
  /// A steered base (§11.14): `left` its driven wheels (one or more),
  /// `right` empty, `wheel_separation` its wheelbase; the command's ω is
  /// the steering angle δ (rad), limited by `angular/z` as ros_controllers'
  /// ackermann_steering_controller limits it.
  std::optional<SteeringSpec> steering;
  DiffDriveSettings settings;
  /// Per wheel (left then right) the PID on its speed error; empty: the
  /// default of defaultWheelGains.
  std::vector<PidGains> gains;
};

/// The default PID of a wheel whose joint is link `wheel` of `model`: a PI
/// on the speed error with both closed-loop poles at −1/τ, τ = 20 ms, for
/// the inertia J the wheel drives, its own about its axle plus its share of
/// the robot's mass at its rim (m_robot r² / wheels): p = 2 J / τ,
/// i = J / τ², i_clamp = the joint's effort limit (100 p if it has none).
PidGains defaultWheelGains(const ArticulationModel& model, int wheel, double wheel_radius, int wheels);

/// The PI above for an inertia J (kg·m² or kg): p = 2 J / τ, i = J / τ²,
/// i_clamp = `effort_limit` (100 p if it is infinite).
PidGains servoGains(double inertia, double effort_limit);

/// The base's pose and twist in the odometry frame, which is where the
/// base was when the controller started (x forward, z up).
struct PlanarOdometry {
  double x = 0.0, y = 0.0;  ///< m
  double heading = 0.0;     ///< rad, in (−π, π]
  double linear = 0.0;      ///< m/s, along the base's x (averaged over the window)
  double angular = 0.0;     ///< rad/s, about z (averaged over the window)
  double lateral = 0.0;     ///< m/s, along the base's y (a mecanum base's; averaged over the window)
};

class DiffDrive {
 public:
  /// Throws std::invalid_argument naming the controller: no wheels, unequal
  /// counts, a wheel that is no moving joint of `model`, a mimic joint, named
  /// twice; a separation, radius or multiplier not finite and > 0, a
  /// timeout < 0, a window < 1, a wheel torque not > 0, a limit pair not
  /// finite with min ≤ 0 ≤ max, gains not one per wheel or not finite ≥ 0.
  DiffDrive(const ArticulationModel& model, DiffDriveSpec spec);

  const DiffDriveSpec& spec() const { return spec_; }
  /// Every wheel joint (left then right).
  const std::vector<int>& wheels() const { return wheels_; }
  /// m and m: the separation and each side's radius after the multipliers.
  double separation() const { return separation_; }
  double leftRadius() const { return left_radius_; }
  double rightRadius() const { return right_radius_; }

  /// A cmd_vel received at `t` (s of sim time): v (m/s), ω (rad/s), and a
  /// mecanum base's v_y (m/s; a differential base ignores it, as
  /// ros_controllers' does). Not finite or beyond ranges::kMaxCommandSpeed:
  /// refused (false), nothing changes.
  bool command(double linear, double angular, double t, double lateral = 0.0);
  /// The step [t, t + dt) from `state`: the command limited and turned into
  /// wheel speeds, each wheel's PID effort written to `effort` (per joint,
  /// within its limit).
  void efforts(const ArticulationState& state, double t, double dt, Eigen::VectorXd& effort);
  /// The odometry after a step of `dt` s that left `state` (its wheels'
  /// angles; open loop, the command limited for that step).
  void observe(const ArticulationState& state, double dt);
  const PlanarOdometry& odometry() const { return odometry_; }
  /// The last command as limited (publish_cmd's cmd_vel_out): v, ω.
  double limitedLinear() const { return last0_linear_; }
  double limitedAngular() const { return last0_angular_; }
  double limitedLateral() const { return last0_lateral_; }

  /// The base was put somewhere or its joints moved: the wheels' positions
  /// are read afresh (no jump in the odometry), the PIDs and the velocity
  /// window forgotten, the command zero. `zero_pose` (a world reset): the
  /// odometry starts again at 0.
  void restart(const ArticulationState& state, bool zero_pose);

 private:
  /// The mean of `joints`' positions in `state`.
  static double meanPosition(const ArticulationState& state, const std::vector<int>& joints);
  /// Moves the pose by an arc of length `ds` (and `dlat` sideways) turning `dtheta`.
  void integrate(double ds, double dtheta, double dlat = 0.0);
  /// Adds one step's velocity sample to the windows.
  void average(double linear, double angular, double lateral = 0.0);
  /// A mecanum base's odometry from each wheel's travel since the last update.
  void observeMecanum(const ArticulationState& state, double dt);
  /// A steered base's: the motion its steering joints allow, scaled to its wheels' travel.
  void observeSteered(const ArticulationState& state, double dt);
  /// A steered base's efforts for the limited command (v, δ).
  void steeredEfforts(const ArticulationState& state, double v, double delta, double dt, Eigen::VectorXd& effort);
  /// A steered base's steering joints checked, their servos made.
  void checkSteering(const ArticulationModel& model, const ArticulationKinematics& rest);
  /// Steering joint k's heading now (its angle, signed as its axis is ±z).
  double heading(const ArticulationState& state, std::size_t k) const;
  /// Wheel n's rim radius (m): its side's.
  double rimRadius(std::size_t n) const { return n < spec_.left.size() ? left_radius_ : right_radius_; }
  /// Each wheel's rim (m) now, into travel_.
  void readTravel(const ArticulationState& state);

  DiffDriveSpec spec_;
  std::vector<int> wheels_;          ///< left then right
  std::vector<JointLimits> limits_;  ///< per wheel, left then right
  std::vector<Pid> pids_;            ///< per wheel, left then right
  /// Per wheel, how fast its speed answers an impulse with nothing touching
  /// (jointResponse at the robot's rest), which its servo is implicit in.
  std::vector<double> response_;
  double separation_ = 0.0, left_radius_ = 0.0, right_radius_ = 0.0;
  // The command: as received, and the last two as limited.
  double linear_ = 0.0, angular_ = 0.0, lateral_ = 0.0, stamp_ = 0.0;
  bool commanded_ = false;
  double last0_linear_ = 0.0, last0_angular_ = 0.0, last1_linear_ = 0.0, last1_angular_ = 0.0;
  double last0_lateral_ = 0.0, last1_lateral_ = 0.0;
  // The odometry.
  PlanarOdometry odometry_;
  double left_travel_ = 0.0, right_travel_ = 0.0;  ///< m, each side's rim at the last update
  bool has_travel_ = false;                        ///< false until the first update or restart
  std::vector<double> travel_;  ///< m, a mecanum or steered base's wheels' rims at the last update (left then right)
  // A steered base's steering joints: limits, speed servos, responses.
  std::vector<JointLimits> steer_limits_;
  std::vector<Pid> steer_pids_;
  std::vector<double> steer_response_;
  std::vector<double> linear_window_, angular_window_, lateral_window_;
  std::size_t window_next_ = 0;
};

}  // namespace rigid_body_sim::core
