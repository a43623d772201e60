// The islands that hold a robot and their one solve: docs/physics.md §11.9.
#include <algorithm>
#include <numeric>

#include "contacts/solver_contact.h"
#include "scene_stages.h"
#include "step/guard.h"
#include "step/scratch.h"

namespace rigid_body_sim::core::detail {

void takeRobotContacts(const World& world, WorldState& world_state, WorldWorkspace& ws) {
  if (world.robots().empty()) return;
  const State& state = world_state.bodies;
  const std::size_t n = world.model().bodyCount();
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
  for (const SceneRobot& robot : world.robots()) {
    for (std::size_t k = 1; k < robot.link.size(); ++k) unite(robot.first_body, robot.first_body + static_cast<int>(k));
  }
  std::vector<Contact>& all = ws.bodies.contacts;
  for (const Contact& c : all) {
    if (c.other >= 0 && !state.bodies[c.body].asleep && !state.bodies[c.other].asleep) unite(c.body, c.other);
  }
  ws.scratch->island_root.resize(n);
  for (std::size_t i = 0; i < n; ++i) ws.scratch->island_root[i] = find(static_cast<int>(i));
  // A sleeping robot's links are sleepers: their contacts are the free
  // bodies' (ground to them) unless an awake robot's island holds them.
  std::vector<char> holds_robot(n, 0);
  for (std::size_t i = world.freeBodyCount(); i < n; ++i) {
    if (!state.bodies[i].asleep) holds_robot[ws.scratch->island_root[i]] = 1;
  }
  ws.scratch->robot_contacts.clear();
  std::size_t kept = 0;
  for (const Contact& c : all) {
    const bool robot = holds_robot[find(c.body)] || (c.other >= 0 && holds_robot[find(c.other)]);
    if (robot) {
      ws.scratch->robot_contacts.push_back(c);
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
  // The free solve rewrites the state's impulses: the robots' warm start
  // keeps the last step's. The free stages leave the links alone.
  ws.scratch->last_impulses = state.contact_impulses;
  for (std::size_t i = world.freeBodyCount(); i < n; ++i) world_state.bodies.bodies[i].asleep = true;
}

namespace {

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
void addSide(const World& world, const WorldWorkspace& ws, const RobotSolve& solve, int body, const Vec3& x_W,
             const Vec3& arm_W, const Mat3& directions, double sign, ContactRows& c) {
  const int r = world.robotOf(static_cast<std::size_t>(body));
  const int offset = r >= 0 ? solve.robot_offset[r] : solve.body_offset[body];
  if (offset < 0) return;
  if (r < 0) {
    c.side[c.sides].offset = offset;
    detail::setBodyPoint(arm_W, directions, sign, c.side[c.sides].J);
    ++c.sides;
    return;
  }
  const SceneRobot& robot = world.robots()[r];
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

}  // namespace

void solveRobotIslands(const World& world, WorldState& state, double h, WorldWorkspace& ws) {
  if (world.robots().empty()) return;
  RobotSolve& solve = ws.scratch->solve;
  const Model& model = world.model();
  const std::vector<SceneRobot>& robots = world.robots();
  std::vector<BodyState>& bodies = state.bodies.bodies;
  // The blocks: the robots, then the free bodies in contact order.
  solve.blocks.clear();
  solve.robot_offset.assign(robots.size(), -1);
  solve.body_offset.assign(model.bodyCount(), -1);
  int offset = 0;
  for (std::size_t r = 0; r < robots.size(); ++r) {
    const int n = robots[r].model.dofCount();
    if (n == 0 || state.robots[r].asleep) continue;  // a sleeping robot is ground
    solve.blocks.push_back({offset, n, &ws.robots[r].factor});
    solve.robot_offset[r] = offset;
    offset += n;
  }
  for (const Contact& c : ws.scratch->robot_contacts) {
    if (world.robotOf(c.body) < 0) addBodyBlock(model, bodies[c.body], c.body, solve, offset);
    if (c.other >= 0 && world.robotOf(c.other) < 0) addBodyBlock(model, bodies[c.other], c.other, solve, offset);
  }
  solve.u.resize(offset);
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (solve.robot_offset[r] >= 0)
      solve.u.segment(solve.robot_offset[r], robots[r].model.dofCount()) = ws.robots[r].next;
  }
  for (std::size_t i = 0; i < world.freeBodyCount(); ++i) {
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
  // The contacts' rows, reusing last step's memory (their J's keep theirs).
  const std::vector<Contact>& contacts = ws.scratch->robot_contacts;
  if (solve.contacts.size() < contacts.size()) solve.contacts.resize(contacts.size());
  std::size_t used = 0;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const Contact& contact = contacts[k];
    ContactRows& c = solve.contacts[used];
    c.sides = 0;
    c.warm_start.setZero();
    const Mat3 directions = detail::frameContact(contact, c);
    const Vec3 x_W = bodies[contact.body].p_WB + contact.r_W;
    addSide(world, ws, solve, contact.body, x_W, contact.r_W, directions, 1.0, c);
    if (contact.other >= 0) addSide(world, ws, solve, contact.other, x_W, contact.r_other_W, directions, -1.0, c);
    if (c.sides == 0) continue;  // between things that do not move this step
    detail::aimContact(model, contact, h, solve.u, c);
    c.contact = static_cast<int>(k);
    ++used;
  }
  solve.contacts.resize(used);
  detail::warmStart(ws.scratch->last_impulses, ws.scratch->robot_contacts, solve.contacts);
  solve.impulse.setZero(offset);
  solve.lift = false;
  if (solve.rows.empty() && solve.contacts.empty()) return;
  detail::solveRows(model.solver(), solve.blocks, solve.rows, solve.contacts, solve.u, solve.impulse);
  detail::reportContactImpulses(solve.contacts, ws.scratch->robot_contacts);
  solve.lift = !solve.contacts.empty() && detail::liftOutOfContacts(model.solver(), solve.contacts, solve.u, h,
                                                                    model.contact().position_slop, solve.pseudo);
  // The velocities back: the robots' for their second half, the bodies'.
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (solve.robot_offset[r] >= 0)
      ws.robots[r].next = solve.u.segment(solve.robot_offset[r], robots[r].model.dofCount());
  }
  for (std::size_t i = 0; i < world.freeBodyCount(); ++i) {
    if (solve.body_offset[i] < 0) continue;
    BodyState& s = bodies[i];
    s.v_WB = solve.u.segment<3>(solve.body_offset[i]);
    s.w_B = s.q_WB.conjugate() * Vec3(solve.u.segment<3>(solve.body_offset[i] + 3));
    limitSpeeds(model, static_cast<int>(i), s, ws.bodies);
  }
}

void liftBodies(const World& world, const WorldWorkspace& ws, double h, WorldState& state) {
  if (world.robots().empty() || !ws.scratch->solve.lift) return;
  const RobotSolve& solve = ws.scratch->solve;
  for (std::size_t i = 0; i < world.freeBodyCount(); ++i) {
    if (solve.body_offset[i] < 0) continue;
    BodyState& s = state.bodies.bodies[i];
    // A lift is a velocity of the positions: no faster than the limits.
    const auto capped = [](const Vec3& v, double most) {
      const double speed = v.stableNorm();
      return speed > most ? Vec3(v * (most / speed)) : v;
    };
    const SpeedLimits& limits = world.model().limits();
    s.p_WB += h * capped(solve.pseudo.segment<3>(solve.body_offset[i]), limits.max_linear_speed);
    const Vec3 turn = h * capped(solve.pseudo.segment<3>(solve.body_offset[i] + 3), limits.max_angular_speed);
    const double angle = turn.norm();
    if (angle > 0.0) s.q_WB = (Quat(Eigen::AngleAxisd(angle, turn / angle)) * s.q_WB).normalized();
  }
}

}  // namespace rigid_body_sim::core::detail
