// Sleep and waking for the islands that hold a robot: docs/physics.md §11.9.
#include "articulation_phases.h"
#include "scene_stages.h"
#include "step/sleep.h"

namespace rigid_body_sim::core::detail {

namespace {

void wakeBody(BodyState& s) {
  s.asleep = false;
  s.still_time = 0.0;
}

}  // namespace

void wakeHitRobots(const World& world, const WorldLoads& loads, double h, WorldState& state, WorldWorkspace& ws) {
  if (world.robots().empty()) return;
  std::vector<char>& woken = ws.scratch->woken;
  std::vector<BodyState>& bodies = state.bodies.bodies;
  for (std::size_t r = 0; r < world.robots().size(); ++r) {
    const SceneRobot& robot = world.robots()[r];
    if (!state.robots[r].asleep) continue;
    bool hit = false;
    for (std::size_t i = 0; i < robot.link.size() && !hit; ++i) hit = !bodies[robot.first_body + i].asleep;
    if (!hit) continue;
    wakeRobot(state.robots[r]);
    woken[r] = 1;
    predictRobot(world, r, robotLoads(loads, r), h, state, ws);
  }
  for (const Contact& c : ws.bodies.contacts) {
    if (c.other < 0) continue;
    const int ra = world.robotOf(static_cast<std::size_t>(c.body));
    const int ro = world.robotOf(static_cast<std::size_t>(c.other));
    if (ra >= 0 && woken[ra] && ro < 0 && bodies[c.other].asleep) wakeBody(bodies[c.other]);
    if (ro >= 0 && woken[ro] && ra < 0 && bodies[c.body].asleep) wakeBody(bodies[c.body]);
  }
}

void sleepRobotIslands(const World& world, double h, WorldState& state, WorldWorkspace& ws) {
  if (world.robots().empty()) return;
  const Model& model = world.model();
  const std::size_t n = model.bodyCount();
  std::vector<char> touching(world.robots().size(), 0);
  for (const Contact& c : ws.scratch->robot_contacts) {
    for (const int b : {c.body, c.other}) {
      const int r = b >= 0 ? world.robotOf(static_cast<std::size_t>(b)) : -1;
      if (r >= 0) touching[r] = 1;
    }
  }
  std::vector<char> ready(n, 1);  // per island root
  std::vector<char> holds(n, 0);  // per island root: an awake robot
  for (std::size_t r = 0; r < world.robots().size(); ++r) {
    const SceneRobot& robot = world.robots()[r];
    ArticulationState& rs = state.robots[r];
    if (rs.asleep || robot.link.empty()) continue;
    const int root = ws.scratch->island_root[robot.first_body];
    holds[root] = 1;
    if (!detail::updateStillTime(robot.model, model.sleep(), touching[r] != 0, h, rs)) ready[root] = 0;
  }
  for (std::size_t i = 0; i < world.freeBodyCount(); ++i) {
    const BodyState& s = state.bodies.bodies[i];
    if (!s.asleep && !readyToSleep(model, true, s)) ready[ws.scratch->island_root[i]] = 0;
  }
  for (std::size_t r = 0; r < world.robots().size(); ++r) {
    const SceneRobot& robot = world.robots()[r];
    if (state.robots[r].asleep || robot.link.empty()) continue;
    if (ready[ws.scratch->island_root[robot.first_body]]) detail::fallAsleep(state.robots[r]);
  }
  for (std::size_t i = 0; i < world.freeBodyCount(); ++i) {
    BodyState& s = state.bodies.bodies[i];
    const int root = ws.scratch->island_root[i];
    if (!s.asleep && holds[root] && ready[root]) fallAsleep(s);
  }
}

}  // namespace rigid_body_sim::core::detail
