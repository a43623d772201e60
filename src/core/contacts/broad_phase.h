// The broad phase between bodies (private to the core): which pairs of
// bodies are close enough for detection to test their points.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/workspace.h"

// Not exported from the library (only its own files and the core tests,
// which link its objects, call these), so link-time optimisation may inline them.
#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// Sweep and prune along x in strips along y: the pairs of bodies (at least
/// one awake) whose boxes, grown by their margins, overlap, both ways round,
/// into ws.directions. One sweep along x over bodies spread over the ground
/// meets every body of the same x, a whole column of a grid (about √N);
/// strips as wide as the widest box hold the bodies of about one row, and
/// two boxes overlapping in y lie in the same strip or in neighbouring ones,
/// so each box is swept against its own strip and the next. The boxes go
/// into flat arrays in (strip, x) order first, so the inner loops only
/// compare numbers. Sorted, so the result does not depend on the order the
/// workspace kept from the last step, nor on the number of parts.
/// Reads the margins from the scratch (per body, m) and writes the pairs,
/// both ways round and sorted, into the scratch's `directions`, in `parts`
/// parts (detail::partsFor).
void broadPhase(const Model& model, const State& state, int parts, Workspace& ws);

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
