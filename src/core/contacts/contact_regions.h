// The regions of one body's contact points (docs/physics.md §5.1): the
// candidates detection finds, grouped by item (or other body) and normal
// direction, each region reduced to at most four points that span it for
// the impulse method, and emitted as contacts in key order.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "step/scratch.h"

namespace rigid_body_sim::core::detail {

#pragma GCC visibility push(hidden)

/// Turns one body's candidates (out.candidates, grouped by item or other
/// body) into contacts appended to out.contacts: regions by item (or other
/// body) and normal direction (within about 20°; a plane is one region),
/// each reduced to at most four points when `reduce` (the impulse method).
void emitContacts(const Model& model, const State& state, int body, bool reduce, PartScratch& out);

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
