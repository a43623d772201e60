// The robots' stages of the one step (step.cpp lists them): their two
// halves, their links placed as bodies, their contacts kept apart and
// merged back; docs/physics.md §11.9. The islands that hold a robot and
// their solve are scene_solve.cpp; sleep and waking scene_sleep.cpp.
#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

#include "articulation_phases.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "scene_stages.h"
#include "step/guard.h"
#include "step/integration.h"
#include "step/sleep.h"

namespace rigid_body_sim::core {

namespace detail {

const ArticulationLoads& robotLoads(const WorldLoads& loads, std::size_t r) {
  static const ArticulationLoads none;
  return loads.robots.empty() ? none : loads.robots[r];
}

void placeLinks(const World& world, std::size_t r, WorldState& state, WorldWorkspace& ws) {
  const SceneRobot& robot = world.robots()[r];
  ArticulationWorkspace& rw = ws.robots[r];
  kinematics(robot.model, state.robots[r], rw.kin);  // also the first half's, with or without links
  if (robot.link.empty()) return;                    // no link is a body: nothing to place
  const std::size_t first = static_cast<std::size_t>(robot.first_body);
  detail::setLinkStates(world.model(), robot.link, rw.kin, first, state.bodies.bodies);
  if (!state.robots[r].asleep) return;
  for (std::size_t i = 0; i < robot.link.size(); ++i) state.bodies.bodies[first + i].asleep = true;
}

void predictRobot(const World& world, std::size_t r, const ArticulationLoads& loads, double h, WorldState& state,
                  WorldWorkspace& ws) {
  const ArticulationModel& m = world.robots()[r].model;
  ArticulationWorkspace& rw = ws.robots[r];
  ArticulationState& rs = state.robots[r];
  rw.start.X_WB = rs.X_WB;
  rw.start.q = rs.q;
  if (m.dofCount() == 0 || rs.asleep) return;
  detail::predictArticulation(m, rs, loads, world.model().gravity(), h, world.model().articulationIntegrator(), rw);
  setTwists(m, rw.next, rw.kin);
}

namespace {

/// Links joined by a joint never touch (they meet at it).
bool adjacentLinks(const World& world, const Contact& c) {
  if (c.other < 0) return false;
  const int r = world.robotOf(static_cast<std::size_t>(c.body));
  if (r < 0 || r != world.robotOf(static_cast<std::size_t>(c.other))) return false;
  const SceneRobot& robot = world.robots()[r];
  const int a = robot.link[c.body - robot.first_body], o = robot.link[c.other - robot.first_body];
  return robot.model.links[a].parent == o || robot.model.links[o].parent == a;
}

}  // namespace

void checkWorld(const World& world, const WorldState& state, const WorldLoads& loads) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("step: " + what); };
  const Model& model = world.model();
  if (state.robots.size() != world.robots().size()) fail("the state has another number of robots than the world");
  if (state.bodies.bodies.size() != model.bodyCount()) fail("the state has another number of bodies");
  const std::size_t n = loads.bodies.size();
  if (n != 0 && n != world.freeBodyCount() && n != model.bodyCount()) {
    fail("one load per free body, or per body, or none");
  }
  for (std::size_t i = world.freeBodyCount(); i < n; ++i) {
    if (!loads.bodies[i].isZero()) fail("a load on link '" + model.body(i).name + "' (a robot's are its own)");
  }
  if (!loads.robots.empty() && loads.robots.size() != world.robots().size()) fail("one load per robot, or none");
  for (std::size_t r = 0; r < loads.robots.size(); ++r) checkLoads(world.robots()[r].model, loads.robots[r]);
}

void predictRobots(const World& world, const WorldLoads& loads, double h, WorldState& state, WorldWorkspace& ws) {
  for (std::size_t r = 0; r < world.robots().size(); ++r) predictRobot(world, r, robotLoads(loads, r), h, state, ws);
}

void dropJoinedLinks(const World& world, Workspace& ws) {
  if (world.robots().empty()) return;
  std::vector<Contact>& contacts = ws.contacts;
  contacts.erase(
      std::remove_if(contacts.begin(), contacts.end(), [&](const Contact& c) { return adjacentLinks(world, c); }),
      contacts.end());
}

void finishRobots(const World& world, double h, WorldState& state, WorldWorkspace& ws) {
  if (world.robots().empty()) return;
  const RobotSolve& solve = ws.scratch->solve;
  for (std::size_t r = 0; r < world.robots().size(); ++r) {
    const ArticulationModel& m = world.robots()[r].model;
    ArticulationWorkspace& rw = ws.robots[r];
    ArticulationState& rs = state.robots[r];
    if (m.dofCount() == 0 || rs.asleep) continue;
    const int at = solve.robot_offset[r];
    rw.row_impulse = solve.impulse.segment(at, m.dofCount());
    if (solve.lift) rw.row_pseudo = solve.pseudo.segment(at, m.dofCount());
    finishArticulation(m, world.model().limits(), h, &rw.row_impulse, solve.lift ? &rw.row_pseudo : nullptr, rs, rw);
    if (!guardArticulation(m, rw.start, rs)) ws.robot_diverged[r] = 1;
  }
}

void placeAllLinks(const World& world, WorldState& state, WorldWorkspace& ws) {
  for (std::size_t r = 0; r < world.robots().size(); ++r) placeLinks(world, r, state, ws);
}

void recordRobotContacts(const World& world, WorldState& state, WorldWorkspace& ws) {
  if (world.robots().empty()) return;
  std::vector<Contact>& contacts = ws.bodies.contacts;
  const std::vector<Contact>& robots = ws.scratch->robot_contacts;
  std::vector<Contact> merged;
  merged.reserve(contacts.size() + robots.size());
  std::merge(contacts.begin(), contacts.end(), robots.begin(), robots.end(), std::back_inserter(merged),
             [](const Contact& x, const Contact& y) { return x.key() < y.key(); });
  contacts.swap(merged);
  state.bodies.contact_impulses.clear();
  for (const Contact& c : contacts) {
    state.bodies.contact_impulses.push_back({c.key(), c.normal_impulse, c.tangent_impulse_W});
  }
}

}  // namespace detail

SceneWorkspace::SceneWorkspace() : scratch(std::make_unique<detail::SceneScratch>()) {}
SceneWorkspace::~SceneWorkspace() = default;
SceneWorkspace::SceneWorkspace(SceneWorkspace&&) noexcept = default;
SceneWorkspace& SceneWorkspace::operator=(SceneWorkspace&&) noexcept = default;

void stepScene(const Scene& scene, SceneState& state, const SceneLoads& loads, SceneWorkspace& ws) {
  detail::WorldState now{state.bodies, state.robots};
  detail::WorldWorkspace memory{ws.bodies, ws.robots, ws.robot_diverged, ws.scratch.get()};
  detail::stepWorld(detail::World(scene), now, detail::WorldLoads{loads.bodies, loads.robots}, memory);
}

}  // namespace rigid_body_sim::core
