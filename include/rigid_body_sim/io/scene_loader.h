// A world of bodies and robots from a config: each entry of its bodies list
// a free body, or a robot when its URDF has moving joints (docs/physics.md
// §11.9). rbsim's and the node's way to such a world; ROS-free.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/controllers.h"
#include "rigid_body_sim/io/sensor_mount.h"

namespace rigid_body_sim::io {

/// The scene and its start, and where each entry of the bodies list went.
struct SceneSetup {
  core::Scene scene;
  core::SceneState state;
  /// Per entry of config.bodies, in its order: a free body's index (≥ 0),
  /// or −1 − r for robot r.
  std::vector<int> entry;
  /// Per robot: its controllers (`controllers`, `bodies[i].controllers`).
  std::vector<RobotControls> controls;
  /// Per robot: its sensors on its links (`imu`, `odom_noise`, `lidar`,
  /// `depth_camera`, `bodies[i]`'s, then its URDF's Gazebo markup's).
  std::vector<RobotSensors> sensors;
  /// What loading it repaired or warns of, one message per URDF or start,
  /// for the caller to log once (io::UrdfOptions::notes).
  std::vector<std::string> notes;
};

/// A URDF's text, where it came from (for messages) and the folder its
/// relative mesh paths start from.
struct UrdfText {
  std::string xml, source, base_dir;
};

/// The URDF a `bodies` entry names (the node's: a parameter, or a file).
using UrdfReader = std::function<UrdfText(const BodyEntry&)>;

/// The URDF file `urdf` names (package://, absolute, or relative to
/// `base_dir`), read within the input caps.
UrdfText readUrdfFile(const std::string& urdf, const std::string& base_dir);

/// Whether some entry of the config's bodies list is a robot (its URDF has
/// a moving joint). Reads each named file once.
bool listsRobots(const SimConfig& config);

/// The scene of the config's bodies list with its settings: a body's entry
/// as buildWorld reads it, a robot's with its base at bodies[i].initial and
/// its joints at bodies[i].initial.joint_positions and .joint_velocities
/// (io::robotStart), its links' surface from bodies[i].contact. Each URDF
/// comes from `read` (default: readUrdfFile), once per name. Refused
/// (ConfigError naming the key): joint values for a body, and for a robot
/// fixed to the world its cmd_vel
/// and the settings io::checkRobotSettings refuses.
SceneSetup buildScene(const SimConfig& config, const UrdfReader& read = {});

/// The world a config describes, as the node runs it: its bodies list
/// (buildScene), or, when it has none, the one body or robot `single`
/// gives (the node's robot_description) at the config's `initial`, a
/// robot's joints at `initial.joint_positions` and `.joint_velocities`,
/// named as its URDF names it.
SceneSetup loadScene(const SimConfig& config, const std::function<UrdfText()>& single, const UrdfReader& read = {});

}  // namespace rigid_body_sim::io
