// Loads a rigid body from URDF through urdfdom. Shared by rbsim and the ROS
// node (which passes the robot_description string). ROS-free.
#pragma once

#include <stdexcept>
#include <string>

#include "rigid_body_sim/core/model.h"

namespace rigid_body_sim::io {

/// A URDF that cannot be turned into one rigid body. The message names the
/// source, the link or joint, and the field.
class UrdfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The rigid body described by a URDF document.
///
/// The root link and every link hanging from it by fixed joints are lumped
/// into one body: masses add, the centre of mass is the mass-weighted mean,
/// and inertias are carried to it by the parallel-axis theorem. The body's
/// frame L is the root link frame, whatever the centre of mass: that is the
/// pose reported everywhere. Refused, with a message naming the element:
/// a movable joint (articulated bodies are out of scope), a link without
/// <inertial>, a negative or non-finite mass, an inertia that no mass
/// distribution can have, a total mass of zero.
///
/// The <collision> elements of the lumped links become the body's collision
/// shapes (box, sphere, cylinder, mesh vertices through assimp); mesh URIs
/// resolve as resolveMeshUri() says, relative to `base_dir`. A non-positive
/// size or an unreadable mesh is refused, naming the link.
///
/// `source` names the document in messages (a file path, or the parameter).
core::BodySpec loadUrdfString(const std::string& xml, const std::string& source, const std::string& base_dir = "");

/// Reads and loads a URDF file.
core::BodySpec loadUrdfFile(const std::string& path);

}  // namespace rigid_body_sim::io
