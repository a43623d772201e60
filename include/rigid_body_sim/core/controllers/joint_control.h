// Joint controllers as ros_controllers names them, acting through effort
// only (docs/physics.md §11.10): an effort command passes through, a
// position or velocity command, or a trajectory (joint_trajectory.h), is
// tracked by control_toolbox's PID on effort, never by setting the joint
// (Gazebo's position interface teleports it). Every effort is clipped to the joint's limit, position commands to
// its range, velocity commands to its speed limit. ROS-free: the node feeds
// the commands and adds the efforts to the robot's loads.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/controllers/joint_trajectory.h"

namespace rigid_body_sim::core {

/// control_toolbox's gains: effort = p e + clip(i ∫e dt, ±i_clamp) + d ė.
struct PidGains {
  double p = 0.0;        ///< effort per unit error (N·m/rad, N/m; for velocity N·m·s/rad, N·s/m)
  double i = 0.0;        ///< effort per unit integrated error
  double d = 0.0;        ///< effort per unit error rate
  double i_clamp = 0.0;  ///< the integral term's bound (N·m or N)
};

/// Every gain finite and >= 0.
bool validGains(const PidGains& g);

/// control_toolbox::Pid's arithmetic (without anti-windup): ∫e accumulates
/// e dt; the integral term i ∫e is clipped to ±i_clamp.
class Pid {
 public:
  explicit Pid(const PidGains& gains = {}) : gains_(gains) {}
  /// The effort for error e, its rate `rate` over dt.
  double command(double error, double rate, double dt);
  /// The effort for error e, its rate the change since the last call over dt
  /// (0 on the first), as Pid::computeCommand(error, dt).
  double command(double error, double dt);
  /// A speed loop's effort (docs/physics.md §11.12), as command(error, dt)
  /// but stable for any gains on a joint whose speed changes by at most
  /// `response` (1/(kg·m²) or 1/kg: rad/s per N·m·s) per unit impulse: the
  /// proportional term is implicit, taken on the speed the effort itself
  /// leaves, so the effort is divided by 1 + p dt response; it is held to
  /// ±`limit`, and while it is held the integral does not grow (anti-windup).
  double servo(double error, double dt, double response, double limit);
  /// Forgets the integral and the last error.
  void reset();
  const PidGains& gains() const { return gains_; }

 private:
  PidGains gains_;
  double integral_ = 0.0;  ///< ∫e dt
  double last_error_ = 0.0;
  bool has_last_ = false;
};

/// What a controller's command is.
enum class ControlMode {
  kEffort,    ///< N·m or N, applied as given (within the limit)
  kVelocity,  ///< rad/s or m/s, tracked by a PID on the velocity error
  kPosition,  ///< rad or m, tracked by a PID on the position error, its rate −v (ros_controllers' d term)
  /// Waypoints, tracked by a PID on the error from the trajectory's setpoint, its rate that
  /// of the velocity error (ros_controllers' JointTrajectoryController on an effort joint).
  kTrajectory,
};

/// One controller of one robot.
struct JointControllerSpec {
  std::string name;  ///< the controller's (config key, topic namespace)
  ControlMode mode = ControlMode::kEffort;
  std::vector<int> joints;      ///< its joints (link indices), in its command's order
  std::vector<PidGains> gains;  ///< per joint, for kVelocity and kPosition
};

/// A command that was clipped: which joint, and what limit.
struct Clipped {
  int joint = -1;    ///< link index
  std::string what;  ///< "effort", "position range" or "velocity"
};

/// A robot's controllers, each owning its joints.
class JointControllers {
 public:
  JointControllers() = default;
  /// Throws std::invalid_argument naming the controller: a joint that is
  /// not a moving joint of `model`, or a mimic joint (its leader is the one
  /// to command), or owned by two controllers; missing or negative gains.
  JointControllers(const ArticulationModel& model, std::vector<JointControllerSpec> specs);

  const std::vector<JointControllerSpec>& specs() const { return specs_; }
  /// The controller owning `joint` (a link index), or −1.
  int ownerOf(int joint) const;

  /// Sets controller c's command, one value per joint. Refused (returns
  /// false and changes nothing) when the count is wrong or a value is not
  /// finite or beyond ranges.h's kMaxCommand* for its mode, or c follows
  /// trajectories; `clipped` gets the values held to a limit.
  bool command(std::size_t c, const std::vector<double>& values, std::vector<Clipped>& clipped);

  /// Sets the target of `joint` (a link index) alone, within its owner,
  /// whose mode must be `mode`; returns "" or why it was refused (no
  /// owner, another mode, not finite, absurd), and then nothing has changed.
  std::string commandJoint(int joint, ControlMode mode, double value, std::vector<Clipped>& clipped);

  /// Trajectory controller c follows `points` (its joints' order; times
  /// from `start`, s of sim time; `now` the sim time) after what it
  /// follows now (JointTrajectory::follow). Returns "" or why it was
  /// refused (a problem JointTrajectory::check finds, c is no trajectory
  /// controller, every point is past), and then nothing has changed.
  /// Positions are held to the joints' ranges (not a continuous joint's),
  /// velocities to their limits (in `clipped`); `dropped`: the points
  /// already past.
  std::string followTrajectory(std::size_t c, double now, double start, std::vector<TrajectoryPoint> points,
                               std::vector<Clipped>& clipped, int& dropped);
  /// Trajectory controller c holds its joints where `state` has them
  /// (an empty trajectory_msgs/JointTrajectory: stop).
  void hold(std::size_t c, const ArticulationState& state);
  /// What trajectory controller c follows (empty for another kind).
  const JointTrajectory& trajectory(std::size_t c) const { return trajectory_.at(c); }

  /// The efforts of the step [t, t + dt) from `state` (per joint, zero
  /// where no controller acts), within each joint's effort limit.
  void efforts(const ArticulationState& state, double t, double dt, Eigen::VectorXd& effort);

  /// After the robot was put somewhere (reset, set_state): the integrals and
  /// last errors go, position and trajectory controllers hold the joints
  /// where they now are, velocity and effort commands are zero, so nothing
  /// drives the robot back to where it was.
  void restart(const ArticulationState& state);

 private:
  /// `value` for joint j under `mode`, held to its limits (noted in `clipped`).
  double withinLimits(int j, ControlMode mode, double value, std::vector<Clipped>& clipped) const;

  std::vector<JointType> type_;      ///< per link (the base's unused)
  std::vector<JointLimits> limits_;  ///< per link
  std::vector<JointControllerSpec> specs_;
  std::vector<int> owner_;                   ///< per link: its controller, or −1
  std::vector<std::vector<Pid>> pids_;       ///< per controller, per joint
  std::vector<std::vector<double>> target_;  ///< per controller, per joint
  std::vector<JointTrajectory> trajectory_;  ///< per controller (empty but for kTrajectory)
};

}  // namespace rigid_body_sim::core
