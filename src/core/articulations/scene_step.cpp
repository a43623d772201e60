// One step of a scene of free bodies and robots: docs/physics.md §11.9. The
// stages are the free bodies' (§4) and the robots' (§11.5), with one more
// between the velocities and the positions: the solve of the islands that
// hold a robot (scene_solve.cpp); sleep and waking in scene_sleep.cpp.
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

const ArticulationLoads& robotLoads(const SceneLoads& loads, std::size_t r) {
  static const ArticulationLoads none;
  return loads.robots.empty() ? none : loads.robots[r];
}

void placeLinks(const Scene& scene, std::size_t r, SceneState& state, SceneWorkspace& ws) {
  const SceneRobot& robot = scene.robots()[r];
  ArticulationWorkspace& rw = ws.robots[r];
  kinematics(robot.model, state.robots[r], rw.kin);
  const std::size_t first = static_cast<std::size_t>(robot.first_body);
  detail::setLinkStates(scene.model(), robot.link, rw.kin, first, state.bodies.bodies);
  if (!state.robots[r].asleep) return;
  for (std::size_t i = 0; i < robot.link.size(); ++i) state.bodies.bodies[first + i].asleep = true;
}

void predictRobot(const Scene& scene, std::size_t r, const ArticulationLoads& loads, double h, SceneState& state,
                  SceneWorkspace& ws) {
  const ArticulationModel& m = scene.robots()[r].model;
  ArticulationWorkspace& rw = ws.robots[r];
  ArticulationState& rs = state.robots[r];
  rw.start.X_WB = rs.X_WB;
  rw.start.q = rs.q;
  if (m.dofCount() == 0 || rs.asleep) {
    placeLinks(scene, r, state, ws);
    return;
  }
  detail::predictArticulation(m, rs, loads, scene.model().gravity(), h, rw);
  setTwists(m, rw.next, rw.kin);
  const SceneRobot& robot = scene.robots()[r];
  detail::setLinkStates(scene.model(), robot.link, rw.kin, static_cast<std::size_t>(robot.first_body),
                        state.bodies.bodies);
}

}  // namespace detail

SceneWorkspace::SceneWorkspace() : scratch(std::make_unique<detail::SceneScratch>()) {}
SceneWorkspace::~SceneWorkspace() = default;
SceneWorkspace::SceneWorkspace(SceneWorkspace&&) noexcept = default;
SceneWorkspace& SceneWorkspace::operator=(SceneWorkspace&&) noexcept = default;

namespace {

void checkSizes(const Scene& scene, const SceneState& state, const SceneLoads& loads) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("stepScene: " + what); };
  if (state.robots.size() != scene.robots().size()) fail("the state has another number of robots than the scene");
  if (state.bodies.bodies.size() != scene.model().bodyCount()) fail("the state has another number of bodies");
  const std::size_t n = loads.bodies.size();
  if (n != 0 && n != scene.freeBodyCount() && n != scene.model().bodyCount()) {
    fail("one load per free body, or per body, or none");
  }
  for (std::size_t i = scene.freeBodyCount(); i < n; ++i) {
    if (!loads.bodies[i].isZero()) fail("a load on link '" + scene.model().body(i).name + "' (a robot's are its own)");
  }
  if (!loads.robots.empty() && loads.robots.size() != scene.robots().size()) fail("one load per robot, or none");
  for (std::size_t r = 0; r < loads.robots.size(); ++r) detail::checkLoads(scene.robots()[r].model, loads.robots[r]);
}

/// Links joined by a joint never touch (they meet at it).
bool adjacentLinks(const Scene& scene, const Contact& c) {
  if (c.other < 0) return false;
  const int r = scene.robotOf(static_cast<std::size_t>(c.body));
  if (r < 0 || r != scene.robotOf(static_cast<std::size_t>(c.other))) return false;
  const SceneRobot& robot = scene.robots()[r];
  const int a = robot.link[c.body - robot.first_body], o = robot.link[c.other - robot.first_body];
  return robot.model.links[a].parent == o || robot.model.links[o].parent == a;
}

/// Both lists sorted by key into `into`.
void mergeContacts(const std::vector<Contact>& a, const std::vector<Contact>& b, std::vector<Contact>& into) {
  std::vector<Contact> merged;
  merged.reserve(a.size() + b.size());
  std::merge(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(merged),
             [](const Contact& x, const Contact& y) { return x.key() < y.key(); });
  into.swap(merged);
}

}  // namespace

