// Loads a robot (a URDF with moving joints) as an articulation through
// urdfdom (docs/physics.md §11). Shared by rbsim and the ROS node. ROS-free.
#pragma once

#include <string>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/io/urdf_loader.h"

namespace rigid_body_sim::io {

/// The articulation a URDF describes.
///
/// Links joined by fixed joints are one link (lumped as a body's are); the
/// revolute, continuous and prismatic joints join them, with their
/// <origin>, <axis> (made unit length), <limit lower upper effort velocity>
/// (a continuous joint has no position limits; a joint without <limit> no
/// effort or velocity limit), <dynamics damping friction> and <mimic joint
/// multiplier offset>. A root link named `world` is the world, fixed (it
/// needs no <inertial>), as Gazebo reads it; otherwise the base floats.
/// Links are numbered parents first, breadth first; siblings in urdfdom's
/// order of their joints (by name).
///
/// Links may be massless (KDL's reading) where what hangs from them has
/// mass; with `options.repair` a joint that moves only massless links is
/// held (core::HeldJoint), and links without <inertial> or with invalid
/// inertias are repaired as UrdfOptions says, all said in one message.
///
/// Refused with UrdfError naming every joint or link at fault: a URDF
/// without a moving joint (it is one body: loadUrdfString), whatever
/// loadUrdfString refuses about a link, a floating or planar joint, an axis
/// of zero length, lower > upper, a mimic of an unknown joint or of another
/// mimic, a joint that moves no mass or inertia (core::checkArticulation).
core::ArticulationModel loadArticulationString(const std::string& xml, const std::string& source,
                                               const std::string& base_dir = "", const UrdfOptions& options = {});

/// Whether a URDF has a joint that is not fixed: a robot
/// (loadArticulationString), not one body (loadUrdfString). A text urdfdom
/// cannot read is refused with UrdfError, as both loaders refuse it.
bool describesRobot(const std::string& xml, const std::string& source);

/// Reads and loads a URDF file as an articulation.
core::ArticulationModel loadArticulationFile(const std::string& path, const UrdfOptions& options = {});

}  // namespace rigid_body_sim::io
