// The config's scene (scene_config.cpp), a mesh above all (issue 14): a box
// slides down meshes/ramp.obj as down the same ramp made of a box shape,
// and as the closed form says; bad mesh items are refused naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../test_util.h"
#include "rigid_body_sim/core/step/step.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::test {
namespace {

const double kSlope = 20.0 * M_PI / 180.0;  // meshes/ramp.obj rises at 20° along +x
const Vec3 kHalf(0.2, 0.1, 0.05);           // the sliding box (1 kg)
const double kFriction = 0.2;

io::SimConfig parse(const std::string& yaml) {
  return io::parseConfig(io::loadYamlText(yaml, "test"), std::string(RBS_SOURCE_DIR) + "/config");
}

/// How far the box slides down the slope in `seconds`, from rest with its
/// centre above the slope's point at x = 1.6 m.
double slideDown(const io::SimConfig& config, double seconds) {
  core::ModelSpec ms = config.model;
  ms.bodies = {boxBody(kHalf)};
  ms.sleep.enabled = false;
  ms.contact.friction = kFriction;
  const core::Model model(ms);
  const Vec3 along(std::cos(kSlope), 0.0, std::sin(kSlope)), normal(-std::sin(kSlope), 0.0, std::cos(kSlope));
  core::LinkState link;
  link.p_WL = 1.6 / std::cos(kSlope) * along + kHalf.z() * normal;
  link.q_WL = Quat(Eigen::AngleAxisd(-kSlope, Vec3::UnitY()));
  core::State s;
  s.bodies = {core::bodyStateFromLink(model.body(0), link)};
  const Vec3 start = s.bodies[0].p_WB;
  const int steps = static_cast<int>(std::lround(seconds / model.dt()));
  for (int n = 0; n < steps; ++n) core::step(model, s);
  return -(s.bodies[0].p_WB - start).dot(along);
}

TEST(SceneMesh, ABoxSlidesDownAMeshRampAsDownTheSameRampOfABox) {
  const io::SimConfig mesh = parse("scene: [{type: mesh, file: ../meshes/ramp.obj}]");
  ASSERT_EQ(mesh.model.scene.size(), 1u);
  EXPECT_EQ(mesh.model.scene[0].kind(), core::Sdf::Kind::kGrid);
  // The same slope as a box 4 m long, 0.5 m thick, turned by the slope, its
  // top face through the ramp's foot.
  const double c = std::cos(kSlope), s = std::sin(kSlope);
  const Vec3 centre = 1.5 * Vec3(1.0, 0.0, s / c) - 0.25 * Vec3(-s, 0.0, c);
  const io::SimConfig box =
      parse("scene: [{type: box, size: [4, 2, 0.5], rpy: [0, " + std::to_string(-kSlope) + ", 0], position: [" +
            std::to_string(centre.x()) + ", 0, " + std::to_string(centre.z()) + "]}]");
  const double t = 0.5;
  const double on_mesh = slideDown(mesh, t), on_box = slideDown(box, t);
  const double closed_form = 0.5 * 9.81 * (s - kFriction * c) * t * t;  // a = g (sin θ − μ cos θ)
  EXPECT_NEAR(on_mesh, on_box, 0.01 * on_box);
  EXPECT_NEAR(on_box, closed_form, 0.01 * closed_form);
}

TEST(SceneMesh, BadMeshItemsAreRefusedNamingTheKey) {
  const auto refused = [](const std::string& yaml, std::initializer_list<std::string> parts) {
    expectThrowsWith<io::ConfigError>([&] { parse(yaml); }, parts);
  };
  refused("scene: [{type: mesh}]", {"'scene[0].file'", "a mesh needs file"});
  refused("scene: [{type: mesh, file: ../meshes/none.obj}]", {"'scene[0].file'", "none.obj"});
  refused("scene: [{type: mesh, file: ../meshes/ramp.obj, scale: 0}]", {"'scene[0].scale'", "> 0"});
  refused("scene: [{type: mesh, file: ../meshes/ramp.obj, scale: [1, -1, 1]}]", {"'scene[0].scale'", "> 0"});
  refused("scene: [{type: mesh, file: ../meshes/ramp.obj, resolution: 2.5}]", {"'scene[0].resolution'", "[8, 256]"});
  refused("scene: [{type: mesh, file: ../meshes/ramp.obj, scale: 1e6}]", {"'scene[0].file'", "at most 1000 m"});
  refused("scene: [{type: mesh, file: ../meshes/ramp.obj, colour: red}]", {"'scene[0].colour'", "unknown key"});
}

}  // namespace
}  // namespace rigid_body_sim::test
