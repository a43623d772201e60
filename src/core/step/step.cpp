// The simulator loop: advance() is the list of the stages of one step, one
// line per stage, in the order of docs/physics.md §4; each stage lives in the
// file named beside it.
#include "rigid_body_sim/core/step/step.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "barrier.h"
#include "fixed_point.h"
#include "guard.h"
#include "integration.h"
#include "rigid_body_sim/core/step/shape_matching.h"
#include "sleep.h"

namespace rigid_body_sim::core {
namespace {

/// One step of length h of every awake body. Returns whether the impulse
/// solve ran (its islands are then in the workspace, for sleep and the
/// fixed-point cache).
bool advance(const Model& model, State& state, const Loads& loads, double h, Workspace& ws) {
  // The stages, as a table:
  // clang-format off
  detectContacts(model, state, h, ws);                             // §5.1    detection.cpp (wakes sleepers hit)
  integrateVelocities(model, state, loads, h, ws);                 // §5.2–4  integration.cpp: forces, v and ω, damping, limits
  const bool impulse = solveContactImpulses(model, state, h, ws);  // §5.5    contact_solver.cpp (then the limits)
  integratePositions(model, state, h, ws);                         // §5.6–7  integration.cpp: gyroscopic, x and q, guard
  if (impulse) correctPositions(model, state, ws);                 // §5.8    position_correction.cpp
  sleepIslands(model, state, ws, impulse);                         // §6      sleep.cpp
  // clang-format on
  return impulse;
}

}  // namespace

void step(const Model& model, State& state, const Loads& loads, Workspace* workspace) {
  std::unique_ptr<Workspace> local;  // only built when the caller brings none
  if (workspace == nullptr) local = std::make_unique<Workspace>();
  Workspace& ws = workspace != nullptr ? *workspace : *local;
  const double h = model.dt();
  wakeLoadedBodies(state, loads);
  if (!ws.speed_limited.empty()) ws.speed_limited.clear();
  if (!ws.diverged.empty()) ws.diverged.clear();
  switch (model.contact().method) {
    case ContactMethod::kShapeMatching:  // replaces every stage (§7.3), under the same guard
      forgetFixedPoint(ws);
      stepShapeMatching(model, state, loads, h, ws);
      break;
    case ContactMethod::kPenaltyLogBarrier:  // advance() under step control (§7.2)
      forgetFixedPoint(ws);
      advanceKeepingBarrier(model, state, loads, h, ws, advance);
      break;
    default:  // advance(), unless the last step returned this same input (fixed_point.cpp)
      if (repeatFixedPoint(model, state, loads, h, ws)) break;
      recordFixedPoint(model, state, loads, advance(model, state, loads, h, ws), ws);
      break;
  }
  state.time += h;
  if (!ws.diverged.empty()) finishGuard(state, ws);
  if (ws.speed_limited.size() > 1) {  // the stages list a body each time they limit it: once each, ascending
    std::sort(ws.speed_limited.begin(), ws.speed_limited.end());
    ws.speed_limited.erase(std::unique(ws.speed_limited.begin(), ws.speed_limited.end()), ws.speed_limited.end());
  }
}

}  // namespace rigid_body_sim::core
