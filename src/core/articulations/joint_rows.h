// The rows of a joint-space impulse solve (private to the core): a robot's
// joints' limits (one-sided), Coulomb joint friction (bounded) and mimic
// joints (equalities), docs/physics.md §11.6; contacts (a normal row and a
// friction cone), each with one side per robot or free body it joins,
// §11.8 and §11.9 (articulation_contacts.cpp).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "contacts/solver_contact.h"
#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/articulations/articulation_contacts.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/articulations/tree_factor.h"
#include "rigid_body_sim/core/bodies/settings.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/step/workspace.h"

namespace rigid_body_sim::core::detail {

/// n × 3 columns: three rows of a solve, as columns (a contact's along n,
/// t₁, t₂).
using Columns = Eigen::Matrix<double, Eigen::Dynamic, 3>;

/// A block of the solve's coordinates u: a robot's joint-space velocity
/// (its A = M + h D factored), or a free body's (v_W, ω_W), whose inverse
/// inertia is 1/m and I_W⁻¹ (docs/physics.md §11.9). The blocks of a solve
/// follow one another in u.
struct CoordinateBlock {
  int offset = 0;  ///< where the block starts in u
  int size = 0;
  const TreeFactor* factor = nullptr;  ///< a robot's factored A; null for a free body
  double inv_mass = 0.0;               ///< a free body's, 1/kg
  Mat3 inv_inertia_W = Mat3::Zero();   ///< a free body's, 1/(kg·m²)
};

/// A⁻¹ J for columns J over one block's coordinates.
void respond(const CoordinateBlock& block, const Columns& J, Columns& response);

/// One row: its velocity w = J u, with J = sign e_dof + coefficient ·
/// e_other within one robot's block, is driven to `target` by an impulse λ
/// kept within [lower, upper] (the generalized impulse Jᵀλ).
struct JointRow {
  int offset = 0;                   ///< the robot's block's offset in u
  int dof = 0;                      ///< within the block
  int other = -1;                   ///< a second dof (mimic), or -1
  double coefficient = 0.0;         ///< J's entry at `other`
  double sign = 1.0;                ///< J's entry at `dof`: −1 for an upper limit
  double target = 0.0;              ///< rad/s or m/s
  double lower = 0.0, upper = 0.0;  ///< bounds on the accumulated λ, N·m·s or N·s
  double impulse = 0.0;             ///< accumulated λ
  Eigen::VectorXd response;         ///< A⁻¹ Jᵀ over the block: the velocity change a unit λ makes
  double mass = 0.0;                ///< 1 / (J A⁻¹ Jᵀ)
};

/// What one side of a contact moves: a block of u (a robot, or a free
/// body), J's columns over it and A⁻¹ J.
struct RowSide {
  int offset = 0;  ///< the block's offset in u
  Columns J;       ///< block size × 3: the point's velocity along n, t₁, t₂ per coordinate
  Columns response;
};

/// One contact: three rows, the point's velocity along n, t₁ and t₂
/// relative to the other side's (w = Σ Jᵀ u over its sides), a normal
/// impulse λ_N ≥ 0 and a friction impulse on the disk |λ_T| ≤ μ λ_N. A
/// contact with the scene, or of a robot with itself, has one side; one
/// between two robots, or a robot and a free body, two.
struct ContactRows {
  RowSide side[2];
  int sides = 1;
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero();  ///< Σ Jᵀ A⁻¹ J (1/kg)
  double friction = 0.0;                        ///< μ of the pair
  double separation = 0.0;                      ///< m, as detected
  double target = 0.0;  ///< normal velocity aimed at (m/s): −separation/h if apart, e × the approach speed in an impact
  /// The larger of the model's speed limits (m/s, rad/s), and the largest
  /// normal impulse (N·s): what changes a coordinate of what the contact
  /// moves by twice that (§11.7). Two robots overlapping where they cannot
  /// part ask for an infinite impulse; Gauss-Seidel's grew to 1e16 N·s.
  double speed = std::numeric_limits<double>::infinity();
  double most = std::numeric_limits<double>::infinity();
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();            ///< λ_N, λ₁, λ₂ (N·s)
  Eigen::Vector3d warm_start = Eigen::Vector3d::Zero();         ///< where λ starts (the last step's), in the cone
  Vec3 tangent1_W = Vec3::UnitX(), tangent2_W = Vec3::UnitY();  ///< t₁, t₂ (n is the contact's)
  int contact = 0;                                              ///< index in the detection's Workspace::contacts
  /// Friction as one 2 × 2 block by maximal dissipation (frictionOnDisk),
  /// where the sides can move the point in both tangent directions;
  /// else row by row, then onto the disk.
  bool block = false;
  Eigen::Matrix2d tangent_mass = Eigen::Matrix2d::Zero();  ///< (Tᵀ K T)⁻¹ where `block`
  SolverContact::TangentEigen eigen;
  double nu = 0.0;  ///< frictionOnDisk's multiplier of the last sweep

