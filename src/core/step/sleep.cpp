// Still time and sleep (docs/physics.md §6).
#include "sleep.h"

#include <cmath>

#include "articulations/articulation_phases.h"
#include "articulations/scene_stages.h"
#include "contacts/island.h"
#include "scratch.h"

namespace rigid_body_sim::core {

void wakeLoadedBodies(State& state, const Loads& loads) {
  for (std::size_t i = 0; i < loads.size() && i < state.bodies.size(); ++i) {
    BodyState& s = state.bodies[i];
    if (s.asleep && !loads[i].isZero()) {
      s.asleep = false;
      s.still_time = 0.0;
    }
  }
}

bool wakeTouchedSleepers(const Model& model, State& state, const Workspace& ws, double h) {
  // Wake a sleeper when an awake body comes at it faster than a resting
  // contact would (gravity's one step), or presses in deeper than the slop.
  const double still = model.sleep().linear_velocity + model.gravity().norm() * h;
  bool woke = false;
  for (const Contact& c : ws.contacts) {
    if (c.other < 0) continue;
    BodyState &a = state.bodies[c.body], &o = state.bodies[c.other];
    if (a.asleep == o.asleep) continue;
    const BodyState& awake = a.asleep ? o : a;
    BodyState& sleeper = a.asleep ? a : o;
    const Vec3 w = awake.q_WB * awake.w_B;
    const Vec3 arm = a.asleep ? c.r_other_W : c.r_W;
    const double approach = std::abs(c.normal_W.dot(awake.v_WB + w.cross(arm)));
    if (approach > still || c.separation < -model.contact().position_slop) {
      sleeper.asleep = false;
      sleeper.still_time = 0.0;
      woke = true;
    }
  }
  return woke;
}

namespace {

/// The one rule of sleep by islands, as Box2D's: bodies and robots joined
/// by contacts (a robot's links by its joints) fall asleep together, once
/// every awake one of them has been still for the sleep time while touching
/// something, or (a body) is held exactly still by the impulse solve (the
/// scratch's held_still: the sleep time only guards the loose sleep speeds,
/// and exactly zero is equilibrium, not the turning point of a bounce). A
/// body alone would otherwise fall asleep under a neighbour still settling
/// on it, and the neighbour's next jolt would wake it again, over and over.
/// `root`: per body, its island's smallest body; `touching`: per body, in
/// contact with something; `robot_touching`: per robot. A robot's clock runs
/// here (its still time), a body's in the position stage.
void sleepByIslands(const detail::World& world, const std::vector<int>& root, const std::vector<char>& touching,
                    const std::vector<char>* held, const std::vector<char>& robot_touching, double h,
                    detail::WorldState& state, std::vector<char>& ready) {
  const Model& model = world.model();
  const std::vector<SceneRobot>& robots = world.robots();
  std::vector<BodyState>& bodies = state.bodies.bodies;
  const std::size_t free_bodies = world.freeBodyCount();  // a robot's links are their robot's
  ready.assign(model.bodyCount(), 1);
  for (std::size_t i = 0; i < free_bodies; ++i) {
    const BodyState& s = bodies[i];
    const bool still = s.asleep || (held != nullptr && (*held)[i]) || readyToSleep(model, touching[i] != 0, s);
    if (!still) ready[root[i]] = 0;
  }
  for (std::size_t r = 0; r < robots.size(); ++r) {
    ArticulationState& rs = state.robots[r];
    if (rs.asleep || robots[r].link.empty()) continue;
    if (!detail::updateStillTime(robots[r].model, model.sleep(), robot_touching[r] != 0, h, rs)) {
      ready[root[robots[r].first_body]] = 0;
    }
  }
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (state.robots[r].asleep || robots[r].link.empty()) continue;
    if (ready[root[robots[r].first_body]]) detail::fallAsleep(state.robots[r]);
  }
  for (std::size_t i = 0; i < free_bodies; ++i) {
    if (!bodies[i].asleep && ready[root[i]]) fallAsleep(bodies[i]);
  }
}

}  // namespace

void sleepIslands(const Model& model, State& state, Workspace& ws, bool islands_known) {
  if (!model.sleep().enabled || ws.contacts.empty()) return;  // nothing touches: nothing sleeps
  detail::StepScratch& sc = *ws.scratch;
  if (!islands_known) findIslands(model, state, ws);
  std::vector<ArticulationState> no_robots;
  detail::WorldState world_state{state, no_robots};
  static const std::vector<char> no_touching;
  sleepByIslands(detail::World(model), sc.island_root, sc.in_contact, islands_known ? &sc.held_still : nullptr,
                 no_touching, 0.0, world_state, sc.island_flags);
}

namespace detail {

void sleepIslands(const World& world, double h, WorldState& state, WorldWorkspace& ws, bool islands_known) {
  if (world.robots().empty()) {
    core::sleepIslands(world.model(), state.bodies, ws.bodies, islands_known);
    return;
  }
  // With robots, the islands are those of every contact between awake
  // bodies and of every robot's links (takeRobotContacts); a free body in a
  // robot's island touches it, and a robot touches what its contacts hold.
  const Model& model = world.model();
  const std::vector<SceneRobot>& robots = world.robots();
  StepScratch& sc = *ws.bodies.scratch;
  const std::vector<int>& root = ws.scratch->island_root;
  std::vector<char>& robot_touching = ws.scratch->touching;
  robot_touching.assign(robots.size(), 0);
  for (const Contact& c : ws.scratch->robot_contacts) {
    for (const int b : {c.body, c.other}) {
      const int r = b >= 0 ? world.robotOf(static_cast<std::size_t>(b)) : -1;
      if (r >= 0) robot_touching[r] = 1;
    }
  }
  std::vector<char>& holds_robot = sc.island_flags;  // per root, until sleepByIslands reuses it
  holds_robot.assign(model.bodyCount(), 0);
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (!state.robots[r].asleep && !robots[r].link.empty()) holds_robot[root[robots[r].first_body]] = 1;
  }
  std::vector<char>& touching = sc.island_touching;
  touching.assign(model.bodyCount(), 0);
  for (std::size_t i = 0; i < world.freeBodyCount(); ++i) touching[i] = sc.in_contact[i] | holds_robot[root[i]];
  sleepByIslands(world, root, touching, islands_known ? &sc.held_still : nullptr, robot_touching, h, state,
                 sc.island_flags);
}

}  // namespace detail

}  // namespace rigid_body_sim::core
