// What the node publishes of the world's state: every body's tf in one
// message and its odometry (noisy with ground_truth beside), ~body_states,
// /clock on sim time, and the fixed frames on /tf_static. The messages are
// built by plain functions (tested without a master); the class sends them,
// each only when someone listens.
#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/BodyStates.h"
#include "rigid_body_sim/Contacts.h"
#include "rigid_body_sim/core/contacts/contact_report.h"
#include "rigid_body_sim/core/devices/odom_noise.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/ros/body_ports.h"
#include "rigid_body_sim/ros/counted_publisher.h"
#include "rigid_body_sim/ros/params.h"

namespace rigid_body_sim::node {

/// nav_msgs/Odometry of `report`, its twist in `child_frame` (the body's
/// frame, as nav_msgs says); the covariances the report's, or `exact`'s
/// on the diagonal for the exact state.
nav_msgs::Odometry odometryMessage(const core::OdomReport& report, const std::string& child_frame,
                                   const std_msgs::Header& header, std::optional<double> exact);

/// ~body_states: every body's pose, and its twist in its own frame (as
/// ports' frames name them) or, `in_world`, in the world's axes.
BodyStates bodyStatesMessage(const core::Model& model, const core::State& state, const PortRegistry& ports,
                             const std_msgs::Header& header, bool in_world);
/// Appends each robot of `sim` to `msg` after the bodies, by its name: its
/// base link's pose and twist (a world-fixed robot's where it is fixed, at
/// rest, its twist in the world's axes), as Gazebo's model_states has every
/// model.
void appendRobotBases(const core::Simulation& sim, bool in_world, BodyStates& msg);

/// m of arrow per N in ~contact_markers.
inline constexpr double kContactForceScale = 0.01;

/// ~contacts: each touching pair (core::contactPairs) by name, the scene's
/// items as "scene[i]".
Contacts contactsMessage(const core::Model& model, const std::vector<core::ContactPairReport>& pairs,
                         const std_msgs::Header& header);
/// ~contact_markers of `contacts`: every point, and an arrow per force from
/// each pair's centre, kContactForceScale m per N, after a DELETEALL.
visualization_msgs::MarkerArray contactMarkers(const Contacts& contacts);

/// Appends the frames fixed to `body` (its fixed links, its IMU), under
/// its ports' prefix, stamped `stamp`.
void appendFixedFrames(const core::BodyModel& body, const BodyPorts& ports, const ros::Time& stamp,
                       std::vector<geometry_msgs::TransformStamped>& frames);

class StatePublisher {
 public:
  /// Advertises ~body_states, ~contacts, ~contact_markers, /tf_static
  /// (latched) and, on sim time, /clock.
  /// `settings` are read at each publish: ~physics changes some.
  StatePublisher(ros::NodeHandle nh, ros::NodeHandle pnh, const NodeSettings& settings, bool use_sim_time);

  /// /clock at `now`, on sim time.
  void clock(const ros::Time& now);
  /// Every body's tf in one message and its odometry, at `now`, sim time
  /// `t` (s); a noisy odometry (and its ground_truth) only `on_rate`, at a
  /// multiple of the publish period in steps, so its draws follow the step
  /// count, never where a ~step ended. Never at the same stamp twice (tf2
  /// would warn of repeated data) or an older one: false, and nothing sent, then.
  bool state(const core::Simulation& sim, PortRegistry& ports, const ros::Time& now, double t, bool on_rate);
  /// ~contacts and ~contact_markers (contacts.cpp), while someone subscribes.
  void contacts(const core::Simulation& sim, const ros::Time& now);
  /// ~body_states, while someone subscribes.
  void bodyStates(const core::Simulation& sim, const PortRegistry& ports, const ros::Time& now);
  /// The frames fixed to bodies `first` on are added to the set on
  /// /tf_static (0: the set made again, a deleted body's frames gone), and
  /// the set goes whole, as tf2_ros's static broadcaster sends it.
  void fixedFrames(const core::Model& model, const PortRegistry& ports, const ros::Time& now, std::size_t first = 0);

 private:
  const NodeSettings& settings_;
  bool use_sim_time_;
  ros::Publisher clock_pub_;
  CountedPublisher body_states_pub_, contacts_pub_, contact_markers_pub_;
  tf2_ros::TransformBroadcaster tf_;
  std::vector<geometry_msgs::TransformStamped> tf_batch_;  ///< every body's transform, filled in place
  ros::Time last_published_;
  /// The node keeps the static set itself so that a deleted body's frames
  /// leave it (the broadcaster keeps all it was given, and making a new one
  /// cost two round trips to the master per delete).
  ros::Publisher tf_static_pub_;
  tf2_msgs::TFMessage static_frames_;
};

}  // namespace rigid_body_sim::node
