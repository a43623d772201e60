// What touches what after a step, one report per touching pair, as the
// node's ~contacts publishes it (docs/physics.md §10.3). ROS-free.
#pragma once

#include <vector>

#include "rigid_body_sim/core/contact.h"
#include "rigid_body_sim/core/model.h"
#include "rigid_body_sim/core/state.h"

namespace rigid_body_sim::core {

/// A touching pair: a body and a scene item, or two bodies (body < other).
struct ContactPairReport {
  int body = 0;                          ///< index in the model
  int other = -1;                        ///< the other body, or -1 for the scene item `item`
  int item = -1;                         ///< index in model.scene(), or -1
  std::vector<Vec3> points_W;            ///< the touching points, world (m)
  Vec3 normal_W = Vec3::UnitZ();         ///< unit, from the other (or the item) toward `body`
  double depth = 0.0;                    ///< m, the deepest penetration, ≥ 0
  Vec3 normal_force_W = Vec3::Zero();    ///< N, on `body`: the normal impulses over the step / Δt
  Vec3 friction_force_W = Vec3::Zero();  ///< N, on `body`: the friction impulses / Δt
};

/// The pairs of `contacts` (a step's solved contacts, Workspace::contacts)
/// with a touching point (a normal impulse, or a penetration), sorted by
/// (body, other, item). A pair of bodies reported both ways (each body's
/// points against the other's solid) is one report, on the lower index.
std::vector<ContactPairReport> contactPairs(const Model& model, const State& state,
                                            const std::vector<Contact>& contacts);

}  // namespace rigid_body_sim::core
