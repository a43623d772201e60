// A world as it runs: the scene (its free bodies, and its robots' links
// after them) and everything kept in the order of its bodies (the state,
// the state a reset returns to, the wrench schedule, the contact ledger, the
// step's workspace), and the robots' states. Every edit of the world goes
// through here, so they never disagree on which index is which body.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "rigid_body_sim/core/articulations/joint_effort_schedule.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/contacts/contact_report.h"
#include "rigid_body_sim/core/step/entity_ids.h"
#include "rigid_body_sim/core/step/workspace.h"
#include "rigid_body_sim/core/step/wrench_schedule.h"

namespace rigid_body_sim::core {

struct Simulation {
  Scene scene;
  State state;                            ///< every body's: the free bodies', then the links' (their robots place them)
  State initial;                          ///< what reset() returns to: the start, and each body where it was added
  std::vector<ArticulationState> robots;  ///< per robot of the scene
  std::vector<ArticulationState> initial_robots;  ///< what reset() returns them to
  WrenchSchedule schedule;
  JointEffortSchedule joint_efforts;  ///< the robots' timed joint efforts
  ContactLedger contacts;
  /// The step's memory and outputs: `bodies` holds the knobs (threads) and
  /// the contacts (links by their body index), speed limits and guard;
  /// `robot_diverged` and `robots[r].speed_limited` the robots'.
  SceneWorkspace workspace;

  /// A world of free bodies; `state` is also the initial state.
  Simulation(Model model, State state);
  /// A scene and its start (sceneState), also the initial state.
  Simulation(Scene scene, SceneState state);

  const Model& model() const { return scene.model(); }
  std::size_t freeBodyCount() const { return scene.freeBodyCount(); }

  /// One step of dt under `loads` (per free body, or per body with the
  /// links' zero, or none) and `robot_loads` (per robot, or none): the one
  /// step (step.h), in place. Throws std::invalid_argument for loads of the wrong size, and then
  /// nothing has changed.
  void step(const Loads& loads, const std::vector<ArticulationLoads>& robot_loads = {});

  /// Adds `body` last among the free bodies (the robots' links move up by
  /// one), at `start` (also its initial state). Returns its id. The model
  /// refuses a body it cannot take (a taken name, settings the body breaks)
  /// by throwing, and then nothing has changed.
  EntityId addBody(const PreparedBody& body, const BodyState& start);
  /// Adds `robot` last (Scene::addRobot), at `start` (also its initial
  /// state), its links placed there. Returns its id. Throws as
  /// Scene::addRobot does, and then nothing has changed.
  EntityId addRobot(Scene::RobotSpec robot, const ArticulationState& start);

  /// Free body i's id, which names it until it is removed, whatever else is
  /// added or removed (std::out_of_range for no such body).
  EntityId bodyId(int i) const;
  /// The index of the free body `id` names, or nothing once it is removed.
  std::optional<int> bodyIndex(EntityId id) const;
  /// Robot r's id, as bodyId's.
  EntityId robotId(std::size_t r) const { return robot_ids_.at(r); }
  /// The index of the robot `id` names, or nothing once it is removed.
  std::optional<std::size_t> robotIndex(EntityId id) const { return robot_ids_.find(id); }

  /// Takes free body i out of every table at once: its contacts, its wrenches and
  /// those in its axes go, what may touch it wakes (core::removeBody), and
  /// the later bodies' indices move down by one everywhere. Returns how many
  /// timed wrenches (WrenchSchedule::add) went with it.
  std::size_t removeBody(int i);
  /// Takes robot r out of every table at once, as removeBody takes a body:
  /// its links (their contacts, their wrenches and those in their axes),
  /// its state, start and timed joint efforts; what may touch its links
  /// wakes, robots too; the later robots and links move down. Throws
  /// std::invalid_argument for no such robot, and then nothing has changed.
  void removeRobot(std::size_t r);

  /// Puts body i at `now` (a user's set_state): every contact's warm start
  /// goes, since nothing carries over to a new pose, and the body is awake
  /// (its still time from zero) to move from there.
  void place(int i, const BodyState& now);

  /// Puts robot r at `now` (a user's set_model_configuration): its links
  /// where it puts them, every contact's warm start gone, the robot awake
  /// (its still time from zero), its carried momenta dropped.
  void placeRobot(std::size_t r, const ArticulationState& now);

  /// The model with `tuning`'s settings (Model::retuned, which throws and
  /// changes nothing when a check refuses them), and every body awake: what
  /// rested under the old settings must move under the new.
  void retune(const Tuning& tuning);

  /// Back to the initial state, robots too, at sim time `time` (which only
  /// goes forward), every wrench and joint effort cleared.
  void reset(double time);

 private:
  EntityIds body_ids_;   ///< the free bodies', in their order
  EntityIds robot_ids_;  ///< the robots', in theirs
};

}  // namespace rigid_body_sim::core
