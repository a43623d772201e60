// Loads a rigid body from URDF through urdfdom. Shared by rbsim and the ROS
// node (which passes the robot_description string). ROS-free.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

/// A URDF that cannot be turned into one rigid body. The message names the
/// source, the link or joint, and the field.
class UrdfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How a URDF is read. Gazebo and KDL load the descriptions users have,
/// whose CAD-exported inertias break the triangle inequality by rounding
/// and whose frames (base_footprint, sensor mounts) have no <inertial>; so
/// do the loaders, repairing what a strict reading would refuse
/// (docs/physics.md §2.1): a link without <inertial>, or of mass 0, is a
/// massless frame; an inertia no body can have is replaced by the nearest
/// valid one; a moving joint that moves only massless links is held where
/// it starts; `package:///NAME` reads as `package://NAME`.
struct UrdfOptions {
  /// false (config key urdf.repair): each of those is refused instead.
  bool repair = true;
  /// Where a load that repaired something says what, in one message naming
  /// every link and figure (appended; nothing when nothing was repaired).
  std::vector<std::string>* notes = nullptr;
  /// Where a robot's load puts the sensors its Gazebo markup declares
  /// (`<sensor type="ray">` or `"imu"` with a ROS plugin, gazebo_ros_imu);
  /// null: they are named with the markup nothing reads (a free body's: no
  /// sensor on a body's markup yet; rbsim's).
  RobotDevices* sensors = nullptr;
};

/// The rigid body described by a URDF document.
///
/// The root link and every link hanging from it by fixed joints are lumped
/// into one body: masses add, the centre of mass is the mass-weighted mean,
/// and inertias are carried to it by the parallel-axis theorem. The body's
/// frame L is the root link frame, whatever the centre of mass: that is the
/// pose reported everywhere. Refused, with one message naming every
/// element at fault: a movable joint (a URDF with one is a robot:
/// articulation_loader.h), a negative or non-finite mass, a total mass of
/// zero or an inertia no mass distribution can have, and with
/// `options.repair` false a link without <inertial> or an invalid inertia
/// (repaired otherwise, as UrdfOptions says).
///
/// The <collision> elements of the lumped links become the body's collision
/// shapes (box, sphere, cylinder, mesh vertices through assimp); mesh URIs
/// resolve as resolveMeshUri() says, relative to `base_dir`. A non-positive
/// size or an unreadable mesh is refused, naming the link.
///
/// `source` names the document in messages (a file path, or the parameter).
core::BodySpec loadUrdfString(const std::string& xml, const std::string& source, const std::string& base_dir = "",
                              const UrdfOptions& options = {});

/// Reads and loads a URDF file.
core::BodySpec loadUrdfFile(const std::string& path, const UrdfOptions& options = {});

}  // namespace rigid_body_sim::io
