// The model plugins of a URDF's Gazebo markup that move a robot's base as a
// whole, with no wheels (private to io): gazebo_ros_planar_move and
// gazebo_ros_force_based_move (and Clearpath's copy of it), each a base
// drive on its command topic and an odometry of the truth in its odometry frame.
#pragma once

#include <tinyxml.h>

#include "gazebo_markup.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io::detail {

/// Whether `file` is one of the two plugins.
bool isBaseMovePlugin(const std::string& file);

/// The plugin's drive into out.base_drive and its odometry into
/// out.odometry (base_plugins.cpp says which elements). Throws
/// std::invalid_argument naming the element: a number or flag it cannot
/// read, or a second such plugin on the robot.
void readBaseMovePlugin(const TiXmlElement& plugin, const Unread& unread, RobotDevices& out);

}  // namespace rigid_body_sim::io::detail
