// One step of a scene of free bodies and robots: docs/physics.md §11.9. The
// stages are the free bodies' (§4) and the robots' (§11.5), with one more
// between the velocities and the positions: the solve of the islands that
// hold a robot.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "articulation_phases.h"
#include "guard.h"
#include "integration.h"
#include "joint_rows.h"
#include "rigid_body_sim/core/contact.h"
#include "rigid_body_sim/core/scene.h"
#include "scratch.h"
#include "sleep.h"
#include "solver_contact.h"

namespace rigid_body_sim::core {

namespace {

using detail::ContactRows;
using detail::CoordinateBlock;
using detail::JointRow;

void checkSizes(const Scene& scene, const SceneState& state, const SceneLoads& loads) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("stepScene: " + what); };
  if (state.robots.size() != scene.robots().size()) fail("the state has another number of robots than the scene");
  if (state.bodies.bodies.size() != scene.model().bodyCount()) fail("the state has another number of bodies");
  if (!loads.bodies.empty() && loads.bodies.size() != scene.freeBodyCount()) fail("one load per free body, or none");
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

/// Moves the contacts of the islands that hold a robot (bodies joined by
/// contacts between awake bodies, a robot's links joined to each other) out
/// of ws.bodies.contacts into ws.robot_contacts; both stay sorted by key.
/// The free bodies' stages then see only the other islands' contacts.
void takeRobotContacts(const Scene& scene, const State& state, SceneWorkspace& ws) {
  const std::size_t n = scene.model().bodyCount();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  const auto unite = [&](int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  for (const SceneRobot& robot : scene.robots()) {
    for (std::size_t k = 1; k < robot.link.size(); ++k) unite(robot.first_body, robot.first_body + static_cast<int>(k));
  }
  std::vector<Contact>& all = ws.bodies.contacts;
  for (const Contact& c : all) {
    if (c.other >= 0 && !state.bodies[c.body].asleep && !state.bodies[c.other].asleep) unite(c.body, c.other);
  }
  ws.island_root.resize(n);
  for (std::size_t i = 0; i < n; ++i) ws.island_root[i] = find(static_cast<int>(i));
  // A sleeping robot's links are sleepers: their contacts are the free
  // bodies' (ground to them) unless an awake robot's island holds them.
  std::vector<char> holds_robot(n, 0);
  for (std::size_t i = scene.freeBodyCount(); i < n; ++i) {
    if (!state.bodies[i].asleep) holds_robot[ws.island_root[i]] = 1;
  }
  ws.robot_contacts.clear();
  std::size_t kept = 0;
  for (const Contact& c : all) {
    const bool robot = holds_robot[find(c.body)] || (c.other >= 0 && holds_robot[find(c.other)]);
    if (robot) {
      ws.robot_contacts.push_back(c);
    } else {
      all[kept++] = c;
    }
  }
  all.resize(kept);
  // The free stages' view of who touches: their contacts only.
  std::vector<char>& in_contact = ws.bodies.scratch->in_contact;
  in_contact.assign(n, 0);
  for (const Contact& c : all) {
    in_contact[c.body] = 1;
    if (c.other >= 0) in_contact[c.other] = 1;
  }
}

/// The solve of the islands that hold a robot, over u: every robot's
/// joint-space velocity, then every awake free body in them (v_W, ω_W).
struct RobotSolve {
  std::vector<CoordinateBlock> blocks;
  std::vector<int> robot_offset;  ///< per robot; −1: no dofs
  std::vector<int> body_offset;   ///< per body; −1: not a block (a link, a sleeper, a body elsewhere)
  Eigen::VectorXd u, impulse, pseudo;
  std::vector<JointRow> rows;
  std::vector<ContactRows> contacts;
  bool lift = false;  ///< pseudo moves something
};

void addBodyBlock(const Model& model, const BodyState& s, int body, RobotSolve& solve, int& offset) {
  if (solve.body_offset[body] >= 0 || s.asleep) return;
  CoordinateBlock block;
  block.offset = offset;
  block.size = 6;
  block.inv_mass = model.body(body).inv_mass;
  block.inv_inertia_W = detail::worldInverseInertia(model.body(body), s.q_WB);
  solve.blocks.push_back(block);
  solve.body_offset[body] = offset;
  offset += 6;
}

/// One side of a contact's rows for `body`: its robot's block (a second
/// link of the same robot adds to the same side) or its own; none for a
/// robot without dofs or a sleeper.
void addSide(const Scene& scene, const SceneWorkspace& ws, const RobotSolve& solve, int body, const Vec3& x_W,
             const Vec3& arm_W, const Mat3& directions, double sign, ContactRows& c) {
  const int r = scene.robotOf(static_cast<std::size_t>(body));
  const int offset = r >= 0 ? solve.robot_offset[r] : solve.body_offset[body];
  if (offset < 0) return;
  if (r < 0) {
    c.side[c.sides].offset = offset;
    detail::setBodyPoint(arm_W, directions, sign, c.side[c.sides].J);
    ++c.sides;
    return;
  }
  const SceneRobot& robot = scene.robots()[r];
  int s = 0;
  while (s < c.sides && c.side[s].offset != offset) ++s;
  if (s == c.sides) {
    c.side[s].offset = offset;
    c.side[s].J.setZero(robot.model.dofCount(), 3);
    ++c.sides;
  }
  detail::addLinkPoint(robot.model, ws.robots[r].kin, robot.link[body - robot.first_body], x_W, directions, sign,
                       c.side[s].J);
}

void solveRobotIslands(const Scene& scene, SceneState& state, double h, SceneWorkspace& ws, RobotSolve& solve) {
  const Model& model = scene.model();
  const std::vector<SceneRobot>& robots = scene.robots();
  std::vector<BodyState>& bodies = state.bodies.bodies;
  // The blocks: the robots, then the free bodies in contact order.
  solve.blocks.clear();
  solve.robot_offset.assign(robots.size(), -1);
  solve.body_offset.assign(model.bodyCount(), -1);
  int offset = 0;
  for (std::size_t r = 0; r < robots.size(); ++r) {
    const int n = robots[r].model.dofCount();
    if (n == 0 || state.robots[r].asleep) continue;  // a sleeping robot is ground
    solve.blocks.push_back({offset, n, &ws.robots[r].llt});
    solve.robot_offset[r] = offset;
    offset += n;
  }
  for (const Contact& c : ws.robot_contacts) {
    if (scene.robotOf(c.body) < 0) addBodyBlock(model, bodies[c.body], c.body, solve, offset);
    if (c.other >= 0 && scene.robotOf(c.other) < 0) addBodyBlock(model, bodies[c.other], c.other, solve, offset);
  }
  solve.u.resize(offset);
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (solve.robot_offset[r] >= 0)
      solve.u.segment(solve.robot_offset[r], robots[r].model.dofCount()) = ws.robots[r].next;
  }
  for (std::size_t i = 0; i < scene.freeBodyCount(); ++i) {
    if (solve.body_offset[i] < 0) continue;
    solve.u.segment<3>(solve.body_offset[i]) = bodies[i].v_WB;
    solve.u.segment<3>(solve.body_offset[i] + 3) = bodies[i].q_WB * bodies[i].w_B;
  }
  // The rows: every robot's joints, every contact of its islands.
  solve.rows.clear();
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (solve.robot_offset[r] < 0) continue;
    detail::buildJointRows(robots[r].model, state.robots[r], ws.robots[r].next, h, solve.robot_offset[r], solve.rows);
  }
  solve.contacts.clear();
  for (std::size_t k = 0; k < ws.robot_contacts.size(); ++k) {
    const Contact& contact = ws.robot_contacts[k];
    ContactRows c;
    c.sides = 0;
    const Mat3 directions = detail::frameContact(contact, c);
    const Vec3 x_W = bodies[contact.body].p_WB + contact.r_W;
    addSide(scene, ws, solve, contact.body, x_W, contact.r_W, directions, 1.0, c);
    if (contact.other >= 0) addSide(scene, ws, solve, contact.other, x_W, contact.r_other_W, directions, -1.0, c);
    if (c.sides == 0) continue;  // between things that do not move this step
    detail::aimContact(model, contact, h, solve.u, c);
    c.contact = static_cast<int>(k);
    solve.contacts.push_back(std::move(c));
  }
  detail::warmStart(ws.last_impulses, ws.robot_contacts, solve.contacts);
  solve.impulse.setZero(offset);
  solve.lift = false;
  if (solve.rows.empty() && solve.contacts.empty()) return;
  detail::solveRows(model.solver(), solve.blocks, solve.rows, solve.contacts, solve.u, solve.impulse);
  detail::reportContactImpulses(solve.contacts, ws.robot_contacts);
  solve.lift = !solve.contacts.empty() &&
               detail::liftOutOfContacts(solve.contacts, solve.u, h, model.contact().position_slop, solve.pseudo);
  // The velocities back: the robots' for their second half, the bodies'.
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (solve.robot_offset[r] >= 0)
      ws.robots[r].next = solve.u.segment(solve.robot_offset[r], robots[r].model.dofCount());
  }
  for (std::size_t i = 0; i < scene.freeBodyCount(); ++i) {
    if (solve.body_offset[i] < 0) continue;
    BodyState& s = bodies[i];
    s.v_WB = solve.u.segment<3>(solve.body_offset[i]);
    s.w_B = s.q_WB.conjugate() * Vec3(solve.u.segment<3>(solve.body_offset[i] + 3));
    limitSpeeds(model, static_cast<int>(i), s, ws.bodies);
  }
}

