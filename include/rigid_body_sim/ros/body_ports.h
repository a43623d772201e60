// Each body's ports: what the node keeps per body beside the simulation
// (its tf frame, topics, sensors and velocity driver), in the model's order,
// and the directory that finds a body by name or frame. Opening, adding,
// removing and restarting a body's ports all go through here, so the ports
// and the names never disagree on which index is which body.
#pragma once

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/devices/body_sensors.h"
#include "rigid_body_sim/core/devices/odom_noise.h"
#include "rigid_body_sim/core/devices/velocity_driver.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/ros/body_directory.h"
#include "rigid_body_sim/ros/counted_publisher.h"

namespace rigid_body_sim::node {

/// What a body carries besides its shape (config keys imu, odom_noise, cmd_vel).
struct BodyDevices {
  std::optional<io::ImuEntry> imu;
  std::optional<core::OdomNoiseSettings> odom_noise;
  std::optional<core::DriverSettings> cmd_vel;
};

/// A body's names, topics and devices. Its names are fixed when it is
/// created: the one body of a world that starts with one has the single-body
/// names for life (its frame the root link, `odom`, `~wrench`); every other
/// body, listed in a world or spawned, has them under its name ("NAME/").
struct BodyPorts {
  std::string prefix;  ///< "" or "NAME/", before its frames and topics
  /// Its topics' handles (the node's, copied): a NodeHandle keeps a record
  /// of every topic opened through it for as long as it lives (264 bytes
  /// each, which the node's own handles kept for every body ever spawned).
  std::optional<ros::NodeHandle> nh, pnh;
  std::string frame;           ///< its tf frame: prefix + root link
  CountedPublisher odom;       ///< PREFIXodom
  ros::Subscriber wrench;      ///< ~PREFIXwrench
  bool speed_limited = false;  ///< the speed limits have held it (warned once)
  /// Its IMU and its odometry's noise (the core's), sampled whether or not
  /// anyone listens; none without either. Held apart: in place, the
  /// devices' random generators (2.5 KB each) made every body's ports 6 KB.
  std::unique_ptr<core::BodySensors> sensors;
  CountedPublisher imu_pub;                    ///< PREFIXimu, sensor_msgs/Imu
  std::string imu_frame;                       ///< prefix + the IMU's frame_id
  CountedPublisher ground_truth;               ///< PREFIXground_truth, with odom_noise (odom is then noisy)
  std::optional<core::VelocityDriver> driver;  ///< drives it toward its cmd_vel
  ros::Subscriber cmd_vel;                     ///< PREFIXcmd_vel, geometry_msgs/Twist
  bool clipped = false;                        ///< a command was clipped (warned once)
  std::size_t colour = 0;                      ///< its markers' colour: the order it entered the world in
};

/// What opening a body's ports needs of the node. Read only once made: the
/// spawn thread opens ports while the loop runs.
struct PortContext {
  ros::NodeHandle nh, pnh;  ///< the node's handles, and its private ones
  std::string world_frame;  ///< no body's frame may be this one
  double dt = 0.0;          ///< s, the step: the sensors' periods in steps
  /// Where a body's ~PREFIXwrench and PREFIXcmd_vel messages go, with the
  /// body's name (a deletion moves the later bodies' indices).
  std::function<void(const std::string&, const geometry_msgs::WrenchStamped::ConstPtr&)> on_wrench;
  std::function<void(const std::string&, const geometry_msgs::Twist::ConstPtr&)> on_cmd_vel;
};

/// The ports of `body` under `prefix`: its frames, topics and devices.
/// Throws io::ConfigError (an IMU on no such link, or on a taken frame)
/// before anything is advertised. Reads only its arguments, so the spawn
/// thread opens a spawned body's ports: each topic is a round trip to the
/// master, 1-2 ms the loop does not wait for. `topics` false: only its
/// devices' topics, none for odometry or wrenches (~per_body_topics).
BodyPorts openPorts(const PortContext& context, const core::BodyModel& body, const std::string& prefix,
                    const BodyDevices& devices, bool topics = true);

/// Every body's ports, in the model's order, and their names (BodyDirectory).
class PortRegistry {
 public:
  /// A removed body's ports are let go on `closer`'s thread: closing a topic
  /// waits for the master, which the loop must not.
  explicit PortRegistry(ros::CallbackQueue& closer) : closer_(&closer) {}

  /// Adds `ports` for `body`, the model's new last body: its sensors start
  /// at `start` at sim time `t`, it takes the next colour, and its names
  /// are indexed. Returns the ports as kept.
  BodyPorts& add(BodyPorts ports, const core::BodyModel& body, const core::BodyState& start, double t);
  /// Body i's ports and names go; the later bodies' indices move down by one.
  void erase(std::size_t i);
  /// Body i's sensors begin a new period at `now` (set_state: a jump is no acceleration).
  void restart(std::size_t i, const core::BodyModel& body, const core::BodyState& now);
  /// Every body's sensors begin again at `state`, the odometry noise's drift
  /// from zero (reset).
  void restartAll(const core::Model& model, const core::State& state);

  std::size_t size() const { return ports_.size(); }
  BodyPorts& operator[](std::size_t i) { return ports_[i]; }
  const BodyPorts& operator[](std::size_t i) const { return ports_[i]; }
  const BodyDirectory& directory() const { return directory_; }
  std::vector<std::string> frames() const;   ///< each body's tf frame, in the model's order
  std::vector<std::size_t> colours() const;  ///< each body's colour, in the model's order

 private:
  ros::CallbackQueue* closer_;
  std::vector<BodyPorts> ports_;
  BodyDirectory directory_;
  std::size_t entered_ = 0;  ///< bodies that have entered the world: the next one's colour
};

}  // namespace rigid_body_sim::node
