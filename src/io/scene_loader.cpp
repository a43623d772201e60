// A world of bodies and robots from a config: scene_loader.h.
#include "rigid_body_sim/io/scene_loader.h"

#include <filesystem>
#include <map>
#include <optional>
#include <utility>
#include <variant>

#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/input_bounds.h"
#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/robot.h"
#include "rigid_body_sim/io/transmissions.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/io/world.h"

namespace rigid_body_sim::io {
namespace {

/// What one URDF file describes: a body, or a robot and the sensors of its Gazebo markup.
struct Described {
  std::variant<core::BodySpec, core::ArticulationModel> what;
  RobotDevices sensors;
};

/// A body, or a robot when the URDF has a moving joint.
Described describe(const UrdfText& text, UrdfOptions options) {
  Described d;
  if (describesRobot(text.xml, text.source)) {
    options.sensors = &d.sensors;
    d.what = loadArticulationString(text.xml, text.source, text.base_dir, options);
  } else {
    d.what = loadUrdfString(text.xml, text.source, text.base_dir, options);
  }
  return d;
}

/// The sensors a robot's config entry (or the one robot's config, `key`
/// "") puts on its links: `odom_noise` is its base's odometry.
RobotDevices configSensors(const std::optional<ImuEntry>& imu, const std::optional<core::OdomNoiseSettings>& odom_noise,
                           const std::vector<LidarEntry>& lidars, const std::vector<DepthCameraEntry>& cameras,
                           const std::string& key) {
  RobotDevices s;
  s.lidars = lidars;
  s.cameras = cameras;
  if (imu) s.imus.push_back(*imu);
  if (odom_noise) s.odometry.push_back(OdometryEntry::ofOdomNoise(*odom_noise, key + "odom_noise"));
  return s;
}

/// The config's controllers, then the drives of the URDF's markup.
std::vector<ControllerEntry> allControllers(std::vector<ControllerEntry> config, const RobotDevices& markup) {
  config.insert(config.end(), markup.controllers.begin(), markup.controllers.end());
  return config;
}

/// Each URDF of the bodies list read and parsed once (a world of 10,000
/// boxes names one URDF 10,000 times).
class Files {
 public:
  Files(const SimConfig& config, const UrdfReader& read, std::vector<std::string>& notes)
      : base_dir_(config.base_dir), read_(read), options_{config.urdf_repair, &notes} {}
  const Described& get(const BodyEntry& entry) {
    auto it = files_.find(entry.urdf);
    if (it != files_.end()) return it->second;
    return files_.emplace(entry.urdf, describe(read_ ? read_(entry) : readUrdfFile(entry.urdf, base_dir_), options_))
        .first->second;
  }

 private:
  std::string base_dir_;
  const UrdfReader& read_;
  UrdfOptions options_;
  std::map<std::string, Described> files_;
};

/// The warnings for the scene's bodies and robots that start inside the
/// static scene (insideSceneNote).
void noteStartsInside(const core::Scene& scene, const core::SceneState& state, std::vector<std::string>& notes) {
  const core::Model& model = scene.model();
  for (std::size_t i = 0; i < scene.freeBodyCount(); ++i) {
    const std::string note = insideSceneNote(model, state.bodies, i, 1, "body '" + model.body(i).name + "'");
    if (!note.empty()) notes.push_back(note);
  }
  for (const core::SceneRobot& robot : scene.robots()) {
    const std::string note = insideSceneNote(model, state.bodies, static_cast<std::size_t>(robot.first_body),
                                             robot.link.size(), "robot '" + robot.name + "'");
    if (!note.empty()) notes.push_back(note);
  }
}

}  // namespace

UrdfText readUrdfFile(const std::string& urdf, const std::string& base_dir) {
  const std::string path = resolveMeshUri(urdf, base_dir);
  return {readInput<UrdfError>(path, InputCaps::kUrdfBytes, "URDF"), path,
          std::filesystem::path(path).parent_path().string()};
}

bool listsRobots(const SimConfig& config) {
  std::map<std::string, bool> seen;
  for (const BodyEntry& entry : config.bodies) {
    auto it = seen.find(entry.urdf);
    if (it == seen.end()) {
      const std::string path = resolveMeshUri(entry.urdf, config.base_dir);
      it = seen.emplace(entry.urdf, describesRobot(readInput<UrdfError>(path, InputCaps::kUrdfBytes, "URDF"), path))
               .first;
    }
    if (it->second) return true;
  }
  return false;
}

SceneSetup buildScene(const SimConfig& config, const UrdfReader& read) {
  std::vector<std::string> notes;
  Files files(config, read, notes);
  core::ModelSpec spec = config.model;
  spec.bodies.clear();
  std::vector<core::Scene::RobotSpec> robots;
  std::vector<core::LinkState> body_starts;
  std::vector<core::ArticulationState> robot_starts;
  std::vector<int> entry;
  std::vector<RobotControls> controls;
  std::vector<RobotSensors> sensors;
  DeviceMemory memory{config.device_memory};
  for (std::size_t i = 0; i < config.bodies.size(); ++i) {
    const BodyEntry& e = config.bodies[i];
    const std::string key = "bodies[" + std::to_string(i) + "]";
    const Described& described = files.get(e);
    if (const auto* body = std::get_if<core::BodySpec>(&described.what)) {
      if (!e.controllers.empty()) {
        throw ConfigError("config key '" + key + ".controllers': body '" + e.name + "' has no moving joints");
      }
      if (!e.lidars.empty() || !e.cameras.empty()) {
        throw ConfigError(
            "config key '" + key + ".lidar': body '" + e.name +
            "' has no moving joints: a lidar or depth camera goes on a robot's link (not on a free body yet)");
      }
      if (!e.initial_joints.empty()) {
        throw ConfigError("config key '" + key + ".initial.joint_positions' / '.joint_velocities': body '" + e.name +
                          "' has no moving joints");
      }
      checkStart(e.initial, config.model.limits, key + ".initial");
      core::BodySpec b = *body;
      b.name = e.name;
      if (e.friction) core::setBodyFriction(b, *e.friction);  // else its URDF's <mu1>, or the scene's
      b.restitution = e.restitution;
      entry.push_back(static_cast<int>(spec.bodies.size()));
      spec.bodies.push_back(std::move(b));
      body_starts.push_back(e.initial);
      continue;
    }
    core::ArticulationModel model = std::get<core::ArticulationModel>(described.what);
    model.name = e.name;
    checkRobotSettings(config, e.name);
    robot_starts.push_back(robotStart(model, e.initial, e.initial_joints, config.model.limits, key + ".initial"));
    controls.push_back(buildControls(allControllers(e.controllers, described.sensors), model));
    addBaseDrive(e.cmd_vel, described.sensors.base_drive, model, key + ".", controls.back());
    controls.back().robot_namespace = described.sensors.robot_namespace;
    notes.insert(notes.end(), controls.back().notes.begin(), controls.back().notes.end());
    for (std::string& note : transmissionNotes(e.controllers, described.sensors.transmissions, model)) {
      notes.push_back(std::move(note));
    }
    sensors.push_back(mountSensors(configSensors(e.imu, e.odom_noise, e.lidars, e.cameras, key + "."),
                                   described.sensors, model, spec.dt, memory));
    notes.insert(notes.end(), sensors.back().notes.begin(), sensors.back().notes.end());
    entry.push_back(-1 - static_cast<int>(robots.size()));
    robots.push_back({e.name, std::move(model), e.friction, e.restitution});
  }
  core::Scene scene(spec, std::move(robots));
  core::State free;
  free.bodies.resize(body_starts.size());
  for (std::size_t i = 0; i < body_starts.size(); ++i) {
    free.bodies[i] = core::bodyStateFromLink(scene.model().body(i), body_starts[i]);
  }
  core::SceneState state = core::sceneState(scene, free, robot_starts);
  noteStartsInside(scene, state, notes);
  return {std::move(scene),    std::move(state),   std::move(entry),
          std::move(controls), std::move(sensors), std::move(notes)};
}

}  // namespace rigid_body_sim::io

