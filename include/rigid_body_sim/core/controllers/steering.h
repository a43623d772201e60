// A steered base's geometry on its plane (docs/physics.md §11.14): the
// angles its steering joints take for one steering angle (Ackermann's
// linkage, or a tricycle's one wheel), the rim speeds its wheels roll at
// for the base's motion, and the motion its steering allows, for the
// wheeled-base controller's steered mode (diff_drive.h). Lengths are in the
// base's frame at rest from the centre of the axle that does not steer, x
// forward and y left (m); angles in rad, positive turning left. ROS-free.
#pragma once

#include <limits>
#include <vector>

#include "rigid_body_sim/core/controllers/joint_control.h"

namespace rigid_body_sim::core {

/// The base's motion on its plane: v (m/s) of the fixed axle's centre along
/// the base's x and ω (rad/s) about z; or, as a direction, their ratio.
struct PlanarMotion {
  double v = 0.0;
  double w = 0.0;
};

/// A steered base: ros_controllers' ackermann_steering_controller (its
/// `front_steer` one joint in the middle, or one per front wheel) or
/// gazebo_ros_tricycle_drive (one steered, driven wheel).
struct SteeringSpec {
  std::vector<int> joints;               ///< the steering joints (link indices)
  std::vector<double> joint_x, joint_y;  ///< m, where each steering axis meets the ground plane
  /// Per steering joint: +1 when its axis is the base's +z (its angle
  /// turns the wheel left), −1 when it is −z.
  std::vector<double> joint_sign;
  /// m, the fixed axle to the steering axes; its steering angle δ is a
  /// virtual wheel's at (wheelbase, 0), which each joint turns as the
  /// linkage turns it (steerAngle).
  double wheelbase = 0.0;
  /// Per driven wheel (the drive's wheels, in order): where it touches the
  /// ground, and the steering joint (an index into `joints`) it turns
  /// with, or −1.
  std::vector<double> wheel_x, wheel_y;
  std::vector<int> wheel_steer;
  /// The command's speed is the steered wheel's rim (a tricycle's driven
  /// wheel, as gazebo_ros_tricycle_drive), else the fixed axle's centre
  /// (ackermann_steering_controller's rear wheel).
  bool speed_at_steered_wheel = false;
  /// rad/s: the steering joints turn at most this fast (the joint's own
  /// limit too); gazebo_ros_tricycle_drive's `steeringSpeed`.
  double steering_speed = std::numeric_limits<double>::infinity();
  /// Per steering joint its speed servo's PID; empty: defaultSteeringGains.
  std::vector<PidGains> gains;
};

/// The angle of a steering joint at (x, y) that rolls about the same point
/// as the virtual middle wheel at (L, 0) steered δ, a point of the fixed
/// axle's line: atan2(x sin δ, L cos δ − y sin δ).
double steerAngle(double delta, double wheelbase, double x, double y);

/// The steering angle δ a base takes for a commanded one: within ±90° for
/// a tricycle (its wheel sideways turns it on the spot), ±80° from the
/// fixed axle (tan δ, the rear wheels' speed per unit of the turn's, is 5.7
/// there and infinite at 90°).
double steerable(const SteeringSpec& s, double delta);

/// The base's motion per unit of the command's speed at steering angle δ:
/// (1, tan δ / L) from the fixed axle, (cos δ, sin δ / L) from the
/// steered wheel.
PlanarMotion motionPerSpeed(const SteeringSpec& s, double delta);

/// The speed a wheel touching at (x, y), heading `a` from the base's x,
/// rolls at for the base's motion m: (v − ω y) cos a + ω x sin a.
double rimSpeed(const PlanarMotion& m, double x, double y, double a);

/// The direction of motion that a steering joint at (x, y) turned `a`
/// allows (its wheel rolling without sliding sideways), as a unit vector
/// (v, ω/1 m⁻¹), its v ≥ 0: ∝ (x cos a + y sin a, sin a).
PlanarMotion allowedDirection(double x, double y, double a);

/// The default PI of a steering joint's speed servo: the poles of
/// defaultWheelGains (τ = 20 ms) for the inertia the joint turns at the
/// robot's rest, 1 / jointResponse; i_clamp its effort limit (100 p if none).
PidGains defaultSteeringGains(const ArticulationModel& model, int joint);

}  // namespace rigid_body_sim::core
