// An articulation: a tree of rigid links joined by one-degree-of-freedom
// joints (revolute, continuous, prismatic), its base fixed to the world or
// floating; and its state in generalized coordinates (docs/physics.md §11).
// Eigen only.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/spatial.h"
#include "rigid_body_sim/core/bodies/collision.h"
#include "rigid_body_sim/core/bodies/geometry.h"
#include "rigid_body_sim/core/bodies/inertia.h"
#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"

namespace rigid_body_sim::core {

enum class JointType { Revolute, Continuous, Prismatic };

/// What a URDF's <limit> says; infinite where it says nothing.
struct JointLimits {
  double lower = -std::numeric_limits<double>::infinity();    ///< rad or m
  double upper = std::numeric_limits<double>::infinity();     ///< rad or m
  double effort = std::numeric_limits<double>::infinity();    ///< N·m or N, a clip on commanded effort
  double velocity = std::numeric_limits<double>::infinity();  ///< rad/s or m/s

  /// u within ±effort: the one clip of a commanded effort, whoever gives it
  /// (a controller, the control stage's sum, the step's input).
  double heldEffort(double u) const { return std::clamp(u, -effort, effort); }
};

/// A URDF <mimic>: q = multiplier · q_joint + offset.
struct Mimic {
  int joint = -1;  ///< index of the joint followed (a link index), -1 for none
  double multiplier = 1.0;
  double offset = 0.0;  ///< rad or m
};

/// A link and the joint that moves it relative to its parent. Links joined
/// by fixed joints are one link here (lumped as a body's links are, §2).
struct ArticulatedLink {
  std::string name;  ///< the link's URDF name (the lumped group's first)
  int parent = -1;   ///< index of the parent link, lower than this one's; -1 for the base
  // The joint to the parent (unused for the base):
  std::string joint;                     ///< its URDF name
  JointType type = JointType::Revolute;  ///<
  Pose X_PJ;                             ///< joint frame J in the parent link's frame (URDF <origin>)
  Vec3 axis_J = Vec3::UnitX();           ///< unit axis in J, which is the child link's frame at q = 0
  JointLimits limits;
  double damping = 0.0;   ///< viscous, N·m·s/rad or N·s/m
  double friction = 0.0;  ///< Coulomb, N·m or N
  Mimic mimic;
  // The link itself:
  MassProperties mass;                    ///< in the link frame
  std::vector<CollisionShape> collision;  ///< its <collision> elements, posed in its frame
  std::vector<FixedLink> fixed_links;     ///< the URDF links lumped into it, in URDF order
  /// μ of its surfaces (a URDF's `<gazebo reference="LINK"><mu1>`); unset:
  /// the robot's (its config entry's `contact.friction`, or the scene's).
  std::optional<double> surface_friction;
};

/// A URDF joint that moves no mass (only massless links hang from it): it
/// is held at `position`, its links fixed links of the link it hangs from,
/// and still reported with the joints (docs/physics.md §2.1).
struct HeldJoint {
  std::string name;       ///< its URDF name
  double position = 0.0;  ///< rad or m: 0, or the limit nearest to it
};

/// The links in an order where every parent comes before its children; the
/// base is link 0. Joint i is the joint of link i (i ≥ 1).
struct ArticulationModel {
  std::string name;         ///< the robot's name (the URDF's <robot name>)
  bool fixed_base = false;  ///< true: the base stays where the state puts it (URDF root `world`)
  std::vector<ArticulatedLink> links;
  std::vector<HeldJoint> held;  ///< joints that move no mass, in URDF order

  int jointCount() const { return static_cast<int>(links.size()) - 1; }
  /// Generalized velocities: the base twist (6, floating only), then one per joint.
  int dofCount() const { return (fixed_base ? 0 : 6) + jointCount(); }
  /// The index in the generalized velocity vector of link i's joint.
  int dofOf(int link) const { return (fixed_base ? 0 : 6) + link - 1; }
};

/// Throws std::invalid_argument naming every link or joint at fault when
/// the model cannot be simulated: a parent not before its child, a negative
/// mass or an inertia no body can have, an axis of zero length, lower >
/// upper, a negative damping, friction or effort limit, a mimic of itself or
/// of another mimic, a non-finite number, or a joint that moves no mass or
/// inertia in the rest pose (a singular mass matrix: a link may be massless
/// only when what hangs from it moves with its joint).
void checkArticulation(const ArticulationModel& model);

/// The link whose joint is `model`'s moving joint `name`, or −1.
int linkOfJoint(const ArticulationModel& model, const std::string& name);

/// " (joint 'NAME' is held: it moves only massless links)" when `name` is a
/// held joint of `model`, else "": for the messages that refuse a joint name.
std::string heldJointNote(const ArticulationModel& model, const std::string& name);

/// An articulation's state. The base twist is in the base link's axes,
/// [ω; v] with v the velocity of its origin, as a free body's ω is (§1).
struct ArticulationState {
  Pose X_WB;                ///< the base link's pose in W
  Vec6 V_B = Vec6::Zero();  ///< the base twist (zero for a fixed base)
  Eigen::VectorXd q;        ///< joint positions, joint i at i − 1 (rad or m)
  Eigen::VectorXd v;        ///< joint velocities (rad/s or m/s)
  /// Asleep (§11.8): at rest on its contacts, not stepped until a load
  /// wakes it or the caller clears the flag (after editing the state).
  bool asleep = false;
  double still_time = 0.0;  ///< s spent touching and slower than the sleep speeds

  /// The momenta the step carries from one step to the next (§11.5), and the
  /// state it left them with: they are used only while q, v and the base are
  /// still that state bit for bit, so any edit makes the next step take
  /// them from the velocities again.
  struct Carried {
    bool valid = false;
    Eigen::VectorXd p;        ///< the joints' momenta ∂T/∂q̇ (symplectic Euler's; Verlet carries none)
    Vec6 H_W = Vec6::Zero();  ///< total momentum, world axes, about W's origin (floating base)
    Eigen::VectorXd q, v;
    Pose X_WB;
    Vec6 V_B = Vec6::Zero();
    int predict_only = 0;  ///< steps left that skip the corrector, after one where it did not contract
    Eigen::VectorXd gain;  ///< Verlet: what the dynamics alone changed the velocity by in the last step
  } carried;
};

/// Where a joint rests at the start: 0, or the limit nearest to 0 when its
/// limits leave 0 out (arms whose zero is no legal pose, legs whose calves
/// start folded: Gazebo snaps them there on the first step, §11.6).
double restPosition(const ArticulatedLink& link);

/// The state at rest with every joint at its restPosition, each mimic where
/// its joint puts it (the base at X_WB).
ArticulationState restState(const ArticulationModel& model, const Pose& X_WB = {});

/// The base link's pose and twist in the world, as a free body's link is
/// given (the state keeps the twist in the base's axes).
LinkState baseLinkState(const ArticulationState& state);
/// Places the base and sets its twist from its link's pose and twist in the
/// world (baseLinkState's inverse; the orientation normalised).
void setBaseLinkState(ArticulationState& state, const LinkState& base);

/// The generalized velocity vector: [V_B (floating only); v].
Eigen::VectorXd generalizedVelocity(const ArticulationModel& model, const ArticulationState& state);
/// Sets the base twist and joint velocities from a generalized velocity.
void setGeneralizedVelocity(const ArticulationModel& model, const Eigen::VectorXd& u, ArticulationState& state);

}  // namespace rigid_body_sim::core
