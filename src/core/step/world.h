// The one step of any world, free bodies and robots alike (private to the
// core): what it reads, advances and keeps, as views of a Scene's or of a
// Model's alone, so core::step, core::stepScene and core::Simulation::step
// all run the one list of stages in step.cpp (docs/physics.md §4, §11.9).
#pragma once

#include <cstddef>
#include <vector>

#include "rigid_body_sim/core/articulations/scene.h"

namespace rigid_body_sim::core::detail {

/// What the step reads: a scene, or a model of free bodies alone (no
/// robots), with a scene's accessors.
class World {
 public:
  explicit World(const Scene& scene) : scene_(&scene), model_(&scene.model()) {}
  explicit World(const Model& model) : model_(&model) {}
  const Model& model() const { return *model_; }
  const std::vector<SceneRobot>& robots() const {
    static const std::vector<SceneRobot> none;
    return scene_ != nullptr ? scene_->robots() : none;
  }
  std::size_t freeBodyCount() const { return scene_ != nullptr ? scene_->freeBodyCount() : model_->bodyCount(); }
  int robotOf(std::size_t body) const { return scene_ != nullptr ? scene_->robotOf(body) : -1; }

 private:
  const Scene* scene_ = nullptr;
  const Model* model_;
};

/// The state a step advances: the bodies' (links included) and the robots'.
struct WorldState {
  State& bodies;
  std::vector<ArticulationState>& robots;
};

/// What acts over the step: per free body (or per body, or none), per robot (or none).
struct WorldLoads {
  const Loads& bodies;
  const std::vector<ArticulationLoads>& robots;
};

struct SceneScratch;  // scene_stages.h

/// The step's memory and outputs: the bodies' workspace, per robot its
/// own, and the robots' stages' scratch (null without robots).
struct WorldWorkspace {
  Workspace& bodies;
  std::vector<ArticulationWorkspace>& robots;
  std::vector<char>& robot_diverged;
  SceneScratch* scratch;
};

#pragma GCC visibility push(hidden)

/// One step of dt of `world` (step.cpp): the free bodies' stages and the
/// robots', each list doing nothing where the world has none. Throws
/// std::invalid_argument for a state or loads that do not fit the world.
/// `ws.scratch` may be null for a world without robots.
void stepWorld(const World& world, WorldState& state, const WorldLoads& loads, WorldWorkspace& ws);

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
