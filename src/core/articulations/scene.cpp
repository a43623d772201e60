// A scene of free bodies and robots: docs/physics.md §11.9.
#include "rigid_body_sim/core/articulations/scene.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "joint_rows.h"
#include "rigid_body_sim/core/articulations/articulation_contacts.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"

namespace rigid_body_sim::core {

namespace {

/// Robot `r`'s links as bodies (`bodies`), in collision group `group` (−1:
/// none), named ROBOT/LINK; the robot itself, its links from `first_body` on.
SceneRobot robotLinks(Scene::RobotSpec& r, int group, int first_body, std::vector<BodySpec>& bodies) {
  LinkBodies links = linkBodies(r.model, group);
  for (BodySpec& b : links.bodies) {
    b.name = r.name + "/" + b.name;            // two robots of one URDF have links of one name
    if (!b.friction) b.friction = r.friction;  // a link's own surface first (linkBodies)
    b.restitution = r.restitution;
  }
  SceneRobot robot;
  robot.name = std::move(r.name);
  robot.model = std::move(r.model);
  robot.first_body = first_body;
  robot.link = std::move(links.link);
  bodies = std::move(links.bodies);
  return robot;
}

/// `spec` with every robot's links appended as bodies; `robots` gets where.
ModelSpec withLinks(const ModelSpec& spec, std::vector<Scene::RobotSpec>& specs, std::vector<SceneRobot>& robots) {
  ModelSpec all = spec;
  // A robot's links are a collision group of their own unless self-collision
  // is on; the groups come after any the free bodies have.
  int group = 0;
  for (const BodySpec& b : spec.bodies) group = std::max(group, b.collision_group + 1);
  for (Scene::RobotSpec& r : specs) {
    std::vector<BodySpec> links;
    robots.push_back(
        robotLinks(r, spec.contact.self_collision ? -1 : group++, static_cast<int>(all.bodies.size()), links));
    all.bodies.insert(all.bodies.end(), links.begin(), links.end());
  }
  return all;
}

void placeLinks(const Scene& scene, std::size_t r, const ArticulationKinematics& kin, State& state) {
  const SceneRobot& robot = scene.robots()[r];
  detail::setLinkStates(scene.model(), robot.link, kin, static_cast<std::size_t>(robot.first_body), state.bodies);
}

}  // namespace

Scene::Scene(const ModelSpec& spec, std::vector<RobotSpec> robots)
    : model_(withLinks(spec, robots, robots_)), free_bodies_(spec.bodies.size()) {
  if (!robots_.empty() && model_.contact().method != ContactMethod::kImpulse) {
    throw std::invalid_argument(
        "contact.method: a scene with robots takes the impulse method (robots' contacts are rows of its solve)");
  }
  robot_of_.assign(model_.bodyCount(), -1);
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    const SceneRobot& robot = robots_[r];
    std::fill_n(robot_of_.begin() + robot.first_body, robot.link.size(), static_cast<int>(r));
  }
}

Scene::Scene(Model model) : model_(std::move(model)), free_bodies_(model_.bodyCount()) {
  robot_of_.assign(model_.bodyCount(), -1);
}

void Scene::addBody(const PreparedBody& body) {
  model_.insertBody(free_bodies_, body);
  robot_of_.insert(robot_of_.begin() + static_cast<std::ptrdiff_t>(free_bodies_), -1);
  ++free_bodies_;
  for (SceneRobot& robot : robots_) ++robot.first_body;
}

void Scene::addRobot(RobotSpec spec) {
  for (const SceneRobot& robot : robots_) {
    if (robot.name == spec.name) throw std::invalid_argument("robot '" + spec.name + "': another robot has this name");
  }
  if (model_.contact().method != ContactMethod::kImpulse) {
    throw std::invalid_argument(
        "contact.method: a scene with robots takes the impulse method (robots' contacts are rows of its solve)");
  }
  int group = 0;  // after every group in use, as the constructor numbers them
  for (const BodyModel& b : model_.bodies()) group = std::max(group, b.collision_group + 1);
  std::vector<BodySpec> links;
  SceneRobot robot =
      robotLinks(spec, model_.contact().self_collision ? -1 : group, static_cast<int>(model_.bodyCount()), links);
  Model next = model_;  // the bodies' grids are shared, not copied; unchanged if a link throws
  const BodyBuilder builder = next.bodyBuilder();
  for (const BodySpec& b : links) next.addBody(builder.build(b));
  model_ = std::move(next);
  robot_of_.resize(model_.bodyCount(), static_cast<int>(robots_.size()));
  robots_.push_back(std::move(robot));
}

void Scene::removeBody(std::size_t i) {
  if (i >= free_bodies_) {
    throw std::invalid_argument("body " + std::to_string(i) + ": no free body (" + std::to_string(free_bodies_) +
                                " in the scene)");
  }
  model_.removeBody(i);
  --free_bodies_;
  robot_of_.erase(robot_of_.begin() + static_cast<std::ptrdiff_t>(i));
  for (SceneRobot& robot : robots_) --robot.first_body;
}

void Scene::removeRobot(std::size_t r) {
  if (r >= robots_.size()) {
    throw std::invalid_argument("robot " + std::to_string(r) + ": no such robot (" + std::to_string(robots_.size()) +
                                " in the scene)");
  }
  const auto first = static_cast<std::ptrdiff_t>(robots_[r].first_body);
  const auto count = static_cast<std::ptrdiff_t>(robots_[r].link.size());
  for (std::ptrdiff_t k = count - 1; k >= 0; --k) model_.removeBody(static_cast<std::size_t>(first + k));
  robot_of_.erase(robot_of_.begin() + first, robot_of_.begin() + first + count);
  for (int& owner : robot_of_) {
    if (owner > static_cast<int>(r)) --owner;
  }
  for (std::size_t s = r + 1; s < robots_.size(); ++s) robots_[s].first_body -= static_cast<int>(count);
  robots_.erase(robots_.begin() + static_cast<std::ptrdiff_t>(r));
}

void placeRobot(const Scene& scene, std::size_t r, const ArticulationState& now, State& bodies) {
  ArticulationKinematics kin;
  kinematics(scene.robots().at(r).model, now, kin);
  placeLinks(scene, r, kin, bodies);
}

SceneState sceneState(const Scene& scene, const State& bodies, const std::vector<ArticulationState>& robots) {
  SceneState s;
  s.bodies = bodies;
  s.bodies.bodies.resize(scene.model().bodyCount());
  s.robots = robots;
  ArticulationKinematics kin;
  for (std::size_t r = 0; r < robots.size(); ++r) {
    kinematics(scene.robots()[r].model, robots[r], kin);
    placeLinks(scene, r, kin, s.bodies);
  }
  return s;
}

}  // namespace rigid_body_sim::core
