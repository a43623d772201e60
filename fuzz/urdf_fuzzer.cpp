// libFuzzer: any bytes as a URDF document (read as the default reads it,
// repairing what the descriptions users have break: physics §2.1; seed
// repaired_robot.urdf holds every class), then the model of the body and
// a few steps; and the same bytes as a robot (the articulation loader:
// refused, or a model that a few steps on the ground, alone and in a scene
// with a box, leave finite, the guards undoing any step that would not);
// and as the node loads a robot, its Gazebo markup's sensors and drives
// with it (seeds gazebo_*.urdf, many_sensors.urdf): refused, or devices
// fuzz::checkDevices finds sound.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz_model.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"

namespace {

/// The robot in a scene on the ground, alone or with a box where its base
/// is (so that its links and the box may press into each other): a few
/// steps leave everything finite. A link a body could not be (a mass or
/// inertia outside a body's range) refuses the scene: then the robot steps
/// alone without its collision shapes.
void stepped(const rigid_body_sim::core::ArticulationModel& robot, bool with_box) {
  namespace core = rigid_body_sim::core;
  core::ModelSpec spec;
  spec.scene = {core::Sdf::plane(core::Vec3::UnitZ())};
  if (with_box) {
    core::BodySpec box;
    box.name = "fuzz_box";
    core::CollisionShape shape;
    shape.kind = core::CollisionShape::Kind::kBox;
    shape.size = core::Vec3(0.2, 0.2, 0.2);
    box.collision = {shape};
    box.I_C_L = core::Mat3::Identity() * (1.0 / 150.0);
    spec.bodies = {box};
  }
  std::unique_ptr<core::Scene> scene;
  try {
    scene = std::make_unique<core::Scene>(spec, std::vector<core::Scene::RobotSpec>{{"robot", robot}});
  } catch (const std::invalid_argument&) {
    if (with_box) return;
    core::ArticulationModel bare = robot;
    for (core::ArticulatedLink& link : bare.links) link.collision.clear();
    scene = std::make_unique<core::Scene>(spec, std::vector<core::Scene::RobotSpec>{{"robot", bare}});
  }
  core::State free;
  free.bodies.resize(spec.bodies.size());
  if (with_box) free.bodies[0].p_WB = core::Vec3(0.0, 0.0, 0.1);
  core::SceneState state = core::sceneState(*scene, free, {core::restState(robot)});
  core::SceneWorkspace ws;
  for (int n = 0; n < 5; ++n) core::stepScene(*scene, state, {}, ws);
  const core::ArticulationState& r = state.robots[0];
  if (!r.q.allFinite() || !r.v.allFinite() || !r.V_B.allFinite() || !r.X_WB.translation.allFinite()) std::abort();
  for (const core::BodyState& b : state.bodies.bodies) {
    if (!b.p_WB.allFinite() || !b.v_WB.allFinite() || !b.w_B.allFinite()) {
      std::abort();  // the guards must never let this through
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    const rigid_body_sim::core::ArticulationModel robot = rigid_body_sim::io::loadArticulationString(xml, "fuzz.urdf");
    stepped(robot, false);
    stepped(robot, true);
  } catch (const rigid_body_sim::io::UrdfError&) {
  }
  try {
    const rigid_body_sim::io::SimConfig config;
    const rigid_body_sim::io::SceneSetup setup = rigid_body_sim::io::loadScene(config, [&] {
      return rigid_body_sim::io::UrdfText{xml, "fuzz.urdf", ""};
    });
    rigid_body_sim::fuzz::checkDevices(setup, config.device_memory);
  } catch (const std::exception&) {  // a refusal, whatever its kind, names what it refused
  }
  rigid_body_sim::core::ModelSpec spec;
  try {
    spec.bodies = {rigid_body_sim::io::loadUrdfString(xml, "fuzz.urdf")};
  } catch (const rigid_body_sim::io::UrdfError&) {
    return 0;
  }
  spec.scene = {rigid_body_sim::core::Sdf::plane(rigid_body_sim::core::Vec3::UnitZ())};
  rigid_body_sim::fuzz::stepAFew(spec);
  return 0;
}