void stepScene(const Scene& scene, SceneState& state, const SceneLoads& loads, SceneWorkspace& ws) {
  checkSizes(scene, state, loads);
  const Model& model = scene.model();
  const std::vector<SceneRobot>& robots = scene.robots();
  const double h = model.dt();
  Workspace& bw = ws.bodies;
  ws.robots.resize(robots.size());
  ws.robot_diverged.assign(robots.size(), 0);
  wakeLoadedBodies(state.bodies, loads.bodies);
  bw.speed_limited.clear();
  bw.diverged.clear();
  // The robots' first halves: each one's velocity without rows, its links
  // placed as bodies moving at it (for the speculative margins); a
  // sleeping robot's stay put, as sleepers, unless a load wakes it.
  std::vector<char> woken(robots.size(), 0);
  for (std::size_t r = 0; r < robots.size(); ++r) {
    ArticulationState& rs = state.robots[r];
    if (rs.asleep && detail::loaded(detail::robotLoads(loads, r))) {
      detail::wakeRobot(rs);
      woken[r] = 1;
    }
    detail::predictRobot(scene, r, detail::robotLoads(loads, r), h, state, ws);
  }
  // The stages, as a table:
  // clang-format off
  detectContacts(model, state.bodies, h, bw);                               // §5.1  detection.cpp, over every body
  bw.contacts.erase(std::remove_if(bw.contacts.begin(), bw.contacts.end(),
                                   [&](const Contact& c) { return adjacentLinks(scene, c); }),
                    bw.contacts.end());
  detail::wakeHitRobots(scene, loads, h, woken, state, ws);                 // §11.9 a sleeping robot hit wakes
  detail::takeRobotContacts(scene, state.bodies, ws);                       // §11.9 the robots' islands apart
  ws.scratch->last_impulses = state.bodies.contact_impulses;                         // the free solve rewrites them
  for (std::size_t i = scene.freeBodyCount(); i < model.bodyCount(); ++i) {
    state.bodies.bodies[i].asleep = true;                                   // the free stages leave links alone
  }
  integrateVelocities(model, state.bodies, loads.bodies, h, bw);            // §5.2–4 integration.cpp
  const bool impulse = solveContactImpulses(model, state.bodies, h, bw);    // §5.5  contact_solver.cpp: the other islands
  detail::RobotSolve& solve = ws.scratch->solve;
  detail::solveRobotIslands(scene, state, h, ws, solve);                    // §11.9 the robots' islands, one solve
  integratePositions(model, state.bodies, h, bw);                           // §5.6–7 integration.cpp
  if (solve.lift) detail::liftBodies(scene, solve, h, state);               // §11.8 split impulse, the bodies
  if (impulse) correctPositions(model, state.bodies, bw);                   // §5.8  position_correction.cpp
  sleepIslands(model, state.bodies, bw, impulse);                           // §6    sleep.cpp
  // clang-format on
  // The robots' second halves: momenta, positions, the guard.
  for (std::size_t r = 0; r < robots.size(); ++r) {
    const ArticulationModel& m = robots[r].model;
    ArticulationWorkspace& rw = ws.robots[r];
    ArticulationState& rs = state.robots[r];
    if (m.dofCount() > 0 && !rs.asleep) {
      const int at = solve.robot_offset[r];
      const Eigen::VectorXd impulse_r = solve.impulse.segment(at, m.dofCount());
      const Eigen::VectorXd pseudo_r =
          solve.lift ? Eigen::VectorXd(solve.pseudo.segment(at, m.dofCount())) : Eigen::VectorXd();
      detail::finishArticulation(m, model.limits(), h, &impulse_r, solve.lift ? &pseudo_r : nullptr, rs, rw);
      if (!detail::guardArticulation(m, rw.start, rs)) ws.robot_diverged[r] = 1;
    }
  }
  detail::sleepRobotIslands(scene, h, state, ws);  // §11.9 sleep, island by island
  for (std::size_t r = 0; r < robots.size(); ++r)
    detail::placeLinks(scene, r, state, ws);  // for readers and the next step
  // Every contact, for the caller and the next step's warm start.
  mergeContacts(bw.contacts, ws.scratch->robot_contacts, bw.contacts);
  state.bodies.contact_impulses.clear();
  for (const Contact& c : bw.contacts) {
    state.bodies.contact_impulses.push_back({c.key(), c.normal_impulse, c.tangent_impulse_W});
  }
  state.bodies.time += h;
  if (!bw.diverged.empty()) finishGuard(state.bodies, bw);
  if (bw.speed_limited.size() > 1) {
    std::sort(bw.speed_limited.begin(), bw.speed_limited.end());
    bw.speed_limited.erase(std::unique(bw.speed_limited.begin(), bw.speed_limited.end()), bw.speed_limited.end());
  }
}

}  // namespace rigid_body_sim::core