  /// The rows' velocities at u (m/s).
  Eigen::Vector3d velocity(const Eigen::VectorXd& u) const {
    Eigen::Vector3d w = side[0].J.transpose() * u.segment(side[0].offset, side[0].J.rows());
    if (sides > 1) w.noalias() += side[1].J.transpose() * u.segment(side[1].offset, side[1].J.rows());
    return w;
  }
  /// Row r's velocity at u (m/s).
  double velocity(const Eigen::VectorXd& u, int r) const {
    double w = side[0].J.col(r).dot(u.segment(side[0].offset, side[0].J.rows()));
    if (sides > 1) w += side[1].J.col(r).dot(u.segment(side[1].offset, side[1].J.rows()));
    return w;
  }
  /// u's change for impulses λ (N·s) along the rows.
  void apply(const Eigen::Vector3d& lambda, Eigen::VectorXd& u) const {
    for (int s = 0; s < sides; ++s) u.segment(side[s].offset, side[s].J.rows()).noalias() += side[s].response * lambda;
  }
};

#pragma GCC visibility push(hidden)

/// The rows an articulation's joints need this step, given the velocity it
/// would have without them (u_free), appended to `rows` for its block at
/// `offset`: a limit the joint could reach within h, each joint's friction,
/// each mimic joint.
void buildJointRows(const ArticulationModel& model, const ArticulationState& state, const Eigen::VectorXd& u_free,
                    double h, int offset, std::vector<JointRow>& rows);

/// Projected Gauss-Seidel over the joint rows and the contacts together,
/// each through its blocks' inverse inertia (`blocks`, in u's order):
/// u changes by Σ A⁻¹ Jᵀ λ; `impulse` gets Σ Jᵀ λ.
void solveRows(const SolverSettings& settings, const std::vector<CoordinateBlock>& blocks, std::vector<JointRow>& rows,
               std::vector<ContactRows>& contacts, Eigen::VectorXd& u, Eigen::VectorXd& impulse);

/// One Gauss-Seidel update of a contact's rows (articulation_contacts.cpp):
/// the normal toward its target, then friction on its disk. Returns the
/// largest velocity change it made along a row (m/s).
double sweepContactRows(const SolverSettings& settings, ContactRows& c, Eigen::VectorXd& u);

/// `contact`'s tangents t₁, t₂ into c, and the directions n, t₁, t₂ as a
/// matrix's rows.
Mat3 frameContact(const Contact& contact, ContactRows& c);

/// Adds to J (the robot's nv × 3) `sign` times the velocity of the point
/// x_W fixed to `link` along `directions`' rows, per coordinate: every
/// joint from the link up to the base moves it.
void addLinkPoint(const ArticulationModel& model, const ArticulationKinematics& kin, int link, const Vec3& x_W,
                  const Mat3& directions, double sign, Columns& J);

/// J (6 × 3) of a free body's point at arm r_W from its centre of mass:
/// sign × (d, r × d) per direction d, over (v_W, ω_W).
void setBodyPoint(const Vec3& r_W, const Mat3& directions, double sign, Columns& J);

/// The contact's friction, separation and target with J set: −separation/h
/// while apart; a contact arriving faster than the restitution threshold at
/// u leaves at e times that speed (§11.8).
void aimContact(const Model& bodies, const Contact& contact, double h, const Eigen::VectorXd& u, ContactRows& c);

/// The links' body states (centre of mass and principal axes, velocity)
/// from the kinematics: body i of `bodies` is link link[i], its state
/// states[first + i].
void setLinkStates(const Model& bodies, const std::vector<int>& link, const ArticulationKinematics& kin,
                   std::size_t first, std::vector<BodyState>& states);

/// Each contact starts from the impulse it carried last step (the same key
/// in `last`, sorted by key as `contacts` is), put in its cone, as the free
/// bodies' do (§5.5): resting or pressing contacts then need a few sweeps,
/// not hundreds. `rows` refer to `contacts` in ascending order.
void warmStart(const std::vector<ContactImpulse>& last, const std::vector<Contact>& contacts,
               std::vector<ContactRows>& rows);

/// After the solve: each contact's impulses into `contacts_out`.
void reportContactImpulses(const std::vector<ContactRows>& contacts, std::vector<Contact>& contacts_out);

/// The position correction (split impulse): where a contact would end the
/// step deeper than the slop, a second solve of the normal rows alone
/// finds the velocity that lifts each out to half the slop in one step:
/// `pseudo` (sized as u). Returns whether anything must move. Its sweeps
/// stop as the velocity solve's do: `settings`' joint_space_sweeps and
/// joint_space_tolerance (absolute here, m/s: the lifts are small).
bool liftOutOfContacts(const SolverSettings& settings, std::vector<ContactRows>& contacts, const Eigen::VectorXd& u,
                       double h, double slop, Eigen::VectorXd& pseudo);

/// Moves a robot's positions (not its velocities) by h times the pseudo
/// velocity `pseudo` (its block), its joints kept within their limits.
void moveRobot(const ArticulationModel& model, const Eigen::VectorXd& pseudo, double h, ArticulationState& state);

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
