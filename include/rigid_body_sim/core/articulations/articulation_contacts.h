// An articulation's links against the scene: the links as the contact
// detection sees them, and the contacts as rows of the articulation's
// joint-space impulse solve (docs/physics.md §11.8). Eigen only.
#pragma once

#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/bodies/model.h"

namespace rigid_body_sim::core {

/// The moving links that have collision shapes, each a body of `bodies`
/// (built as any body is: its contact points and solid from its shapes, its
/// mass and inertia). Links joined by a joint never touch each other; with
/// `contact.self_collision` off (Gazebo's default) no two links do: they
/// share one collision group. `bodies` also holds the scene, the contact
/// settings (surface, slop, sampling) and the solver's tolerances the step
/// uses.
struct ArticulationColliders {
  Model bodies;
  std::vector<int> link;        ///< body i is link link[i]
  bool self_collision = false;  ///< `contact.self_collision`
};

/// The moving links of `model` that have collision shapes, as bodies
/// (their mass, inertia and shapes; in `collision_group`, −1 for none):
/// body i is link link[i].
struct LinkBodies {
  std::vector<BodySpec> bodies;
  std::vector<int> link;
};
LinkBodies linkBodies(const ArticulationModel& model, int collision_group);

/// The colliders of `model` with the scene and settings of `settings` (its
/// bodies are ignored). A link a body could not be (a mass or inertia
/// outside the model's ranges) throws std::invalid_argument naming it.
ArticulationColliders articulationColliders(const ArticulationModel& model, const ModelSpec& settings);

/// The links of `colliders` as body states, placed and moving as `state`
/// puts them (each at its centre of mass, on its principal axes).
State linkStates(const ArticulationColliders& colliders, const ArticulationModel& model,
                 const ArticulationState& state);

}  // namespace rigid_body_sim::core
