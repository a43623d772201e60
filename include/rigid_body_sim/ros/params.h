// The node's private parameters: its own settings plus the simulation keys,
// which go through the same parser as rbsim's YAML config (io/config.h).
#pragma once

#include <ros/node_handle.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>
#include <vector>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::node {

/// Settings of the node itself (not of the simulation).
/// Each number has a range, refused outside it at start naming the key.
struct NodeSettings {
  double rate = 1000.0;               ///< ~rate: Hz of wall clock at which the loop ticks, [1, 1e4]
  double realtime_factor = 1.0;       ///< ~realtime_factor: sim s per wall s, [0, 1000]; 0 = as fast as possible
  double publish_rate = 100.0;        ///< ~publish_rate: Hz of sim time for odom, tf and /clock, [0.01, 1e4]
  std::string world_frame = "world";  ///< ~world_frame: parent frame of the body's transform (no body's own frame)
  double wrench_timeout = 1.0;  ///< ~wrench_timeout: s of sim time a ~wrench message is held, [0, 1e6]; 0: forever
  double covariance = 1e-9;     ///< ~covariance: diagonal of the odometry covariances (ground truth)
  double scene_size = 20.0;     ///< ~scene_size: m, extent drawn for planes and unbounded shapes
  bool report_timing = false;   ///< ~report_timing: log the tick-period jitter at shutdown
  bool paused = false;          ///< ~paused: start paused (Gazebo's paused:=true), for ~step or ~unpause
  /// ~publish_tf: send each body's world → root link transform; false leaves
  /// that to the user's own estimator (REP 105). Fixed links stay on /tf_static.
  bool publish_tf = true;
  double body_states_rate = 100.0;  ///< ~body_states_rate: Hz of sim time of ~body_states, [0.01, 1e4]
  /// ~per_body_topics: a world of at most this many bodies at start gives
  /// each its odometry and wrench topics; a larger one only those with a
  /// device (imu, odom_noise, cmd_vel), each a round trip to the master and
  /// its memory. ~body_states, /tf and the services carry every body; a
  /// spawned body always has its topics. [0, 1e9]
  double per_body_topics = 100;
  /// ~body_states_twist: "body" (each twist in its root link frame, as
  /// nav_msgs/Odometry) or "world" (in ~world_frame's axes, as Gazebo's model_states).
  bool body_states_twist_in_world = false;
  /// ~config_file: the file these parameters were loaded from (the launch
  /// files set it); relative `urdf` paths in `bodies` resolve from its folder.
  std::string config_file;

  // The ranges are in nodeParamKeys(), one per parameter.
};

struct NodeParams {
  NodeSettings node;
  io::SimConfig sim;
  YAML::Node sim_yaml;  ///< the simulation keys as read, for the log: all but a bodies list (sim.bodies has it)
};

/// Reads every private parameter once. Keys of NodeSettings are the node's;
/// every other key is a simulation key (config/default.yaml) and is parsed
/// by io::parseConfig, so unknown keys and bad values are refused with the
/// key's name (io::ConfigError).
NodeParams readParams(const ros::NodeHandle& private_nh);

/// One of the node's own parameters: its name (`~rate`), unit, the one range
/// it is checked against at start and when ~physics changes it, and its
/// NodeSettings field (of the same name). Live tuning (cfg/Physics.cfg)
/// names it the same.
struct NodeParamKey {
  enum class Kind { kNumber, kFlag, kText };
  std::string_view key;  ///< "publish_rate"
  std::string_view unit;
  Kind kind = Kind::kNumber;
  double min = 0.0, max = 0.0;                 ///< kNumber: [min, max]
  bool zero_too = false;                       ///< kNumber: 0 is accepted besides [min, max] (~realtime_factor)
  std::string_view zero_means;                 ///< what 0 means, for the message
  double* (*number)(NodeSettings&) = nullptr;  ///< kNumber
  bool* (*flag)(NodeSettings&) = nullptr;      ///< kFlag
};

/// Every parameter of the node itself (the others are simulation keys).
const std::vector<NodeParamKey>& nodeParamKeys();

/// The entry of `key`, or nullptr.
const NodeParamKey* findNodeParamKey(std::string_view key);

/// Refuses x outside the parameter's range (or not finite) with an
/// io::ConfigError naming `~key` and the range.
void checkNodeParam(const NodeParamKey& key, double x);

/// A parameter tree as YAML (structs → maps, arrays → sequences).
YAML::Node toYaml(const XmlRpc::XmlRpcValue& value);

}  // namespace rigid_body_sim::node