/// The free bodies of the robots' islands moved by the position
/// correction's pseudo velocity (their velocities kept).
void liftBodies(const Scene& scene, const RobotSolve& solve, double h, SceneState& state) {
  for (std::size_t i = 0; i < scene.freeBodyCount(); ++i) {
    if (solve.body_offset[i] < 0) continue;
    BodyState& s = state.bodies.bodies[i];
    s.p_WB += h * solve.pseudo.segment<3>(solve.body_offset[i]);
    const Vec3 turn = h * solve.pseudo.segment<3>(solve.body_offset[i] + 3);
    const double angle = turn.norm();
    if (angle > 0.0) s.q_WB = (Quat(Eigen::AngleAxisd(angle, turn / angle)) * s.q_WB).normalized();
  }
}

/// Both lists sorted by key into `into`.
void mergeContacts(const std::vector<Contact>& a, const std::vector<Contact>& b, std::vector<Contact>& into) {
  std::vector<Contact> merged;
  merged.reserve(a.size() + b.size());
  std::merge(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(merged),
             [](const Contact& x, const Contact& y) { return x.key() < y.key(); });
  into.swap(merged);
}

void wakeRobot(ArticulationState& rs) {
  rs.asleep = false;
  rs.still_time = 0.0;
}

void wakeBody(BodyState& s) {
  s.asleep = false;
  s.still_time = 0.0;
}

