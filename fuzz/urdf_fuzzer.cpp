// libFuzzer: any bytes as a URDF document, then the model of the body; and
// the same bytes as a robot (the articulation loader: refused or a model
// checkArticulation accepts; stepping it joins once the guard covers
// articulations).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_model.h"
#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    const rigid_body_sim::core::ArticulationModel robot = rigid_body_sim::io::loadArticulationString(xml, "fuzz.urdf");
    if (robot.links.empty()) std::abort();  // a model always has its base
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