namespace rigid_body_sim::io {

SceneSetup loadScene(const SimConfig& config, const std::function<UrdfText()>& single, const UrdfReader& read) {
  if (config.bodies_listed) return buildScene(config, read);
  if (!single) throw ConfigError("bodies: the config lists no bodies, and no single body was given");
  std::vector<std::string> notes;
  Described described = describe(single(), UrdfOptions{config.urdf_repair, &notes});
  if (auto* body = std::get_if<core::BodySpec>(&described.what)) {
    if (!config.controllers.empty()) {
      throw ConfigError("config key 'controllers': body '" + body->name + "' has no moving joints");
    }
    if (!config.lidars.empty() || !config.cameras.empty()) {
      throw ConfigError("config key 'lidar': body '" + body->name +
                        "' has no moving joints: a lidar goes on a robot's link (not on a free body yet)");
    }
    World world = loadWorld(config, [&] { return std::move(*body); });
    notes.insert(notes.end(), world.notes.begin(), world.notes.end());
    core::Scene scene(std::move(world.model));
    core::SceneState state{std::move(world.state), {}};
    return {std::move(scene), std::move(state), {0}, {}, {}, std::move(notes)};
  }
  core::ArticulationModel model = std::move(std::get<core::ArticulationModel>(described.what));
  checkRobotSettings(config, model.name);
  core::ArticulationState start =
      robotStart(model, config.initial, config.initial_joints, config.model.limits, "initial");
  RobotControls controls = buildControls(allControllers(config.controllers, described.sensors), model);
  addBaseDrive(config.cmd_vel, described.sensors.base_drive, model, "", controls);
  controls.robot_namespace = described.sensors.robot_namespace;
  notes.insert(notes.end(), controls.notes.begin(), controls.notes.end());
  for (std::string& note : transmissionNotes(config.controllers, described.sensors.transmissions, model)) {
    notes.push_back(std::move(note));
  }
  DeviceMemory memory{config.device_memory};
  RobotSensors sensors = mountSensors(configSensors(config.imu, config.odom_noise, config.lidars, config.cameras, ""),
                                      described.sensors, model, config.model.dt, memory);
  notes.insert(notes.end(), sensors.notes.begin(), sensors.notes.end());
  core::ModelSpec spec = config.model;
  spec.bodies.clear();
  const std::string name = model.name;
  core::Scene scene(spec, {{name, std::move(model)}});
  core::SceneState state = core::sceneState(scene, {}, {start});
  noteStartsInside(scene, state, notes);
  return {std::move(scene), std::move(state), {-1}, {std::move(controls)}, {std::move(sensors)}, std::move(notes)};
}

}  // namespace rigid_body_sim::io
