// Islands (private to the core): bodies joined by contacts between awake
// bodies. The impulse solve takes each island on its own (and splits them
// over the cores), and sleep takes each as a whole.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/workspace.h"

// Not exported from the library (only its own files and the core tests,
// which link its objects, call these), so link-time optimisation may inline them.
#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// Union-find over this step's body-body contacts (the scene and sleepers
/// join nothing). Fills the scratch's island_root: per body, the smallest
/// body index of its island.
void findIslands(const Model& model, const State& state, Workspace& ws);

/// The island of a contact, once findIslands has run: its awake body's (a
/// sleeper's own points against an awake body make contacts whose `body` is
/// the sleeper; the contact moves only the awake one).
inline int islandOf(const State& state, const std::vector<int>& island_root, const Contact& c) {
  const bool sleeper_first = c.other >= 0 && state.bodies[c.body].asleep;
  return island_root[sleeper_first ? c.other : c.body];
}

/// findIslands, then the contacts sorted into islands: the scratch's
/// island_contacts (contact indices, island by island in root order, each
/// island in contact order) and island_starts (offsets, one past the end last).
void groupContactsByIsland(const Model& model, const State& state, Workspace& ws);

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
