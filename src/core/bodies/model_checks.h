// The checks a model's settings must pass (docs/physics.md §5.9), shared by
// Model's constructor and Model::retuned: each key's range (setting_keys.h)
// and the rules that tie settings to the bodies. Private to the core. Each
// throws std::invalid_argument naming the key, the value and the allowed range.
#pragma once

#include <vector>

#include "rigid_body_sim/core/bodies/model.h"

#pragma GCC visibility push(hidden)
namespace rigid_body_sim::core {

/// Every config key's value within its one range (setting_keys.h), and the
/// solver's settings that have no key.
void validateSettings(const ModelSpec& spec);
/// The explicit drag must not reverse a body's velocity: σ Δt / m < 1.
void validateDamping(const Damping& d, double dt, const std::vector<BodyModel>& bodies);
/// The penalty spring and damper act explicitly on each body: k h²/m and
/// c h/m must stay small, or the force overshoots (as validateDamping's drag).
void validatePenalty(const ContactSettings& c, double dt, const std::vector<BodyModel>& bodies);
/// The log barrier must hold what a body can bring to one contact point at
/// the speed limits (§7.2).
void validateBarrier(const ContactSettings& c, const SpeedLimits& limits, const Vec3& gravity,
                     const std::vector<BodyModel>& bodies);

}  // namespace rigid_body_sim::core
#pragma GCC visibility pop
