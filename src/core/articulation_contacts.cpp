// An articulation's links against the scene: docs/physics.md §11.8.
#include "rigid_body_sim/core/articulation_contacts.h"

#include <algorithm>
#include <cmath>

#include "joint_rows.h"
#include "rigid_body_sim/core/articulation_step.h"
#include "rigid_body_sim/core/contact.h"

namespace rigid_body_sim::core {

ArticulationColliders articulationColliders(const ArticulationModel& model, const ModelSpec& settings) {
  const bool self_collision = settings.contact.self_collision;
  ModelSpec spec = settings;
  spec.bodies.clear();
  std::vector<int> link;
  for (int i = model.fixed_base ? 1 : 0; i < static_cast<int>(model.links.size()); ++i) {
    const ArticulatedLink& l = model.links[i];
    if (l.collision.empty()) continue;
    BodySpec b;
    b.name = l.name;
    b.link = l.name;
    b.mass = l.mass.mass;
    b.p_LC = l.mass.p_FC;
    b.I_C_L = l.mass.I_C_F;
    b.collision = l.collision;
    b.collision_group = self_collision ? -1 : 0;
    spec.bodies.push_back(b);
    link.push_back(i);
  }
  return {Model(spec), link, self_collision};
}

namespace detail {

namespace {

/// A row's diagonal entry below this fraction of K's trace is a direction
/// the articulation cannot move the point in (a pendulum's point along its
/// axle): the row is left out, not solved through rounding.
constexpr double kMovableFraction = 1e-12;

/// One row's Gauss-Seidel update: λ toward the target, then `clamp`;
/// returns the velocity change along the row.
template <class Clamp>
double updateRow(ContactRows& c, int r, double target, Eigen::VectorXd& u, Clamp&& clamp) {
  const double k = c.K(r, r);
  if (!(k > kMovableFraction * c.K.trace())) return 0.0;
  const double next = clamp(c.impulse(r) + (target - c.J.col(r).dot(u)) / k);
  const double change = next - c.impulse(r);
  if (change == 0.0) return 0.0;
  c.impulse(r) = next;
  u.noalias() += change * c.response.col(r);
  return std::abs(change) * k;
}

}  // namespace

double sweepContactRows(const SolverSettings& settings, ContactRows& c, Eigen::VectorXd& u) {
  double largest = updateRow(c, 0, c.target, u, [](double l) { return std::max(l, 0.0); });
  const double limit = c.friction * c.impulse(0);
  if (c.block) {
    // Of the impulses on the disk |λ_T| ≤ μ λ_N, the one nearest in K's
    // metric to the one that would stop the slip, as for free bodies (§5.5).
    const Eigen::Vector2d slip = c.J.rightCols<2>().transpose() * u;
    const Eigen::Vector2d stick = c.impulse.tail<2>() - c.tangent_mass * slip;
    const Eigen::Vector2d lt = frictionOnDisk(settings, c.K.bottomRightCorner<2, 2>(), c.eigen, stick, limit, c.nu);
    const Eigen::Vector2d change = lt - c.impulse.tail<2>();
    if (change.x() != 0.0 || change.y() != 0.0) {
      c.impulse.tail<2>() = lt;
      u.noalias() += c.response.rightCols<2>() * change;
      largest = std::max(largest, (c.K.bottomRightCorner<2, 2>() * change).norm());
    }
    return largest;
  }
  // A point the articulation moves along one tangent only: each tangent row
  // toward sticking within ±μ λ_N, then the pair onto the disk.
  const auto box = [limit](double l) { return std::clamp(l, -limit, limit); };
  largest = std::max(largest, updateRow(c, 1, 0.0, u, box));
  largest = std::max(largest, updateRow(c, 2, 0.0, u, box));
  const Eigen::Vector2d lt = c.impulse.tail<2>();
  const double size = lt.norm();
  if (size > limit) {
    const Eigen::Vector2d change = lt * (limit / size) - lt;
    c.impulse.tail<2>() += change;
    u.noalias() += c.response.rightCols<2>() * change;
    largest = std::max(largest, change.norm() * std::max(c.K(1, 1), c.K(2, 2)));
  }
  return largest;
}

void findContactRows(const ArticulationModel& model, const ArticulationColliders& colliders,
                     const ArticulationKinematics& kin, const Eigen::VectorXd& u, double h, State& links, Workspace& ws,
                     std::vector<ContactRows>& contacts) {
  contacts.clear();
  const Model& bodies = colliders.bodies;
  if (bodies.bodyCount() == 0 || (bodies.scene().empty() && !colliders.self_collision)) {
    ws.contacts.clear();
    return;
  }
  // Each link as a body: its centre of mass and principal axes B, its
  // velocity from its twist (in its own axes, of its origin).
  links.bodies.resize(bodies.bodyCount());
  for (std::size_t i = 0; i < bodies.bodyCount(); ++i) {
    const BodyModel& b = bodies.body(i);
    const int l = colliders.link[i];
    const Placement& X = kin.X_WL[l];
    const Vec6& V = kin.V_L[l];
    BodyState& s = links.bodies[i];
    s = BodyState();
    s.p_WB = X.p_PC + X.R_PC * b.p_LB;
    s.q_WB = (Quat(X.R_PC) * b.q_LB).normalized();
    s.v_WB = X.R_PC * (V.tail<3>() + V.head<3>().cross(b.p_LB));
    s.w_B = b.q_LB.conjugate() * V.head<3>();
  }
  detectContacts(bodies, links, h, ws);
  // Links joined by a joint never touch each other (they meet at it).
  const auto adjacent = [&](const Contact& c) {
    if (c.other < 0) return false;
    const int a = colliders.link[c.body], o = colliders.link[c.other];
    return model.links[a].parent == o || model.links[o].parent == a;
  };
  ws.contacts.erase(std::remove_if(ws.contacts.begin(), ws.contacts.end(), adjacent), ws.contacts.end());
  const int nv = model.dofCount();
  contacts.resize(ws.contacts.size());
  for (std::size_t k = 0; k < ws.contacts.size(); ++k) {
    const Contact& contact = ws.contacts[k];
    ContactRows& c = contacts[k];
    const Vec3& n = contact.normal_W;
    c.tangent1_W = (std::abs(n.x()) < 0.57 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    c.tangent2_W = n.cross(c.tangent1_W);
    Mat3 directions;  // rows n, t₁, t₂
    directions << n.transpose(), c.tangent1_W.transpose(), c.tangent2_W.transpose();
    const Vec3 x_W = links.bodies[contact.body].p_WB + contact.r_W;
    // J's row for a dof is the point's velocity a unit speed of it gives,
    // along n, t₁ and t₂: every joint from the link up to the base moves
    // it; against another link of the robot, less that link's point's.
    c.J.setZero(nv, 3);
    const auto addPoint = [&](int link, double sign) {
      for (int l = link; l >= 0; l = model.links[l].parent) {
        const Placement& X = kin.X_WL[l];
        const Vec3 arm = x_W - X.p_PC;
        if (l > 0) {
          const Vec3 w = X.R_PC * kin.S_L[l].head<3>();
          const Vec3 v = X.R_PC * kin.S_L[l].tail<3>() + w.cross(arm);
          c.J.row(model.dofOf(l)) += sign * (directions * v).transpose();
        } else if (!model.fixed_base) {  // the base's twist, in its axes: ω, then its origin's v
          for (int j = 0; j < 3; ++j) {
            c.J.row(j) += sign * (directions * X.R_PC.col(j).cross(arm)).transpose();
            c.J.row(3 + j) += sign * (directions * X.R_PC.col(j)).transpose();
          }
        }
      }
    };
    addPoint(colliders.link[contact.body], 1.0);
    if (contact.other >= 0) addPoint(colliders.link[contact.other], -1.0);
    c.friction = bodies.friction(contact.body, contact.other);
    c.separation = contact.separation;
    c.target = contact.separation > 0.0 ? -contact.separation / h : 0.0;
    // Restitution (§11.8): a contact arriving faster than the threshold
    // this step leaves at e times the speed it comes with.
    const double restitution = bodies.restitution(contact.body, contact.other);
    const double approach = c.J.col(0).dot(u);
    const bool arrives = contact.separation <= 0.0 || approach * h < -contact.separation;
    if (restitution > 0.0 && arrives && approach < -bodies.restitutionThreshold()) {
      c.target = -restitution * approach;
    }
    c.contact = static_cast<int>(k);
  }
}

void reportContactImpulses(const std::vector<ContactRows>& contacts, Workspace& ws) {
  for (const ContactRows& c : contacts) {
    Contact& contact = ws.contacts[c.contact];
    contact.normal_impulse = c.impulse(0);
    contact.tangent_impulse_W = c.impulse(1) * c.tangent1_W + c.impulse(2) * c.tangent2_W;
  }
}

bool correctContactPositions(const ArticulationModel& model, std::vector<ContactRows>& contacts,
                             const Eigen::VectorXd& u, double h, double slop, ArticulationState& state) {
  // The depth each contact would end at (linear in the step); nothing to
  // do unless one is deeper than the slop.
  bool deep = false;
  std::vector<double> lift(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const double end = contacts[k].separation + h * contacts[k].J.col(0).dot(u);
    deep = deep || end < -slop;
    lift[k] = std::max(-end - 0.5 * slop, 0.0) / h;
  }
  if (!deep) return false;
  Eigen::VectorXd pseudo = Eigen::VectorXd::Zero(u.size());
  for (ContactRows& c : contacts) c.impulse.setZero();
  for (int sweep = 0; sweep < 200; ++sweep) {
    double largest = 0.0;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      largest =
          std::max(largest, updateRow(contacts[k], 0, lift[k], pseudo, [](double l) { return std::max(l, 0.0); }));
    }
    if (largest <= 1e-12) break;
  }
  const int nj = model.jointCount();
  const int base = model.fixed_base ? 0 : 6;
  state.q += h * pseudo.tail(nj);
  for (int i = 1; i <= nj; ++i) {
    state.q(i - 1) = std::clamp(state.q(i - 1), model.links[i].limits.lower, model.links[i].limits.upper);
  }
  if (base) state.X_WB = advanceBase(state.X_WB, pseudo.head<6>(), h);
  return true;
}

}  // namespace detail

}  // namespace rigid_body_sim::core
