// libFuzzer: any bytes as a mesh file (the first byte picks the format),
// then the model of a body made of it, in a world (its distance grid).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_model.h"
#include "rigid_body_sim/io/mesh_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rigid_body_sim;
  if (size < 1) return 0;
  static const char* const kFormats[] = {"obj", "stl", "dae", "ply", "off"};
  const std::string format = kFormats[data[0] % 5];
  const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  core::CollisionShape shape;
  shape.kind = core::CollisionShape::Kind::kPoints;
  shape.name = "fuzz." + format;
  try {
    shape.mesh = io::loadMeshBytes(bytes, format, core::Vec3::Ones());
  } catch (const io::MeshError&) {
    return 0;
  }
  core::ModelSpec spec;
  core::BodySpec mesh;
  mesh.name = "mesh";
  mesh.I_C_L = 0.01 * core::Mat3::Identity();
  mesh.collision = {shape};
  core::BodySpec ball = mesh;
  ball.name = "ball";
  ball.collision = {core::CollisionShape{core::CollisionShape::Kind::kSphere, {}, core::Vec3::Zero(), 0.1}};
  spec.bodies = {mesh, ball};
  spec.scene = {core::Sdf::plane(core::Vec3::UnitZ())};
  fuzz::stepAFew(spec);
  return 0;
}