/// Robot r's links as bodies where it is now, moving as it does; a
/// sleeping robot's as sleepers.
void placeLinks(const Scene& scene, std::size_t r, SceneState& state, SceneWorkspace& ws) {
  const SceneRobot& robot = scene.robots()[r];
  ArticulationWorkspace& rw = ws.robots[r];
  kinematics(robot.model, state.robots[r], rw.kin);
  const std::size_t first = static_cast<std::size_t>(robot.first_body);
  detail::setLinkStates(scene.model(), robot.link, rw.kin, first, state.bodies.bodies);
  if (!state.robots[r].asleep) return;
  for (std::size_t i = 0; i < robot.link.size(); ++i) state.bodies.bodies[first + i].asleep = true;
}

/// Robot r's first half (awake, with dofs): its velocity without rows,
/// its links placed moving at it (for the speculative margins).
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

/// A sleeping robot whose link the detection woke (something came at it)
/// wakes, and takes its first half now. A robot woken this step (by that or
/// by a load, `woken`) wakes the sleeping bodies its links touch: they
/// slept as one island, and a robot pressing on a sleeper it rested against
/// would not come at it fast enough to wake it (the free bodies' rule).
template <class LoadsOf>
void wakeHitRobots(const Scene& scene, const LoadsOf& loadsOf, double h, std::vector<char>& woken, SceneState& state,
                   SceneWorkspace& ws) {
  std::vector<BodyState>& bodies = state.bodies.bodies;
  for (std::size_t r = 0; r < scene.robots().size(); ++r) {
    const SceneRobot& robot = scene.robots()[r];
    if (!state.robots[r].asleep) continue;
    bool hit = false;
    for (std::size_t i = 0; i < robot.link.size() && !hit; ++i) hit = !bodies[robot.first_body + i].asleep;
    if (!hit) continue;
    wakeRobot(state.robots[r]);
    woken[r] = 1;
    predictRobot(scene, r, loadsOf(r), h, state, ws);
  }
  for (const Contact& c : ws.bodies.contacts) {
    if (c.other < 0) continue;
    const int ra = scene.robotOf(static_cast<std::size_t>(c.body));
    const int ro = scene.robotOf(static_cast<std::size_t>(c.other));
    if (ra >= 0 && woken[ra] && ro < 0 && bodies[c.other].asleep) wakeBody(bodies[c.other]);
    if (ro >= 0 && woken[ro] && ra < 0 && bodies[c.body].asleep) wakeBody(bodies[c.body]);
  }
}

