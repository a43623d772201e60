#include "rigid_body_sim/core/step/simulation.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "world.h"

namespace rigid_body_sim::core {

Simulation::Simulation(Model model_in, State state_in)
    : scene(std::move(model_in)), state(std::move(state_in)), initial(state), body_ids_(scene.freeBodyCount()) {}

Simulation::Simulation(Scene scene_in, SceneState state_in)
    : scene(std::move(scene_in)),
      state(std::move(state_in.bodies)),
      initial(state),
      robots(std::move(state_in.robots)),
      initial_robots(robots),
      body_ids_(scene.freeBodyCount()),
      robot_ids_(robots.size()) {}

void Simulation::step(const Loads& loads, const std::vector<ArticulationLoads>& robot_loads) {
  detail::WorldState now{state, robots};
  detail::WorldWorkspace memory{workspace.bodies, workspace.robots, workspace.robot_diverged, workspace.scratch.get()};
  detail::stepWorld(detail::World(scene), now, detail::WorldLoads{loads, robot_loads}, memory);
}

EntityId Simulation::addBody(const PreparedBody& body, const BodyState& start) {
  const int i = static_cast<int>(scene.freeBodyCount());  // before the robots' links
  scene.addBody(body);                                    // in place, unchanged if it throws
  insertBody(state, i, start);
  insertBody(initial, i, start);
  contacts.insertBody(i);
  schedule.insertBody(i);
  workspace.bodies = workspace.bodies.forEditedModel();  // its caches assumed the old model
  return body_ids_.insert(static_cast<std::size_t>(i));
}

EntityId Simulation::addRobot(Scene::RobotSpec robot, const ArticulationState& start) {
  scene.addRobot(std::move(robot));  // unchanged if it throws
  const std::size_t r = scene.robots().size() - 1;
  robots.push_back(start);
  initial_robots.push_back(start);
  state.bodies.resize(model().bodyCount());
  initial.bodies.resize(model().bodyCount());
  core::placeRobot(scene, r, start, state);
  core::placeRobot(scene, r, start, initial);
  workspace.bodies = workspace.bodies.forEditedModel();
  return robot_ids_.insert(r);
}

EntityId Simulation::bodyId(int i) const {
  if (i < 0) throw std::out_of_range("body " + std::to_string(i) + ": no free body");
  return body_ids_.at(static_cast<std::size_t>(i));
}

std::optional<int> Simulation::bodyIndex(EntityId id) const {
  const std::optional<std::size_t> i = body_ids_.find(id);
  if (!i) return std::nullopt;
  return static_cast<int>(*i);
}

std::size_t Simulation::removeBody(int i) {
  if (i < 0 || static_cast<std::size_t>(i) >= scene.freeBodyCount()) {
    throw std::invalid_argument("body " + std::to_string(i) + ": no free body (" +
                                std::to_string(scene.freeBodyCount()) + " in the world)");
  }
  core::removeBody(scene.model(), state, i);    // wakes what may touch it
  core::removeBody(scene.model(), initial, i);  // reads the model with body i still in it
  scene.removeBody(static_cast<std::size_t>(i));
  contacts.removeBody(i);
  workspace.bodies = workspace.bodies.forEditedModel();
  body_ids_.erase(static_cast<std::size_t>(i));
  return schedule.removeBody(i);
}

void Simulation::removeRobot(std::size_t r) {
  if (r >= robots.size()) {
    throw std::invalid_argument("robot " + std::to_string(r) + ": no robot (" + std::to_string(robots.size()) +
                                " in the world)");
  }
  const int first = scene.robots()[r].first_body;
  const int count = static_cast<int>(scene.robots()[r].link.size());
  removeBodies(scene.model(), state, first, count);  // wakes what may touch a link
  removeBodies(scene.model(), initial, first, count);
  scene.removeRobot(r);
  for (int i = first + count - 1; i >= first; --i) {
    contacts.removeBody(i);
    schedule.removeBody(i);
  }
  robots.erase(robots.begin() + static_cast<std::ptrdiff_t>(r));
  initial_robots.erase(initial_robots.begin() + static_cast<std::ptrdiff_t>(r));
  joint_efforts.removeRobot(r);
  robot_ids_.erase(r);
  // A sleeping robot sleeps as its links do: one of them woken wakes it.
  for (std::size_t s = 0; s < robots.size(); ++s) {
    const SceneRobot& robot = scene.robots()[s];
    for (std::size_t k = 0; k < robot.link.size(); ++k) {
      if (robots[s].asleep && !state.bodies[robot.first_body + k].asleep) {
        robots[s].asleep = false;
        robots[s].still_time = 0.0;
      }
    }
  }
  if (workspace.robots.size() > r) workspace.robots.erase(workspace.robots.begin() + static_cast<std::ptrdiff_t>(r));
  if (workspace.robot_diverged.size() > r) {
    workspace.robot_diverged.erase(workspace.robot_diverged.begin() + static_cast<std::ptrdiff_t>(r));
  }
  workspace.bodies = workspace.bodies.forEditedModel();
}

void Simulation::place(int i, const BodyState& now) {
  state.bodies.at(static_cast<std::size_t>(i)) = now;
  state.bodies[i].asleep = false;
  state.bodies[i].still_time = 0.0;
  state.contact_impulses.clear();
}

void Simulation::placeRobot(std::size_t r, const ArticulationState& now) {
  ArticulationState& robot = robots.at(r);
  robot = now;
  robot.asleep = false;
  robot.still_time = 0.0;
  robot.carried = {};
  core::placeRobot(scene, r, robot, state);
  state.contact_impulses.clear();
}

void Simulation::retune(const Tuning& tuning) {
  scene.retune(tuning);
  workspace.bodies = workspace.bodies.forEditedModel();  // the fixed-point cache assumed the old settings
  wakeAll(state);
  for (ArticulationState& robot : robots) {
    robot.asleep = false;
    robot.still_time = 0.0;
  }
}

void Simulation::reset(double time) {
  state = initial;
  state.time = time;
  robots = initial_robots;
  schedule.clear(-1);
  joint_efforts.clearAll();
}

}  // namespace rigid_body_sim::core
