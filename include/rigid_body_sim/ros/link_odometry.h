// What robots' links report of where they are, each at its rate of sim
// time, stamped on the node's clock:
// - odometry: a robot's `odom_noise` (its base on `odom` with the noise,
//   exact on `ground_truth`) and Gazebo's gazebo_ros_p3d, each a
//   nav_msgs/Odometry of its link (core/devices/odom_noise.h,
//   docs/physics.md §10.2): the pose in the world frame, the twist in the
//   link's axes (child_frame_id); and gazebo_ros_planar_move's and
//   force_based_move's, the truth in their odometry frame (where the world
//   is), odom -> link on tf too;
// - hector's GNSS receivers (sensor_msgs/NavSatFix and its velocity,
//   geometry_msgs/Vector3Stamped) and magnetometers (Vector3Stamped or
//   sensor_msgs/MagneticField), core/devices/earth_sensors.h, §10.9.
// The noise is drawn whether or not anyone listens.
#pragma once

#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/devices/earth_sensors.h"
#include "rigid_body_sim/core/devices/odom_noise.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/io/sensor_mount.h"
#include "rigid_body_sim/ros/counted_publisher.h"

namespace rigid_body_sim::node {

class LinkOdometry {
 public:
  /// Each odometry of rate 0 at `publish_rate` Hz; `world_frame` heads every message.
  LinkOdometry(const ros::NodeHandle& nh, double dt, double publish_rate, std::string world_frame)
      : nh_(nh), dt_(dt), publish_rate_(publish_rate), world_frame_(std::move(world_frame)) {}
  /// Robot r's odometry, receivers and magnetometers of `sensors`: topics
  /// under `prefix` (an absolute topic as it is), frames after `frame_prefix`.
  void addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                const io::RobotSensors& sensors);
  /// The frames robot r's odometry puts on tf (odom -> frame, after its
  /// tf_prefix): the world's frame of its base leaves tf for them.
  std::vector<std::string> tfFrames(std::size_t r) const;
  /// Robot r deleted: its topics close; the later robots move down by one.
  void removeRobot(std::size_t r) {
    robots_.erase(robots_.begin() + static_cast<std::ptrdiff_t>(r));
    handles_.erase(handles_.begin() + static_cast<std::ptrdiff_t>(r));  // after what it opened
  }
  /// After a reset: each drift from zero, each noise from its seed.
  void restart();
  /// The reports due at step `steps` of `sim`'s state (sim time t), stamped `stamp`.
  void publish(const core::Simulation& sim, long long steps, double t, const ros::Time& stamp);

 private:
  /// Where a report comes from and when: a frame at X_LS in moving link
  /// `link`, every `every` steps, its last at `last` s of sim time (< 0:
  /// none yet).
  struct Schedule {
    int link = 0;
    core::Pose X_LS;
    long long every = 1;
    double last = -1.0;
    /// The s of sim time its noise moves over, from its last report to `t`.
    double elapsed(double t, double dt) {
      const double e = last < 0.0 ? static_cast<double>(every) * dt : t - last;
      last = t;
      return e;
    }
  };
  struct Port {
    Schedule at;
    std::string child;   ///< the link's frame: the twist's axes
    std::string frame;   ///< the pose's frame ("": the world's)
    bool on_tf = false;  ///< frame -> child on tf too
    std::optional<core::OdomNoise> noise;
    CountedPublisher odom, truth;
  };
  struct FixPort {
    Schedule at;
    core::Gnss gnss;
    std::string frame;
    int status = 0, service = 1;
    CountedPublisher fix, velocity;
  };
  struct FieldPort {
    Schedule at;
    core::Magnetometer magnetometer;
    std::string frame;
    bool field_message = false;
    CountedPublisher field;
  };
  struct RobotPorts {
    std::vector<Port> odometry;
    std::vector<FixPort> fixes;
    std::vector<FieldPort> fields;
  };

  ros::NodeHandle nh_;
  double dt_, publish_rate_;
  std::string world_frame_;
  std::vector<RobotPorts> robots_;
  std::vector<std::shared_ptr<ros::NodeHandle>> handles_;     ///< per robot, its own (ownHandle)
  core::ArticulationKinematics kin_;                          ///< reused by every report
  std::vector<geometry_msgs::TransformStamped> tf_;           ///< this publication's, reused
  std::optional<tf2_ros::TransformBroadcaster> broadcaster_;  ///< made with the first odometry on tf
};

}  // namespace rigid_body_sim::node
