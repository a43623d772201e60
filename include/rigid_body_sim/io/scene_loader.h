// A world of bodies and robots from a config's bodies list: each entry a
// free body, or a robot when its URDF has moving joints (docs/physics.md
// §11.9). rbsim's way to such a world; ROS-free.
#pragma once

#include <string>
#include <vector>

#include "rigid_body_sim/core/scene.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io {

/// The scene and its start, and where each entry of the bodies list went.
struct SceneSetup {
  core::Scene scene;
  core::SceneState state;
  /// Per entry of config.bodies, in its order: a free body's index (≥ 0),
  /// or −1 − r for robot r.
  std::vector<int> entry;
};

/// Whether some entry of the config's bodies list is a robot (its URDF has
/// a moving joint). Reads each named file once.
bool listsRobots(const SimConfig& config);

/// The scene of the config's bodies list with its settings: a body's entry
/// as buildWorld reads it, a robot's with its base at bodies[i].initial and
/// its joints at bodies[i].initial.joint_positions and .joint_velocities
/// (io::robotStart), its links' surface from bodies[i].contact. Refused
/// (ConfigError naming the key): joint values for a body, and for a robot
/// the keys it does not read yet (bodies[i].imu, .odom_noise, .cmd_vel)
/// and the settings io::checkRobotSettings refuses.
SceneSetup buildScene(const SimConfig& config);

}  // namespace rigid_body_sim::io
