// The state: everything that changes, as a plain value. A snapshot is a copy,
// a reset is an assignment, a determinism check is a comparison.
#pragma once

#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

/// State of one body, in its body frame B (centre of mass, principal axes).
/// Two cache lines: the pose and whether it sleeps (all that detection
/// reads), then the velocities (at N = 10,000 the states outgrow the L2
/// cache; bench/HISTORY.md).
struct alignas(64) BodyState {
  Vec3 p_WB = Vec3::Zero();      ///< centre of mass in the world (m)
  bool asleep = false;           ///< not integrated until woken (see SleepSettings)
  Quat q_WB = Quat::Identity();  ///< orientation of B in W (unit)
  Vec3 v_WB = Vec3::Zero();      ///< velocity of the centre of mass, world frame (m/s)
  /// Angular velocity expressed in B (rad/s). Stored in the body frame
  /// because Euler's equations live there: a torque-free step needs no
  /// rotation of vectors, and the world value is R_WB w_B.
  Vec3 w_B = Vec3::Zero();
  double still_time = 0.0;  ///< s spent below the sleep speeds

  bool operator==(const BodyState& o) const {
    return p_WB == o.p_WB && v_WB == o.v_WB && q_WB.coeffs() == o.q_WB.coeffs() && w_B == o.w_B && asleep == o.asleep &&
           still_time == o.still_time;
  }
};

/// ContactKey::point of the contact where an edge of `body`'s box crosses an
/// edge of the other body's box, between their samples; the ids below it
/// name where its edges cross the sides of the other's face (box_pair.h,
/// docs/physics.md §5.1).
constexpr int kEdgeCrossing = -2;

/// What names a contact from step to step: the body, what it touches (another
/// body or a scene item) and which of the body's contact points touches.
/// Contacts and their impulses are kept sorted by it; warm starting matches
/// them by it. The one place contacts are compared.
struct ContactKey {
  int body = 0;    ///< index in the model
  int other = -1;  ///< the other body, or -1 for a scene item
  int item = -1;   ///< index in model.scene(), or -1 for a body
  int point = 0;  ///< index in `body`'s contact points; negative: a point of a box pair's own (kEdgeCrossing and below)

  const ContactKey& key() const { return *this; }
  bool operator==(const ContactKey& o) const {
    return body == o.body && other == o.other && item == o.item && point == o.point;
  }
  bool operator<(const ContactKey& o) const {
    if (body != o.body) return body < o.body;
    if (other != o.other) return other < o.other;
    if (item != o.item) return item < o.item;
    return point < o.point;
  }
};

/// The impulse a contact carried in the last step, which starts the next
/// step's solve (warm starting, as Box2D and Bullet do): a resting body's
/// contacts then converge in one sweep instead of fifteen.
struct ContactImpulse : ContactKey {
  double normal = 0.0;            ///< λ_N, N·s
  Vec3 tangent_W = Vec3::Zero();  ///< λ_T, N·s, world frame

  bool operator==(const ContactImpulse& o) const {
    return key() == o.key() && normal == o.normal && tangent_W == o.tangent_W;
  }
};

struct State {
  double time = 0.0;  ///< s
  std::vector<BodyState> bodies;
  /// Last step's contact impulses, sorted by (body, other, item, point).
  std::vector<ContactImpulse> contact_impulses;

  bool operator==(const State& o) const {
    return time == o.time && bodies == o.bodies && contact_impulses == o.contact_impulses;
  }
};

/// The kinematics users see: the URDF root link frame L.
struct LinkState {
  Vec3 p_WL = Vec3::Zero();      ///< link origin in the world (m)
  Quat q_WL = Quat::Identity();  ///< link orientation in the world
  Vec3 v_WL = Vec3::Zero();      ///< velocity of the link origin, world frame (m/s)
  Vec3 w_W = Vec3::Zero();       ///< angular velocity, world frame (rad/s)
};

/// Link pose and twist of a body.
LinkState linkState(const BodyModel& body, const BodyState& s);

/// The pose and twist of a frame S fixed in a link at X_LS (S's origin
/// moves at v + ω × r, r the offset in world axes).
LinkState frameState(const LinkState& link, const Pose& X_LS);

/// The body state whose link frame has the given pose and twist.
BodyState bodyStateFromLink(const BodyModel& body, const LinkState& link);

/// Takes body i of `model` out of the state, as model.withoutBody(i) takes
/// it out of the model: its last contact impulses go, the later bodies'
/// indices in the others move down by one (their warm starts kept), and
/// every body that may touch it wakes (within both bounding radii plus 1 cm
/// of it, or holding a contact impulse with it): what rested on it falls.
void removeBody(const Model& model, State& state, int i);
/// removeBody() for bodies first .. first + count − 1 at once (a robot's
/// links): what may touch any of them wakes, the later bodies move down by
/// `count`.
void removeBodies(const Model& model, State& state, int first, int count);
/// Puts `start` in as body i, as Model::insertBody(i) puts a body in: the
/// bodies from i on move up by one in the contact impulses (their warm
/// starts kept). Nothing wakes: the new body's contacts wake what it hits.
void insertBody(State& state, int i, const BodyState& start);

/// Every body awake, its still time from zero: after the settings a body
/// rests under changed (gravity, friction), none may stay asleep.
void wakeAll(State& state);

/// A state with every body at rest at the identity pose, time 0.
State restState(const Model& model);

/// True once a body has stayed below the sleep speeds for the sleep time
/// (whether or not sleeping is enabled).
bool atRest(const Model& model, const BodyState& s);

/// Angular velocity in the world frame: ω_W = R_WB w_B (rad/s).
inline Vec3 angularVelocityWorld(const BodyState& s) { return s.q_WB * s.w_B; }

}  // namespace rigid_body_sim::core
