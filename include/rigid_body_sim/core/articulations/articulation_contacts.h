// An articulation's links against the scene: the links as the contact
// detection sees them, and the contacts as rows of the articulation's
// joint-space impulse solve (docs/physics.md §11.8). Eigen only.
#pragma once

#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/bodies/model.h"

namespace rigid_body_sim::core {

/// The moving links of `model` that have collision shapes, as bodies
/// (their mass, inertia and shapes; in `collision_group`, −1 for none):
/// body i is link link[i].
struct LinkBodies {
  std::vector<BodySpec> bodies;
  std::vector<int> link;
};
LinkBodies linkBodies(const ArticulationModel& model, int collision_group);

}  // namespace rigid_body_sim::core
