// Building the impulse solver's view of a contact (solver_contact.h): the
// entries of K it needs, its target, its coefficients; and which pairs
// pressed on each other last step (their impacts are plastic).
#include "solver_contact.h"

#include <algorithm>
#include <cmath>

#include "rigid_body_sim/core/contacts/contact.h"
#include "step/scratch.h"

namespace rigid_body_sim::core::detail {
namespace {

/// A contact's pair as pressed_pairs names it.
std::array<int, 3> pairOf(const ContactKey& k) {
  return k.other < 0 ? std::array<int, 3>{k.body, -1, k.item}
                     : std::array<int, 3>{std::min(k.body, k.other), std::max(k.body, k.other), -1};
}

}  // namespace

void findPressedPairs(const State& state, std::vector<std::array<int, 3>>& pairs) {
  pairs.clear();
  for (const ContactImpulse& c : state.contact_impulses) {
    if (c.normal > 0.0) pairs.push_back(pairOf(c));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

namespace {

/// One body's side of a contact: its Jacobian rows and turns for the arm r,
/// and its share of nᵀKn (returned), of TᵀKT (added to k) and of nᵀKT
/// (added to k_nt; nᵀT = 0, so no mass term).
double prepareSide(const Vec3& r, const SolverContact& c, double inv_mass, const Mat3& inv_I, SolverContact::Side& side,
                   Eigen::Matrix2d& k, Eigen::Vector2d& k_nt) {
  side.rn = r.cross(c.normal_W);
  side.rt1 = r.cross(c.tangent1_W);
  side.rt2 = r.cross(c.tangent2_W);
  side.inv_mass = inv_mass;
  side.turn_n = inv_I * side.rn;
  side.turn_t1 = inv_I * side.rt1;
  side.turn_t2 = inv_I * side.rt2;
  Eigen::Matrix2d ks;
  ks << inv_mass + side.rt1.dot(side.turn_t1), side.rt1.dot(side.turn_t2),  //
      side.rt2.dot(side.turn_t1), inv_mass + side.rt2.dot(side.turn_t2);
  k += ks;
  k_nt += Eigen::Vector2d(side.rn.dot(side.turn_t1), side.rn.dot(side.turn_t2));
  return inv_mass + side.rn.dot(side.turn_n);
}

}  // namespace

void prepareContact(const Model& model, const State& state, const StepScratch& sc, double h, const Contact& contact,
                    const SolverContact* previous, SolverContact& c) {
  const std::vector<Mat3>& inv_I_W = sc.inverse_inertias;
  const Vec3& n = contact.normal_W;
  c.body = contact.body;
  c.other = contact.other;
  c.normal_W = n;
  c.friction = model.friction(c.body, contact.point, c.other);
  c.restitution = model.restitution(c.body, c.other);
  // A pair that pressed on each other last step meets again plastically:
  // a rocking block's new corner, a box tipping onto its face (Housner).
  if (c.restitution > 0.0 && std::binary_search(sc.pressed_pairs.begin(), sc.pressed_pairs.end(), pairOf(contact))) {
    c.restitution = 0.0;
  }
  if (previous != nullptr && previous->normal_W == n) {  // the points of one region share n and its tangents
    c.tangent1_W = previous->tangent1_W;
    c.tangent2_W = previous->tangent2_W;
  } else {
    c.tangent1_W = (std::abs(n.x()) < 0.57 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    c.tangent2_W = n.cross(c.tangent1_W);
  }
  Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
  Eigen::Vector2d k_nt = Eigen::Vector2d::Zero();
  // A sleeper is ground on either side: no terms (for the scene, other < 0,
  // o is never read). Its own points against an awake body's solid make
  // contacts whose `body` it is.
  double knn = 0.0;
  if (!state.bodies[c.body].asleep) {
    knn = prepareSide(contact.r_W, c, model.body(c.body).inv_mass, inv_I_W[c.body], c.a, k, k_nt);
  } else {
    c.a = SolverContact::Side();
  }
  if (c.other >= 0 && !state.bodies[c.other].asleep) {
    knn += prepareSide(contact.r_other_W, c, model.body(c.other).inv_mass, inv_I_W[c.other], c.o, k, k_nt);
  } else if (c.other >= 0) {
    c.o = SolverContact::Side();
  }
  c.normal_mass = 1.0 / knn;
  c.tangent_k = k;
  c.normal_tangent_k = k_nt;
  c.tangent_mass = k.inverse();
  c.separation = contact.separation;
  c.target_normal_velocity = c.separation > 0.0 ? -c.separation / h : 0.0;
  c.normal_impulse = 0.0;
  c.tangent_impulse.setZero();
  c.friction_nu = 0.0;
  c.tangent_eigen.ready = false;
}

Eigen::Vector2d frictionOnDisk(const SolverSettings& settings, const Eigen::Matrix2d& K,
                               SolverContact::TangentEigen& eigen, const Eigen::Vector2d& stick, double limit,
                               double& nu) {
  if (stick.squaredNorm() <= limit * limit) {
    nu = 0.0;
    return stick;
  }
  if (limit <= 0.0) return Eigen::Vector2d::Zero();
  if (!eigen.ready) {  // K = Q diag(k) Qᵀ, closed form for a symmetric 2×2; once per contact and step
    const double mean = 0.5 * (K(0, 0) + K(1, 1)), half_gap = 0.5 * (K(0, 0) - K(1, 1));
    const double radius = std::sqrt(half_gap * half_gap + K(0, 1) * K(0, 1));
    eigen.isotropic = radius <= settings.isotropy_tolerance * mean;
    eigen.k = Eigen::Vector2d(mean + radius, mean - radius);
    eigen.q1 =
        half_gap >= 0.0 ? Eigen::Vector2d(half_gap + radius, K(0, 1)) : Eigen::Vector2d(K(0, 1), radius - half_gap);
    if (!eigen.isotropic) eigen.q1.normalize();
    eigen.ready = true;
  }
  if (eigen.isotropic) return stick * (limit / stick.norm());  // the plain projection
  const Eigen::Vector2d& k = eigen.k;
  const Eigen::Vector2d& q1 = eigen.q1;
  const Eigen::Vector2d q2(-q1.y(), q1.x());
  const Eigen::Vector2d c(q1.dot(stick), q2.dot(stick));
  const Eigen::Vector2d kc = k.cwiseProduct(c);
  const double inv_limit = 1.0 / limit;
  nu = std::max(nu, 0.0);
  Eigen::Vector2d l = c;  // λ in the eigenbasis
  double size = 0.0;      // |l|
  for (int i = 0; i < settings.friction_newton_iterations; ++i) {
    const Eigen::Vector2d d(1.0 / (k.x() + nu), 1.0 / (k.y() + nu));
    l = kc.cwiseProduct(d);
    const double size2 = l.squaredNorm();
    size = std::sqrt(size2);
    if (std::abs(size - limit) <= settings.friction_newton_tolerance * limit) break;
    // ν += φ/(−φ') for φ = 1/|λ| − 1/limit, with d|λ|/dν = −Σ λᵢ² dᵢ / |λ|.
    nu = std::max(nu + (size2 * inv_limit - size) * size / (l.x() * l.x() * d.x() + l.y() * l.y() * d.y()), 0.0);
  }
  l *= limit / size;  // exactly on the cone (size is l.norm(), computed the same way)
  return l.x() * q1 + l.y() * q2;
}

}  // namespace rigid_body_sim::core::detail
