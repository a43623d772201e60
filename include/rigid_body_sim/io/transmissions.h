// A robot's controllers checked against its URDF's <transmission>s, as
// gazebo_ros_control checks them: it runs a controller only on joints a
// transmission declares, through a hardware interface the controller's
// type commands. This project runs them either way (through a PID on
// effort); the check says where the description would not run in Gazebo.
// ROS-free.
#pragma once

#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

/// The hardware interface a controller type commands, as ros_controllers'
/// packages name it: EffortJointInterface (effort_controllers/*),
/// VelocityJointInterface (velocity_controllers/*, a DiffDriveController),
/// PositionJointInterface (position_controllers/*); "" for one that only
/// reads (joint_state_controller).
std::string commandedInterface(const std::string& type);

/// One warning per problem, naming the controller's key, the joint and the
/// transmission: a transmission of a joint `model` does not have; a
/// commanding controller's joint no transmission declares, or none with
/// its interface. None when `transmissions` is empty (a description not
/// written for gazebo_ros_control).
std::vector<std::string> transmissionNotes(const std::vector<ControllerEntry>& controllers,
                                           const std::vector<TransmissionEntry>& transmissions,
                                           const core::ArticulationModel& model);

}  // namespace rigid_body_sim::io
