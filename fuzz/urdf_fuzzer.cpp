// libFuzzer: any bytes as a URDF document, then the model of the body and
// a few steps; and the same bytes as a robot (the articulation loader:
// refused, or a model that a few steps on the ground leave finite, the guard
// undoing any step that would not).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "fuzz_model.h"
#include "rigid_body_sim/core/articulation_step.h"
#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    const rigid_body_sim::core::ArticulationModel robot = rigid_body_sim::io::loadArticulationString(xml, "fuzz.urdf");
    rigid_body_sim::core::ArticulationState state = rigid_body_sim::core::restState(robot);
    // Its links on the ground, where they can be bodies (a link's mass may
    // be outside a body's range: then it steps without contacts).
    std::unique_ptr<rigid_body_sim::core::ArticulationColliders> colliders;
    try {
      rigid_body_sim::core::ModelSpec ground;
      ground.scene = {rigid_body_sim::core::Sdf::plane(rigid_body_sim::core::Vec3::UnitZ())};
      colliders = std::make_unique<rigid_body_sim::core::ArticulationColliders>(
          rigid_body_sim::core::articulationColliders(robot, ground));
    } catch (const std::invalid_argument&) {
    }
    rigid_body_sim::core::ArticulationWorkspace ws;
    for (int n = 0; n < 5; ++n) {
      rigid_body_sim::core::stepArticulation(robot, state, {}, rigid_body_sim::core::Vec3(0, 0, -9.81), 1e-3, {}, &ws,
                                             colliders.get());
    }
    if (!state.q.allFinite() || !state.v.allFinite() || !state.V_B.allFinite() || !state.X_WB.translation.allFinite()) {
      std::abort();  // the guard must never let this through
    }
  } catch (const rigid_body_sim::io::UrdfError&) {
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
