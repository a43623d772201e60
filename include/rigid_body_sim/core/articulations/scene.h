// A world of free bodies and robots that touch each other: the robots'
// links are bodies of one Model (the detection sees them as any body), and
// every contact a robot is part of is a row of one impulse solve with the
// robots' joints and the free bodies it holds (docs/physics.md §11.9).
// Eigen only.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/articulations/articulation_step.h"
#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/loads.h"
#include "rigid_body_sim/core/step/workspace.h"

namespace rigid_body_sim::core {

/// A robot of a scene: its articulation, and its links among the scene's
/// bodies.
struct SceneRobot {
  std::string name;
  ArticulationModel model;
  int first_body = 0;     ///< body first_body + i of the scene's model is link link[i]
  std::vector<int> link;  ///< the moving links with collision shapes
};

/// The free bodies, the robots, the settings: fixed while it steps.
class Scene {
 public:
  /// One named articulation.
  struct RobotSpec {
    std::string name;
    ArticulationModel model;
    /// Its links' surface (as BodySpec's); unset: the scene's.
    std::optional<double> friction = std::nullopt, restitution = std::nullopt;
  };

  /// `spec` gives the free bodies and every setting (scene, contact,
  /// sleep, solver, limits); each robot's links with collision shapes
  /// become bodies after them, named ROBOT/LINK. With `contact.self_collision` off a robot's
  /// links share a collision group of their own. Throws
  /// std::invalid_argument as Model does, naming the link.
  Scene(const ModelSpec& spec, std::vector<RobotSpec> robots);
  /// A scene of free bodies only: `model`'s.
  explicit Scene(Model model);

  // Edits between steps (core::Simulation makes them, with the state's).
  /// Adds a free body last among the free bodies, before the robots'
  /// links (which move up by one). Throws as Model::addBody does, and then
  /// nothing has changed.
  void addBody(const PreparedBody& body);
  /// Adds a robot last: its links become bodies after every other, in a
  /// collision group of their own (unless self-collision is on), named
  /// ROBOT/LINK, as the constructor makes them. Throws std::invalid_argument
  /// for a name another robot has, or as Model::addBody does for a link;
  /// then nothing has changed.
  void addRobot(RobotSpec robot);
  /// Takes free body i out (Model::removeBody); the links after it move
  /// down by one. Throws std::invalid_argument for a link or no body.
  void removeBody(std::size_t i);
  /// Takes robot r out, its links with it (the later robots' links move
  /// down); the later robots move down by one. Throws
  /// std::invalid_argument for no such robot.
  void removeRobot(std::size_t r);
  /// The settings `tuning` gives (Model::retuned: throws and changes nothing
  /// when a check refuses them).
  void retune(const Tuning& tuning) { model_ = model_.retuned(tuning); }

  /// The free bodies (0 .. freeBodyCount() − 1), then the robots' links.
  const Model& model() const { return model_; }
  std::size_t freeBodyCount() const { return free_bodies_; }
  const std::vector<SceneRobot>& robots() const { return robots_; }
  /// The robot body i is a link of, or −1 for a free body.
  int robotOf(std::size_t body) const { return robot_of_[body]; }

 private:
  std::vector<SceneRobot> robots_;  // before model_: its constructor fills them
  Model model_;
  std::size_t free_bodies_ = 0;
  std::vector<int> robot_of_;
};

/// A scene's state: its bodies' (the links' are set from the robots' after
/// every step, for the detection and for whoever reads them) and its robots'.
/// `bodies.time` is the scene's time.
struct SceneState {
  State bodies;
  std::vector<ArticulationState> robots;
};

/// The free bodies at `bodies` (one per free body), the robots at
/// `robots` (one per robot), the links where their robots put them.
SceneState sceneState(const Scene& scene, const State& bodies, const std::vector<ArticulationState>& robots);

/// Robot r at `now`, its links placed where it puts them in `bodies`.
void placeRobot(const Scene& scene, std::size_t r, const ArticulationState& now, State& bodies);

/// What acts over one step: per free body (empty for none; or per body,
/// the links' zero, as WrenchSchedule::loadsFor gives them), per robot
/// (empty for none).
struct SceneLoads {
  Loads bodies;
  std::vector<ArticulationLoads> robots;
};

namespace detail {
struct SceneScratch;
}

/// The memory a scene's step reuses, and its outputs. Results never depend
/// on it.
struct SceneWorkspace {
  SceneWorkspace();
  ~SceneWorkspace();
  SceneWorkspace(SceneWorkspace&&) noexcept;
  SceneWorkspace& operator=(SceneWorkspace&&) noexcept;

  /// The free bodies' knobs (threads) and the step's outputs: `contacts`
  /// (every contact, links by their body index, sorted by key, with their
  /// impulses), the deepest penetration, the bodies the speed limits held
  /// or the guard put back.
  Workspace bodies;
  std::vector<ArticulationWorkspace> robots;  ///< per robot; `speed_limited` its output
  /// Per robot: whether the guard put it back in the last step (§11.7).
  std::vector<char> robot_diverged;
  /// The stages' scratch memory; not for callers.
  std::unique_ptr<detail::SceneScratch> scratch;
};

/// Advances the scene by one step of the model's dt (§11.9): the robots'
/// predictions; detection over every body; the contacts of islands without a
/// robot solved as free bodies' are (§5.5); every robot's joint rows and the
/// contacts of the islands that hold a robot, with the free bodies in them,
/// in one joint-space solve; then positions. The guard, the speed limits and
/// sleep act as on their own; an island that holds a robot sleeps as a
/// whole, robots and bodies, when every one of them has been still for the
/// sleep time, and a sleeping robot is, to the others, as a sleeping body
/// is (ground, woken when something comes at it, or by a load). Throws
/// std::invalid_argument for loads of the wrong size.
void stepScene(const Scene& scene, SceneState& state, const SceneLoads& loads, SceneWorkspace& ws);

}  // namespace rigid_body_sim::core
