// Waking the robots and the bodies they touch: docs/physics.md §11.9 (their
// sleep is the one rule of step/sleep.cpp).
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

void wakeLoadedRobots(const World& world, const WorldLoads& loads, WorldState& state, WorldWorkspace& ws) {
  const std::size_t robots = world.robots().size();
  ws.robots.resize(robots);
  ws.robot_diverged.assign(robots, 0);
  if (robots == 0) return;
  std::vector<char>& woken = ws.scratch->woken;
  woken.assign(robots, 0);
  for (std::size_t r = 0; r < robots; ++r) {
    ArticulationState& rs = state.robots[r];
    if (rs.asleep && loaded(robotLoads(loads, r))) {
      wakeRobot(rs);
      woken[r] = 1;
    }
  }
}

void wakeHitRobots(const World& world, WorldState& state, WorldWorkspace& ws) {
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
    placeLinks(world, r, state, ws);  // every link awake, where the robot rests
  }
  for (const Contact& c : ws.bodies.contacts) {
    if (c.other < 0) continue;
    const int ra = world.robotOf(static_cast<std::size_t>(c.body));
    const int ro = world.robotOf(static_cast<std::size_t>(c.other));
    if (ra >= 0 && woken[ra] && ro < 0 && bodies[c.other].asleep) wakeBody(bodies[c.other]);
    if (ro >= 0 && woken[ro] && ra < 0 && bodies[c.body].asleep) wakeBody(bodies[c.body]);
  }
}

}  // namespace rigid_body_sim::core::detail
