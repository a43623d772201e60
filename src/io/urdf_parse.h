// urdfdom, guarded (private to io): what the text must be before urdfdom
// reads it, and what urdfdom could not read. urdfdom logs an element it
// cannot read (<mass value="2.0kg"/>, <box size="1 1 1m"/>) and goes on
// without it, and it leaks the links of a URDF whose joints form a cycle;
// here the first is an error and the second never reaches it.
#pragma once

#include <urdf_world/types.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io::detail {

/// The <collision>s that were capsules: (link name, index among the link's <collision>s).
using CapsuleSet = std::set<std::pair<std::string, std::size_t>>;

struct ParsedUrdf {
  urdf::ModelInterfaceSharedPtr model;  ///< never null
  CapsuleSet capsules;                  ///< read as cylinders by urdfdom
  /// Per link: the friction coefficient of its `<gazebo reference="LINK">`
  /// markup (`<mu1>`, `<mu2>`: the smaller of those given, each as its
  /// text or its `value` attribute, as Gazebo's URDF reader takes them; one
  /// above core::ranges::kMaxFriction as that), which urdfdom skips.
  std::map<std::string, double> surface_friction;
  /// Those read as kMaxFriction: "<gazebo reference=\"LINK\"> <mu1> = V".
  std::vector<std::string> friction_above;
  /// The markup nothing here reads (Gazebo's sensors, plugins and surface
  /// or joint tuning, <transmission>s), by kind (`<sensor type="ray">
  /// libgazebo_ros_laser.so`, `<kp>`, `<transmission>`), each kind's links
  /// or names in document order; `<material>`, drawing only, is left out.
  std::map<std::string, std::vector<std::string>> unread_markup;
  /// The sensors of its Gazebo markup with a ROS plugin (gazebo_sensors.h),
  /// and their markup as unread_markup names it (for a load that takes no sensors).
  RobotDevices sensors;
  std::map<std::string, std::vector<std::string>> sensor_markup;
};

/// urdfdom's model of `xml`. Throws std::invalid_argument, one line that
/// starts with the first cause: two joints giving a link a parent, joints
/// that form a cycle (naming the joint), or anything urdfdom could not read
/// (naming the link and element, and urdfdom's own words on the attribute),
/// or a `<gazebo reference><mu1>` or `<mu2>` that is not a number ≥ 0, or
/// a number of a sensor's markup it cannot read.
ParsedUrdf parseUrdf(const std::string& xml);

}  // namespace rigid_body_sim::io::detail
