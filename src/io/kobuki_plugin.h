// Kobuki's (TurtleBot2's) model plugin, gazebo_ros_kobuki of
// kobuki_gazebo_plugins, read as it reads its markup (private to io): its
// drive as a DiffDriveController on its topics, its IMU.
#pragma once

#include <tinyxml.h>

#include "gazebo_markup.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io::detail {

/// The plugin (kobuki_plugin.cpp says which elements) into out.controllers
/// and out.imus; what it does that is not run here, to `unread`. Throws
/// std::invalid_argument naming the element: a number or flag it cannot
/// read, an element the plugin requires missing, its IMU sensor absent.
void readKobukiPlugin(const TiXmlElement& plugin, const Unread& unread, RobotDevices& out);

}  // namespace rigid_body_sim::io::detail