/// Sleep for the islands that hold a robot (§6, §11.9): every robot in it
/// touching, slower than the sleep speeds for the sleep time, and every
/// awake free body in it still as long: all of them fall asleep.
void sleepRobotIslands(const Scene& scene, double h, SceneState& state, SceneWorkspace& ws) {
  const Model& model = scene.model();
  const std::size_t n = model.bodyCount();
  std::vector<char> touching(scene.robots().size(), 0);
  for (const Contact& c : ws.robot_contacts) {
    for (const int b : {c.body, c.other}) {
      const int r = b >= 0 ? scene.robotOf(static_cast<std::size_t>(b)) : -1;
      if (r >= 0) touching[r] = 1;
    }
  }
  std::vector<char> ready(n, 1);  // per island root
  std::vector<char> holds(n, 0);  // per island root: an awake robot
  for (std::size_t r = 0; r < scene.robots().size(); ++r) {
    const SceneRobot& robot = scene.robots()[r];
    ArticulationState& rs = state.robots[r];
    if (rs.asleep || robot.link.empty()) continue;
    const int root = ws.island_root[robot.first_body];
    holds[root] = 1;
    if (!detail::updateStillTime(robot.model, model.sleep(), touching[r] != 0, h, rs)) ready[root] = 0;
  }
  for (std::size_t i = 0; i < scene.freeBodyCount(); ++i) {
    const BodyState& s = state.bodies.bodies[i];
    if (!s.asleep && !readyToSleep(model, true, s)) ready[ws.island_root[i]] = 0;
  }
  for (std::size_t r = 0; r < scene.robots().size(); ++r) {
    const SceneRobot& robot = scene.robots()[r];
    if (state.robots[r].asleep || robot.link.empty()) continue;
    if (ready[ws.island_root[robot.first_body]]) detail::fallAsleep(state.robots[r]);
  }
  for (std::size_t i = 0; i < scene.freeBodyCount(); ++i) {
    BodyState& s = state.bodies.bodies[i];
    const int root = ws.island_root[i];
    if (!s.asleep && holds[root] && ready[root]) fallAsleep(s);
  }
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
  const ArticulationLoads none;
  const auto loadsOf = [&](std::size_t r) -> const ArticulationLoads& {
    return loads.robots.empty() ? none : loads.robots[r];
  };
  std::vector<char> woken(robots.size(), 0);
  for (std::size_t r = 0; r < robots.size(); ++r) {
    ArticulationState& rs = state.robots[r];
    if (rs.asleep && detail::loaded(loadsOf(r))) {
      wakeRobot(rs);
      woken[r] = 1;
    }
    predictRobot(scene, r, loadsOf(r), h, state, ws);
  }
  // The stages, as a table:
  // clang-format off
  detectContacts(model, state.bodies, h, bw);                               // §5.1  detection.cpp, over every body
  bw.contacts.erase(std::remove_if(bw.contacts.begin(), bw.contacts.end(),
                                   [&](const Contact& c) { return adjacentLinks(scene, c); }),
                    bw.contacts.end());
  wakeHitRobots(scene, loadsOf, h, woken, state, ws);                              // §11.9 a sleeping robot hit wakes
  takeRobotContacts(scene, state.bodies, ws);                               // §11.9 the robots' islands apart
  ws.last_impulses = state.bodies.contact_impulses;                         // the free solve rewrites them
  for (std::size_t i = scene.freeBodyCount(); i < model.bodyCount(); ++i) {
    state.bodies.bodies[i].asleep = true;                                   // the free stages leave links alone
  }
  integrateVelocities(model, state.bodies, loads.bodies, h, bw);            // §5.2–4 integration.cpp
  const bool impulse = solveContactImpulses(model, state.bodies, h, bw);    // §5.5  contact_solver.cpp: the other islands
  RobotSolve solve;
  solveRobotIslands(scene, state, h, ws, solve);                            // §11.9 the robots' islands, one solve
  integratePositions(model, state.bodies, h, bw);                           // §5.6–7 integration.cpp
  if (solve.lift) liftBodies(scene, solve, h, state);                       // §11.8 split impulse, the bodies
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
  sleepRobotIslands(scene, h, state, ws);                                           // §11.9 sleep, island by island
  for (std::size_t r = 0; r < robots.size(); ++r) placeLinks(scene, r, state, ws);  // for readers and the next step
  // Every contact, for the caller and the next step's warm start.
  mergeContacts(bw.contacts, ws.robot_contacts, bw.contacts);
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
