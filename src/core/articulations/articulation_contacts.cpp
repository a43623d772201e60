// An articulation's links against the scene: docs/physics.md §11.8.
#include "rigid_body_sim/core/articulations/articulation_contacts.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "joint_rows.h"
#include "rigid_body_sim/core/articulations/articulation_step.h"
#include "rigid_body_sim/core/contacts/contact.h"

namespace rigid_body_sim::core {

LinkBodies linkBodies(const ArticulationModel& model, int collision_group) {
  LinkBodies out;
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
    b.collision_group = collision_group;
    b.friction = l.surface_friction;
    out.bodies.push_back(b);
    out.link.push_back(i);
  }
  return out;
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
  const double next = clamp(c.impulse(r) + (target - c.velocity(u, r)) / k);
  const double change = next - c.impulse(r);
  if (change == 0.0) return 0.0;
  c.impulse(r) = next;
  for (int s = 0; s < c.sides; ++s) {
    u.segment(c.side[s].offset, c.side[s].J.rows()).noalias() += change * c.side[s].response.col(r);
  }
  return std::abs(change) * k;
}

}  // namespace

double sweepContactRows(const SolverSettings& settings, ContactRows& c, Eigen::VectorXd& u) {
  const double most = c.most;
  double largest = updateRow(c, 0, c.target, u, [most](double l) { return std::clamp(l, 0.0, most); });
  const double limit = c.friction * c.impulse(0);
  if (c.block) {
    // Of the impulses on the disk |λ_T| ≤ μ λ_N, the one nearest in K's
    // metric to the one that would stop the slip, as for free bodies (§5.5).
    const Eigen::Vector2d slip = c.velocity(u).tail<2>();
    const Eigen::Vector2d stick = c.impulse.tail<2>() - c.tangent_mass * slip;
    const Eigen::Vector2d lt = frictionOnDisk(settings, c.K.bottomRightCorner<2, 2>(), c.eigen, stick, limit, c.nu);
    const Eigen::Vector2d change = lt - c.impulse.tail<2>();
    if (change.x() != 0.0 || change.y() != 0.0) {
      c.impulse.tail<2>() = lt;
      c.apply(Eigen::Vector3d(0.0, change.x(), change.y()), u);
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
    c.apply(Eigen::Vector3d(0.0, change.x(), change.y()), u);
    largest = std::max(largest, change.norm() * std::max(c.K(1, 1), c.K(2, 2)));
  }
  return largest;
}

Mat3 frameContact(const Contact& contact, ContactRows& c) {
  const Vec3& n = contact.normal_W;
  c.tangent1_W = (std::abs(n.x()) < 0.57 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  c.tangent2_W = n.cross(c.tangent1_W);
  Mat3 directions;  // rows n, t₁, t₂
  directions << n.transpose(), c.tangent1_W.transpose(), c.tangent2_W.transpose();
  return directions;
}

void addLinkPoint(const ArticulationModel& model, const ArticulationKinematics& kin, int link, const Vec3& x_W,
                  const Mat3& directions, double sign, Columns& J) {
  // J's row for a dof is the velocity a unit speed of it gives the point.
  for (int l = link; l >= 0; l = model.links[l].parent) {
    const Placement& X = kin.X_WL[l];
    const Vec3 arm = x_W - X.p_PC;
    if (l > 0) {
      const Vec3 w = X.R_PC * kin.S_L[l].head<3>();
      const Vec3 v = X.R_PC * kin.S_L[l].tail<3>() + w.cross(arm);
      J.row(model.dofOf(l)) += sign * (directions * v).transpose();
    } else if (!model.fixed_base) {  // the base's twist, in its axes: ω, then its origin's v
      for (int j = 0; j < 3; ++j) {
        J.row(j) += sign * (directions * X.R_PC.col(j).cross(arm)).transpose();
        J.row(3 + j) += sign * (directions * X.R_PC.col(j)).transpose();
      }
    }
  }
}

void setBodyPoint(const Vec3& r_W, const Mat3& directions, double sign, Columns& J) {
  J.resize(6, 3);
  for (int d = 0; d < 3; ++d) {
    const Vec3 n = directions.row(d).transpose();
    J.col(d).head<3>() = sign * n;
    J.col(d).tail<3>() = sign * r_W.cross(n);
  }
}

void aimContact(const Model& bodies, const Contact& contact, double h, const Eigen::VectorXd& u, ContactRows& c) {
  c.friction = bodies.friction(contact.body, contact.point, contact.other);
  c.speed = std::max(bodies.limits().max_linear_speed, bodies.limits().max_angular_speed);
  c.separation = contact.separation;
  c.target = contact.separation > 0.0 ? -contact.separation / h : 0.0;
  // Restitution (§11.8): a contact arriving faster than the threshold
  // this step leaves at e times the speed it comes with.
  const double restitution = bodies.restitution(contact.body, contact.other);
  const double approach = c.velocity(u, 0);
  const bool arrives = contact.separation <= 0.0 || approach * h < -contact.separation;
  if (restitution > 0.0 && arrives && approach < -bodies.restitutionThreshold()) c.target = -restitution * approach;
}

void setLinkStates(const Model& bodies, const std::vector<int>& link, const ArticulationKinematics& kin,
                   std::size_t first, std::vector<BodyState>& states) {
  // Each link as a body: its centre of mass and principal axes B, its
  // velocity from its twist (in its own axes, of its origin).
  for (std::size_t i = 0; i < link.size(); ++i) {
    const BodyModel& b = bodies.body(first + i);
    const Placement& X = kin.X_WL[link[i]];
    const Vec6& V = kin.V_L[link[i]];
    BodyState& s = states[first + i];
    s = BodyState();
    s.p_WB = X.p_PC + X.R_PC * b.p_LB;
    s.q_WB = (Quat(X.R_PC) * b.q_LB).normalized();
    s.v_WB = X.R_PC * (V.tail<3>() + V.head<3>().cross(b.p_LB));
    s.w_B = b.q_LB.conjugate() * V.head<3>();
  }
}

void warmStart(const std::vector<ContactImpulse>& last, const std::vector<Contact>& contacts,
               std::vector<ContactRows>& rows) {
  std::size_t k = 0;
  for (ContactRows& c : rows) {
    const ContactKey key = contacts[c.contact].key();
    while (k < last.size() && last[k].key() < key) ++k;
    if (k == last.size() || !(last[k].key() == key)) continue;
    const double normal = std::max(last[k].normal, 0.0);
    Eigen::Vector2d tangent(c.tangent1_W.dot(last[k].tangent_W), c.tangent2_W.dot(last[k].tangent_W));
    const double limit = c.friction * normal;
    if (tangent.norm() > limit) tangent *= limit / tangent.norm();
    c.warm_start = Eigen::Vector3d(normal, tangent.x(), tangent.y());
  }
}

void reportContactImpulses(const std::vector<ContactRows>& contacts, std::vector<Contact>& contacts_out) {
  for (const ContactRows& c : contacts) {
    Contact& contact = contacts_out[c.contact];
    contact.normal_impulse = c.impulse(0);
    contact.tangent_impulse_W = c.impulse(1) * c.tangent1_W + c.impulse(2) * c.tangent2_W;
  }
}

bool liftOutOfContacts(const SolverSettings& settings, std::vector<ContactRows>& contacts, const Eigen::VectorXd& u,
                       double h, double slop, Eigen::VectorXd& pseudo) {
  // The depth each contact would end at (linear in the step); nothing to
  // do unless one is deeper than the slop.
  bool deep = false;
  std::vector<double> lift(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const double end = contacts[k].separation + h * contacts[k].velocity(u, 0);
    deep = deep || end < -slop;
    // No faster than a point may move: a lift is a velocity of the positions.
    lift[k] = std::min(std::max(-end - 0.5 * slop, 0.0) / h, contacts[k].speed);
  }
  if (!deep) return false;
  pseudo.setZero(u.size());
  for (ContactRows& c : contacts) c.impulse.setZero();
  for (int sweep = 0; sweep < settings.joint_space_sweeps; ++sweep) {
    double largest = 0.0;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      const double most = contacts[k].most;
      largest = std::max(
          largest, updateRow(contacts[k], 0, lift[k], pseudo, [most](double l) { return std::clamp(l, 0.0, most); }));
    }
    if (largest <= settings.joint_space_tolerance) break;
  }
  return true;
}

void moveRobot(const ArticulationModel& model, const Eigen::VectorXd& pseudo, double h, ArticulationState& state) {
  const int nj = model.jointCount();
  state.q += h * pseudo.tail(nj);
  for (int i = 1; i <= nj; ++i) {
    state.q(i - 1) = std::clamp(state.q(i - 1), model.links[i].limits.lower, model.links[i].limits.upper);
  }
  if (!model.fixed_base) state.X_WB = advanceBase(state.X_WB, pseudo.head<6>(), h);
}

}  // namespace detail

}  // namespace rigid_body_sim::core
