// A body's devices in the config: its sensors (`imu`, `odom_noise`) and its
// velocity driver (`cmd_vel`), top level for one body or each body's. Private to io.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

/// An `imu` map at `path`: frame_id, pose {position, rpy | quaternion},
/// rate, seed, gyro_noise, accel_noise, gyro_bias_walk, accel_bias_walk,
/// orientation_noise (units in config/default.yaml).
ImuEntry parseImu(const YAML::Node& node, const std::string& path);

/// An `odom_noise` map at `path`: position, orientation, linear_velocity,
/// angular_velocity, drift {x, y, yaw}, seed; checked (ConfigError).
core::OdomNoiseSettings parseOdomNoise(const YAML::Node& node, const std::string& path);

/// A `cmd_vel` map at `path`: the core::DriverSettings keys; checked (ConfigError).
core::DriverSettings parseDriver(const YAML::Node& node, const std::string& path);

/// The core's checks of an IMU for a model of step `dt`, as a ConfigError naming `path`.
/// `lidar` at `path`: one lidar's map, or a list of them (each key read or
/// refused; the settings checked by core::checkLidar, refusals naming the key).
std::vector<LidarEntry> parseLidars(const YAML::Node& node, const std::string& path);
/// `depth_camera` at `path`: one camera's map, or a list of them, as parseLidars.
std::vector<DepthCameraEntry> parseDepthCameras(const YAML::Node& node, const std::string& path);
void validateImuEntry(const ImuEntry& imu, double dt, const std::string& path);

}  // namespace rigid_body_sim::io
