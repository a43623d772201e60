// A world as it runs: the model and everything kept in the order of its
// bodies (the state, the state a reset returns to, the wrench schedule, the
// contact ledger, the step's workspace). Every edit of the world goes
// through here, so they never disagree on which index is which body.
#pragma once

#include <cstddef>

#include "rigid_body_sim/core/contact_report.h"
#include "rigid_body_sim/core/model.h"
#include "rigid_body_sim/core/state.h"
#include "rigid_body_sim/core/workspace.h"
#include "rigid_body_sim/core/wrench_schedule.h"

namespace rigid_body_sim::core {

struct Simulation {
  Model model;
  State state;
  State initial;  ///< what reset() returns to: the start, and each body where it was added
  WrenchSchedule schedule;
  ContactLedger contacts;
  Workspace workspace;

  /// `state` is also the initial state.
  Simulation(Model model, State state);

  /// Adds `body` last, at `start` (also its initial state). The model
  /// refuses a body it cannot take (a taken name, settings the body breaks)
  /// by throwing, and then nothing has changed.
  void addBody(const PreparedBody& body, const BodyState& start);

  /// Takes body i out of every table at once: its contacts, its wrenches and
  /// those in its axes go, what may touch it wakes (core::removeBody), and
  /// the later bodies' indices move down by one everywhere. Returns how many
  /// timed wrenches (WrenchSchedule::add) went with it.
  std::size_t removeBody(int i);

  /// Puts body i at `now` (a user's set_state): every contact's warm start
  /// goes, since nothing carries over to a new pose, and the body is awake
  /// (its still time from zero) to move from there.
  void place(int i, const BodyState& now);

  /// The model with `tuning`'s settings (Model::retuned, which throws and
  /// changes nothing when a check refuses them), and every body awake: what
  /// rested under the old settings must move under the new.
  void retune(const Tuning& tuning);

  /// Back to the initial state at sim time `time` (which only goes forward),
  /// every wrench cleared.
  void reset(double time);
};

}  // namespace rigid_body_sim::core
