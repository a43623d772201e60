// A world of bodies and robots from a config: scene_loader.h.
#include "rigid_body_sim/io/scene_loader.h"

#include <filesystem>
#include <map>
#include <utility>
#include <variant>

#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/input_bounds.h"
#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/robot.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/io/world.h"

namespace rigid_body_sim::io {
namespace {

/// What one URDF file describes.
using Described = std::variant<core::BodySpec, core::ArticulationModel>;

/// Each file of the bodies list read and parsed once (a world of 10,000
/// boxes names one URDF 10,000 times).
class Files {
 public:
  explicit Files(const SimConfig& config) : base_dir_(config.base_dir) {}
  const Described& get(const std::string& urdf) {
    auto it = files_.find(urdf);
    if (it != files_.end()) return it->second;
    const std::string path = resolveMeshUri(urdf, base_dir_);
    const std::string xml = readInput<UrdfError>(path, InputCaps::kUrdfBytes, "URDF");
    const std::string dir = std::filesystem::path(path).parent_path().string();
    Described described = describesRobot(xml, path) ? Described(loadArticulationString(xml, path, dir))
                                                    : Described(loadUrdfString(xml, path, dir));
    return files_.emplace(urdf, std::move(described)).first->second;
  }

 private:
  std::string base_dir_;
  std::map<std::string, Described> files_;
};

}  // namespace

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

SceneSetup buildScene(const SimConfig& config) {
  Files files(config);
  core::ModelSpec spec = config.model;
  spec.bodies.clear();
  std::vector<core::Scene::RobotSpec> robots;
  std::vector<core::LinkState> body_starts;
  std::vector<core::ArticulationState> robot_starts;
  std::vector<int> entry;
  for (std::size_t i = 0; i < config.bodies.size(); ++i) {
    const BodyEntry& e = config.bodies[i];
    const std::string key = "bodies[" + std::to_string(i) + "]";
    const Described& described = files.get(e.urdf);
    if (const auto* body = std::get_if<core::BodySpec>(&described)) {
      if (!e.initial_joints.empty()) {
        throw ConfigError("config key '" + key + ".initial.joint_positions' / '.joint_velocities': body '" + e.name +
                          "' has no moving joints");
      }
      checkStart(e.initial, config.model.limits, key + ".initial");
      core::BodySpec b = *body;
      b.name = e.name;
      b.friction = e.friction;
      b.restitution = e.restitution;
      entry.push_back(static_cast<int>(spec.bodies.size()));
      spec.bodies.push_back(std::move(b));
      body_starts.push_back(e.initial);
      continue;
    }
    core::ArticulationModel model = std::get<core::ArticulationModel>(described);
    model.name = e.name;
    checkRobotSettings(config, e.name);
    for (const auto& [what, set] : {std::pair<const char*, bool>{"imu", e.imu.has_value()},
                                    {"odom_noise", e.odom_noise.has_value()},
                                    {"cmd_vel", e.cmd_vel.has_value()}}) {
      if (set) {
        throw ConfigError("config key '" + key + "." + what + "': robot '" + e.name +
                          "' does not read it yet (a body's sensor and driver, not a robot's)");
      }
    }
    robot_starts.push_back(robotStart(model, e.initial, e.initial_joints, config.model.limits, key + ".initial"));
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
  return {std::move(scene), std::move(state), std::move(entry)};
}

}  // namespace rigid_body_sim::io
