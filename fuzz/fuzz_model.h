// What every fuzzer does with a body or config the loader accepted: build
// the model (its validation is part of what is fuzzed) and take a few steps,
// which must stay finite. A refusal is an exception, never a crash.
#pragma once

#include <cstdlib>
#include <stdexcept>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::fuzz {

inline void stepAFew(const core::ModelSpec& spec, const core::State* start = nullptr) {
  try {
    const core::Model model(spec);
    core::State state = start != nullptr ? *start : core::restState(model);
    core::Workspace ws;
    ws.threads = 1;
    for (int n = 0; n < 5; ++n) core::step(model, state, {}, &ws);
    for (const core::BodyState& b : state.bodies) {
      if (!b.p_WB.allFinite() || !b.v_WB.allFinite() || !b.q_WB.coeffs().allFinite() || !b.w_B.allFinite()) {
        std::abort();  // the guard must never let this through
      }
    }
  } catch (const std::invalid_argument&) {
    // refused by the model's validation: fine
  }
}

}  // namespace rigid_body_sim::fuzz
