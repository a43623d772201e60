// libFuzzer: any bytes as a YAML config, then the model of a box under it.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_model.h"
#include "rigid_body_sim/io/config.h"

namespace {

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
