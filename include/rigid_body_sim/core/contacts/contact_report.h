// What touches what after a step, one report per touching pair, as the
// node's ~contacts publishes it (docs/physics.md §10.3), and the contacts a
// sleeping body keeps (ContactLedger). ROS-free.
#pragma once

#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/contacts/contact.h"

namespace rigid_body_sim::core {

/// A contact touches: it pushed (a normal impulse), or it penetrates.
inline bool touching(const Contact& c) { return c.normal_impulse > 0.0 || c.separation <= 0.0; }

/// A touching pair: a body and a scene item, or two bodies (body < other).
struct ContactPairReport {
  int body = 0;                          ///< index in the model
  int other = -1;                        ///< the other body, or -1 for the scene item `item`
  int item = -1;                         ///< index in model.scene(), or -1
  std::vector<Vec3> points_W;            ///< the touching points, world (m)
  Vec3 normal_W = Vec3::UnitZ();         ///< unit, from the other (or the item) toward `body`
  double depth = 0.0;                    ///< m, the deepest penetration, ≥ 0
  Vec3 normal_force_W = Vec3::Zero();    ///< N, on `body`: the normal impulses over the step / Δt
  Vec3 friction_force_W = Vec3::Zero();  ///< N, on `body`: the friction impulses / Δt
};

/// The pairs of `contacts` (a step's solved contacts, Workspace::contacts)
/// with a touching point (a normal impulse, or a penetration), sorted by
/// (body, other, item). A pair of bodies reported both ways (each body's
/// points against the other's solid) is one report, on the lower index.
std::vector<ContactPairReport> contactPairs(const Model& model, const State& state,
                                            const std::vector<Contact>& contacts);

/// What touches what, sleepers included. The step reports only the awake
/// bodies' contacts (a sleeper is not detected again); a sleeping body keeps
/// the touching contacts it fell asleep with, taken from the step in which
/// it did, until it wakes. Call update() after every step.
class ContactLedger {
 public:
  /// Takes the contacts of the bodies that fell asleep in the step whose
  /// contacts are `step_contacts`, and drops those of the bodies that woke.
  /// A step that changed no body's sleep changes nothing (no scan: a resting
  /// pile of 1,000 boxes keeps about 4,000).
  void update(const State& state, const std::vector<Contact>& step_contacts);
  /// Every touching contact now: the awake bodies' from the step, the
  /// sleepers' kept.
  std::vector<Contact> touchingNow(const State& state, const std::vector<Contact>& step_contacts) const;
  /// The sleepers' contacts kept.
  const std::vector<Contact>& kept() const { return kept_; }
  /// After `removeBody(model, state, body)`: its contacts go and the later
  /// indices move down, as the state's did.
  void removeBody(int body);
  /// After `insertBody(state, body, ...)`: the indices from `body` on move up.
  void insertBody(int body);

 private:
  std::vector<Contact> kept_;
  std::vector<char> kept_for_;    ///< per body: asleep, its contacts in kept_
  std::vector<char> was_asleep_;  ///< per body: asleep after the last update
};

/// What touches after one step, for those who read it (the sensors of
/// forces, ~contacts): every touching contact (ContactLedger::touchingNow,
/// the ledger updated with the step) and their pairs (contactPairs), each
/// found on its first ask and kept for the step. Refers to what it was made
/// from, which must outlive it unchanged.
class StepContacts {
 public:
  StepContacts(const Model& model, const State& state, const ContactLedger& ledger,
               const std::vector<Contact>& step_contacts)
      : model_(model), state_(state), ledger_(ledger), step_contacts_(step_contacts) {}
  const std::vector<Contact>& touching();
  const std::vector<ContactPairReport>& pairs();

 private:
  const Model& model_;
  const State& state_;
  const ContactLedger& ledger_;
  const std::vector<Contact>& step_contacts_;
  std::vector<Contact> touching_;
  std::vector<ContactPairReport> pairs_;
  bool found_touching_ = false, found_pairs_ = false;
};

}  // namespace rigid_body_sim::core
