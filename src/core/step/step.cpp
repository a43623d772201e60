// The simulator loop, one for every world: advance() is the list of the
// stages of one step, one line per stage, in the order of docs/physics.md §4
// and §11.9; each stage lives in the file named beside it. The robots'
// stages do nothing in a world of free bodies alone, which then steps bit
// for bit as it did before robots existed.
#include "rigid_body_sim/core/step/step.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "articulations/scene_stages.h"
#include "barrier.h"
#include "fixed_point.h"
#include "guard.h"
#include "integration.h"
#include "rigid_body_sim/core/step/shape_matching.h"
#include "sleep.h"
#include "world.h"

namespace rigid_body_sim::core {
namespace detail {
namespace {

// The stages that do one job for free bodies and robots alike: each runs
// the free bodies' part (the bodies' own files), then the robots'
// (articulations/scene_*.cpp), so a world without robots runs the first
// alone.

/// §5.2–5.4, §11.5: the awake bodies' forces, v and ω, damping and speed
/// limits (integration.cpp), then every awake robot's first half, its
/// velocities without rows (scene_step.cpp). Both after the detection,
/// whose speculative margins take every body and link as it moves now.
void integrateVelocities(const World& world, const WorldLoads& loads, double h, WorldState& state, WorldWorkspace& ws) {
  core::integrateVelocities(world.model(), state.bodies, loads.bodies, h, ws.bodies);
  predictRobots(world, loads, h, state, ws);
}

/// §5.5, §11.9: the free bodies' islands (contact_solver.cpp), then the
/// islands that hold a robot, joints and contacts in one solve
/// (scene_solve.cpp). Returns whether the free bodies' solve ran.
bool solveContacts(const World& world, WorldState& state, double h, WorldWorkspace& ws) {
  const bool impulse = solveContactImpulses(world.model(), state.bodies, h, ws.bodies);
  solveRobotIslands(world, state, h, ws);
  return impulse;
}

/// §5.6–5.7, §11.5–11.7: the awake bodies' positions, still times and guard
/// (integration.cpp), then every awake robot's second half: momenta,
/// positions, speed limits and guard (scene_step.cpp).
void integratePositions(const World& world, double h, WorldState& state, WorldWorkspace& ws) {
  core::integratePositions(world.model(), state.bodies, h, ws.bodies);
  finishRobots(world, h, state, ws);
}

/// §5.8, §11.8: the split impulse of the robots' islands on their free
/// bodies (scene_solve.cpp; the robots took theirs in their second half),
/// then the free bodies' own (position_correction.cpp), where their solve ran.
void correctPositions(const World& world, bool impulse, double h, WorldState& state, WorldWorkspace& ws) {
  liftBodies(world, ws, h, state);
  if (impulse) core::correctPositions(world.model(), state.bodies, ws.bodies);
}

/// One step of length h of every awake body and robot. Returns whether the
/// free bodies' impulse solve ran (its islands are then in the workspace,
/// for sleep and the fixed-point cache).
bool advance(const World& world, WorldState& state, const WorldLoads& loads, double h, WorldWorkspace& ws) {
  const Model& model = world.model();
  State& bodies = state.bodies;
  Workspace& bw = ws.bodies;
  // The stages, as a table:
  // clang-format off
  placeAllLinks(world, state, ws);                                 // §11.9   scene_step.cpp: where the robots are
  detectContacts(model, bodies, h, bw);                            // §5.1    detection.cpp (wakes sleepers hit)
  dropJoinedLinks(world, bw);                                      // §11.8   scene_step.cpp
  wakeHitRobots(world, state, ws);                                 // §11.9   scene_sleep.cpp
  takeRobotContacts(world, state, ws);                             // §11.9   scene_solve.cpp: the robots' islands apart
  integrateVelocities(world, loads, h, state, ws);                 // §5.2–4  above: forces, limits, robots' first halves
  const bool impulse = solveContacts(world, state, h, ws);         // §5.5    above: every island, bodies' and robots'
  integratePositions(world, h, state, ws);                         // §5.6–7  above: positions, guard, robots' second halves
  correctPositions(world, impulse, h, state, ws);                  // §5.8    above: split impulse, position correction
  sleepIslands(world, h, state, ws, impulse);                      // §6      sleep.cpp: islands of bodies and robots
  placeAllLinks(world, state, ws);                                 // §11.9   scene_step.cpp: where they are, for readers
  recordRobotContacts(world, state, ws);                           // §11.9   scene_step.cpp: every contact, for the warm start
  // clang-format on
  return impulse;
}

/// advance() for a world of free bodies, in the shape the log barrier's step
/// control repeats (it takes no robots).
bool advanceBodies(const Model& model, State& state, const Loads& loads, double h, Workspace& ws) {
  std::vector<ArticulationState> no_robots;
  std::vector<ArticulationLoads> no_loads;
  std::vector<ArticulationWorkspace> no_memory;
  std::vector<char> no_flags;
  WorldState now{state, no_robots};
  WorldWorkspace memory{ws, no_memory, no_flags, nullptr};
  return advance(World(model), now, WorldLoads{loads, no_loads}, h, memory);
}

}  // namespace

void stepWorld(const World& world, WorldState& state, const WorldLoads& loads, WorldWorkspace& ws) {
  checkWorld(world, state, loads);
  const Model& model = world.model();
  Workspace& bw = ws.bodies;
  const double h = model.dt();
  wakeLoadedBodies(state.bodies, loads.bodies);
  wakeLoadedRobots(world, loads, state, ws);
  if (!bw.speed_limited.empty()) bw.speed_limited.clear();
  if (!bw.diverged.empty()) bw.diverged.clear();
  switch (model.contact().method) {      // a scene with robots takes the impulse method (Scene refuses others)
    case ContactMethod::kShapeMatching:  // replaces every stage (§7.3), under the same guard
      forgetFixedPoint(bw);
      stepShapeMatching(model, state.bodies, loads.bodies, h, bw);
      break;
    case ContactMethod::kPenaltyLogBarrier:  // advance() under step control (§7.2)
      forgetFixedPoint(bw);
      advanceKeepingBarrier(model, state.bodies, loads.bodies, h, bw, advanceBodies);
      break;
    default:
      if (!world.robots().empty()) {  // the cache compares bodies only: a robot's joints could move unseen
        forgetFixedPoint(bw);
        advance(world, state, loads, h, ws);
        break;
      }
      // advance(), unless the last step returned this same input (fixed_point.cpp)
      if (repeatFixedPoint(model, state.bodies, loads.bodies, h, bw)) break;
      recordFixedPoint(model, state.bodies, loads.bodies, advance(world, state, loads, h, ws), bw);
      break;
  }
  state.bodies.time += h;
  if (!bw.diverged.empty()) finishGuard(state.bodies, bw);
  if (bw.speed_limited.size() > 1) {  // the stages list a body each time they limit it: once each, ascending
    std::sort(bw.speed_limited.begin(), bw.speed_limited.end());
    bw.speed_limited.erase(std::unique(bw.speed_limited.begin(), bw.speed_limited.end()), bw.speed_limited.end());
  }
}

}  // namespace detail

void step(const Model& model, State& state, const Loads& loads, Workspace* workspace) {
  std::unique_ptr<Workspace> local;  // only built when the caller brings none
  if (workspace == nullptr) local = std::make_unique<Workspace>();
  std::vector<ArticulationState> no_robots;
  std::vector<ArticulationLoads> no_loads;
  std::vector<ArticulationWorkspace> no_memory;
  std::vector<char> no_flags;
  detail::WorldState now{state, no_robots};
  detail::WorldWorkspace memory{workspace != nullptr ? *workspace : *local, no_memory, no_flags, nullptr};
  detail::stepWorld(detail::World(model), now, detail::WorldLoads{loads, no_loads}, memory);
}

}  // namespace rigid_body_sim::core
