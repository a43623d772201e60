// How a body's contact points and solid are built from its collision
// shapes, and shared between bodies built alike (private to the core; the
// model builds its bodies with these, model.cpp).
#pragma once

#include "rigid_body_sim/core/bodies/model.h"

namespace rigid_body_sim::core::detail {

#pragma GCC visibility push(hidden)

/// Samples the body's collision shapes into contact points in B (round
/// features among them), groups the extreme ones, and the quantities shape
/// matching needs. Throws when the points would be too many.
void buildContactPoints(const BodySpec& spec, const ContactSettings& contact, const SolverSettings& solver,
                        BodyModel& b);

/// The body's solid in B: the union of its collision shapes; meshes as a
/// sampled signed-distance grid (refused when too big for one).
void buildSolid(const BodySpec& spec, const SolverSettings& solver, BodyModel& b);

/// Whether two bodies get the same contact points and solid: the same
/// collision shapes, placed alike, and the same mass properties (which
/// place the principal frame B the points are in).
bool sameGeometry(const BodySpec& a, const BodySpec& b);

/// Gives `body` the contact points and solid of `twin` (built alike):
/// shared, not copied.
void shareGeometry(const BodyModel& twin, BodyModel& body);

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
