// libFuzzer: any bytes as a YAML config, then the model of a box under it,
// and a wheeled robot loaded under it as the node loads one: its config's
// lidars, depth cameras and controllers (seeds sensors.yaml, devices.yaml)
// refused, or sound (fuzz::checkDevices).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_model.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/scene_loader.h"

namespace {

/// A base on two wheels (joints left_wheel_joint, right_wheel_joint) with a
/// laser_link fixed to it: what the config's devices and controllers go on.
constexpr const char* kRobot =
    "<robot name='rover'><link name='base_link'><inertial><mass value='5'/><inertia ixx='0.1' iyy='0.1' izz='0.1' "
    "ixy='0' ixz='0' iyz='0'/></inertial><collision><geometry><box size='0.4 0.3 0.1'/></geometry></collision></link>"
    "<joint name='left_wheel_joint' type='continuous'><parent link='base_link'/><child link='left_wheel'/>"
    "<origin xyz='0 0.2 0'/><axis xyz='0 1 0'/></joint><link name='left_wheel'><inertial><mass value='1'/>"
    "<inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial><collision><geometry>"
    "<cylinder radius='0.06' length='0.03'/></geometry></collision></link>"
    "<joint name='right_wheel_joint' type='continuous'><parent link='base_link'/><child link='right_wheel'/>"
    "<origin xyz='0 -0.2 0'/><axis xyz='0 1 0'/></joint><link name='right_wheel'><inertial><mass value='1'/>"
    "<inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial><collision><geometry>"
    "<cylinder radius='0.06' length='0.03'/></geometry></collision></link>"
    "<joint name='laser_mount' type='fixed'><parent link='base_link'/><child link='laser_link'/>"
    "<origin xyz='0.1 0 0.2'/></joint><link name='laser_link'/></robot>";

rigid_body_sim::core::BodySpec box() {
  rigid_body_sim::core::BodySpec b;
  b.name = "box";
  b.I_C_L = rigid_body_sim::core::Vec3(0.0042, 0.0142, 0.0167).asDiagonal();
  rigid_body_sim::core::CollisionShape shape;
  shape.size = rigid_body_sim::core::Vec3(0.4, 0.2, 0.1);
  b.collision = {shape};
  return b;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rigid_body_sim;
  const std::string text(reinterpret_cast<const char*>(data), size);
  io::SimConfig config;
  std::string refused;
  try {
    config = io::parseConfig(io::loadYamlText(text, "fuzz.yaml"));
  } catch (const io::ConfigError& e) {
    refused = e.what();
  }
  // rbsim's way, the bodies list an entry at a time: the same refusal, or the same bodies.
  try {
    const io::SimConfig streamed = io::parseConfigText(text, "fuzz.yaml");
    if (!refused.empty() || streamed.bodies.size() != config.bodies.size()) std::abort();
    for (std::size_t i = 0; i < config.bodies.size(); ++i) {
      if (streamed.bodies[i].name != config.bodies[i].name) std::abort();
    }
  } catch (const io::ConfigError& e) {
    if (refused != e.what()) std::abort();
  }
  if (!refused.empty()) return 0;
  if (!config.bodies_listed) {
    try {
      fuzz::checkDevices(io::loadScene(config,
                                       [] {
                                         return io::UrdfText{kRobot, "rover.urdf", ""};
                                       }),
                         config.device_memory);
    } catch (const std::exception&) {  // a refusal names what it refused
    }
  }
  core::ModelSpec spec = config.model;
  spec.bodies = {box()};
  try {
    const core::Model model(spec);
    core::State start;
    start.bodies = {core::bodyStateFromLink(model.body(0), config.initial)};
    if (!start.bodies[0].p_WB.allFinite()) return 0;
    fuzz::stepAFew(spec, &start);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
