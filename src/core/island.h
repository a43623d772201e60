// Islands (private to the core): bodies joined by contacts between awake
// bodies. The impulse solve takes each island on its own (and splits them
// over the cores), and sleep takes each as a whole.
#pragma once

#include "rigid_body_sim/core/model.h"
#include "rigid_body_sim/core/state.h"
#include "rigid_body_sim/core/workspace.h"

// Not exported from the library (only its own files and the core tests,
// which link its objects, call these), so link-time optimisation may inline them.
#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// Union-find over this step's body-body contacts (the scene and sleepers
/// join nothing). Fills the scratch's island_root: per body, the smallest
/// body index of its island.
void findIslands(const Model& model, const State& state, Workspace& ws);

/// findIslands, then the contacts sorted into islands: the scratch's
/// island_contacts (contact indices, island by island in root order, each
/// island in contact order) and island_starts (offsets, one past the end last).
void groupContactsByIsland(const Model& model, const State& state, Workspace& ws);

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
