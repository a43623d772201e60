// The contact sensors on robots' links in the node (Gazebo's
// gazebo_ros_bumper): each publishes, at its rate of sim time, every pair
// touching its link as rigid_body_sim/Contacts (the message of ~contacts;
// gazebo_msgs/ContactsState is not in Debian 12), its link on the `body`
// side, in the world frame or in a frame fixed to the link, stamped on the
// node's clock. Nothing is sent while nobody listens.
#pragma once

#include <ros/ros.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/io/sensor_mount.h"
#include "rigid_body_sim/ros/counted_publisher.h"

namespace rigid_body_sim::node {

class LinkContacts {
 public:
  /// `world_frame` heads the reports given in the world.
  LinkContacts(const ros::NodeHandle& nh, double dt, std::string world_frame)
      : nh_(nh), dt_(dt), world_frame_(std::move(world_frame)) {}
  /// Robot r's contact sensors: topics under `prefix` (an absolute topic
  /// as it is), frames after `frame_prefix`.
  void addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                const std::vector<io::RobotContactSensor>& sensors);
  /// Robot r deleted: its topics close; the later robots move down by one.
  void removeRobot(std::size_t r) {
    robots_.erase(robots_.begin() + static_cast<std::ptrdiff_t>(r));
    handles_.erase(handles_.begin() + static_cast<std::ptrdiff_t>(r));  // after what it opened
  }
  /// The reports due at step `steps` of `sim` (its contacts as they touch
  /// now), stamped `stamp`.
  void publish(const core::Simulation& sim, long long steps, const ros::Time& stamp);

 private:
  struct Port {
    int link = 0;  ///< the moving link (index in the robot's model)
    bool in_world = true;
    core::Pose X_LS;  ///< the reports' frame in the link, unless in the world
    std::string frame;
    long long every = 1;
    CountedPublisher contacts;
  };

  ros::NodeHandle nh_;
  double dt_;
  std::string world_frame_;
  std::vector<std::vector<Port>> robots_;
  std::vector<std::shared_ptr<ros::NodeHandle>> handles_;  ///< per robot, its own (ownHandle)
  core::ArticulationKinematics kin_;                       ///< reused by every report
};

}  // namespace rigid_body_sim::node
