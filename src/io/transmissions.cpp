// A robot's controllers against its URDF's transmissions: transmissions.h.
#include "rigid_body_sim/io/transmissions.h"

#include <algorithm>
#include <utility>

namespace rigid_body_sim::io {

std::string commandedInterface(const std::string& type) {
  const std::string package = type.substr(0, type.find('/'));
  if (package == "effort_controllers") return "EffortJointInterface";
  if (package == "velocity_controllers" || package == "diff_drive_controller" ||
      package == "mecanum_drive_controller") {
    return "VelocityJointInterface";
  }
  if (package == "position_controllers") return "PositionJointInterface";
  return "";
}

std::vector<std::string> transmissionNotes(const std::vector<ControllerEntry>& controllers,
                                           const std::vector<TransmissionEntry>& transmissions,
                                           const core::ArticulationModel& model) {
  std::vector<std::string> notes;
  if (transmissions.empty()) return notes;
  const auto has_joint = [&model](const std::string& joint) {
    return std::any_of(model.links.begin(), model.links.end(),
                       [&joint](const core::ArticulatedLink& l) { return l.joint == joint; }) ||
           std::any_of(model.held.begin(), model.held.end(),
                       [&joint](const core::HeldJoint& h) { return h.name == joint; });
  };
  for (const TransmissionEntry& t : transmissions) {
    for (const std::string& joint : t.joints) {
      if (!has_joint(joint)) {
        notes.push_back("robot '" + model.name + "': <transmission name=\"" + t.name + "\"> drives joint '" + joint +
                        "', which it does not have (gazebo_ros_control refuses it)");
      }
    }
  }
  for (const ControllerEntry& c : controllers) {
    const std::string interface = commandedInterface(c.type);
    if (interface.empty()) continue;
    for (const std::string& joint : c.joints) {
      std::vector<const TransmissionEntry*> of;
      for (const TransmissionEntry& t : transmissions) {
        if (std::find(t.joints.begin(), t.joints.end(), joint) != t.joints.end()) of.push_back(&t);
      }
      const bool matches = std::any_of(of.begin(), of.end(), [&interface](const TransmissionEntry* t) {
        return std::find(t->interfaces.begin(), t->interfaces.end(), interface) != t->interfaces.end();
      });
      if (matches) continue;
      const std::string why =
          of.empty() ? "no <transmission> declares joint '" + joint + "'"
                     : "joint '" + joint + "''s <transmission name=\"" + of[0]->name + "\"> declares no " + interface;
      notes.push_back("config key '" + c.key + "' (" + c.type + "): " + why +
                      ": gazebo_ros_control would not run it on this URDF (it runs here, through a PID on effort)");
    }
  }
  return notes;
}

}  // namespace rigid_body_sim::io
