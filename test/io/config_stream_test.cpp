// A config file read with its bodies list an entry at a time (rbsim's way,
// io::parseConfigText): the same config, or the same refusal, as parsing the
// whole tree.
#include <gtest/gtest.h>

#include <fstream>
#include <optional>
#include <sstream>

#include "../test_util.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::test {
namespace {

/// The config, or the refusal's message.
struct Outcome {
  std::optional<io::SimConfig> config;
  std::string error;
};

template <class Parse>
Outcome outcome(const Parse& parse) {
  try {
    return {parse(), ""};
  } catch (const io::ConfigError& e) {
    return {std::nullopt, e.what()};
  }
}

void expectSameBody(const io::BodyEntry& a, const io::BodyEntry& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.urdf, b.urdf);
  EXPECT_EQ(a.initial.p_WL, b.initial.p_WL);
  EXPECT_EQ(a.initial.q_WL.coeffs(), b.initial.q_WL.coeffs());
  EXPECT_EQ(a.initial.v_WL, b.initial.v_WL);
  EXPECT_EQ(a.initial.w_W, b.initial.w_W);
  EXPECT_EQ(a.friction, b.friction);
  EXPECT_EQ(a.restitution, b.restitution);
  EXPECT_EQ(a.imu.has_value(), b.imu.has_value());
  if (a.imu && b.imu) {
    EXPECT_EQ(a.imu->settings.rate, b.imu->settings.rate);
  }
  EXPECT_EQ(a.cmd_vel.has_value(), b.cmd_vel.has_value());
  EXPECT_EQ(a.odom_noise.has_value(), b.odom_noise.has_value());
}

/// parseConfigText(yaml, overrides) against parseConfig of the whole tree with the overrides applied.
void expectSameAsTheTree(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  SCOPED_TRACE(yaml);
  const Outcome tree = outcome([&] {
    YAML::Node root = io::loadYamlText(yaml, "world.yaml");
    for (const std::string& s : overrides) io::applyOverride(root, s);
    return io::parseConfig(root, "/worlds");
  });
  const Outcome stream = outcome([&] { return io::parseConfigText(yaml, "world.yaml", overrides, "/worlds"); });
  ASSERT_EQ(tree.error, stream.error);
  if (!tree.config) return;
  const io::SimConfig &a = *tree.config, &b = *stream.config;
  EXPECT_EQ(a.bodies_listed, b.bodies_listed);
  EXPECT_EQ(a.model.dt, b.model.dt);
  EXPECT_EQ(a.model.gravity_W, b.model.gravity_W);
  EXPECT_EQ(a.model.contact.friction, b.model.contact.friction);
  EXPECT_EQ(a.model.contact.restitution, b.model.contact.restitution);
  EXPECT_EQ(a.model.scene.size(), b.model.scene.size());
  EXPECT_EQ(a.initial.p_WL, b.initial.p_WL);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) expectSameBody(a.bodies[i], b.bodies[i]);
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ConfigStream, TheShippedConfigsReadAsTheirTrees) {
  for (const char* file : {"world.yaml", "default.yaml"}) {
    expectSameAsTheTree(slurp(std::string(RBS_SOURCE_DIR) + "/config/" + file));
  }
  const io::SimConfig world =
      io::loadConfigFile(std::string(RBS_SOURCE_DIR) + "/config/world.yaml", {}, std::string(RBS_SOURCE_DIR));
  ASSERT_EQ(world.bodies.size(), 4u);
  EXPECT_EQ(world.bodies[1].name, "ball");
  EXPECT_EQ(world.bodies[3].initial.p_WL, Vec3(0.6, -0.4, 0.5));
}

TEST(ConfigStream, BodiesAnywhereInTheFileAndEveryKeyOfAnEntry) {
  expectSameAsTheTree(R"(
bodies:
  - name: a
    urdf: box.urdf
    initial: {position: [0, 0, 1], rpy: [0, 0, 1.5707963267948966], angular_velocity: [0, 1, 0]}
    contact: {friction: 0.2, restitution: 0.7}
    imu: {rate: 100}
    odom_noise: {seed: 3}
    cmd_vel: {max_linear_speed: 1}
  - {name: b, urdf: /abs/ball.urdf}
  - {name: c, urdf: package://rigid_body_sim/urdf/bunny.urdf, initial: {linear_velocity: [1, 0, 0]}}
dt: 0.02
contact: {friction: 0.9}
scene: []
)");
  expectSameAsTheTree("dt: 0.002\ngravity: [0, 0, -1]\nbodies: [{name: a, urdf: a.urdf}, {name: b, urdf: b.urdf}]");
  expectSameAsTheTree("bodies: []");
  expectSameAsTheTree("");
  expectSameAsTheTree("# nothing but a comment\n");
  expectSameAsTheTree("dt: 0.001");
  expectSameAsTheTree("scene: [{type: box, size: [1, 1, 1], bodies: 2}]");  // a 'bodies' not at the root
}

TEST(ConfigStream, RefusalsAreTheTreesWordForWord) {
  expectSameAsTheTree("bodies: {a: 1}");
  expectSameAsTheTree("bodies: 3");
  expectSameAsTheTree("bodies:\n  - {name: a, urdf: x}\n  - {name: a, urdf: y}");  // a repeated name
  expectSameAsTheTree("bodies: [{name: a}]");
  expectSameAsTheTree("bodies: [{name: a, urdf: x, initial: {position: [0, 0, fast]}}]");
  expectSameAsTheTree("bodies: [{name: a, urdf: x, grip: 1}]");
  expectSameAsTheTree("bodies: [{name: a, urdf: x, imu: {rate: 5000}}]\ndt: 0.001");  // checked against dt
  expectSameAsTheTree("bodies: [{name: a, urdf: x}]\ninitial: {position: [0, 0, 1]}");
  expectSameAsTheTree("bodies: [{name: a, urdf: x}]\ndampign: 1");
  expectSameAsTheTree("bodies: [[1, 2]]");
  expectSameAsTheTree("bodies: [{name: a, urdf: x}");  // not valid YAML
  expectSameAsTheTree("bodies: [&a {name: a, urdf: x}, *a]");
  expectSameAsTheTree("- 1\n- 2");
  // The root's keys are checked before the bodies, however the file orders them.
  expectSameAsTheTree("bodies: [{name: a, urdf: x, grip: 1}]\ndampign: 1");
  expectSameAsTheTree("bodies: [{name: a, urdf: x, grip: 1}]\ninitial: {position: [0, 0, 1]}");
  // A repeated key: a look-up finds the first.
  expectSameAsTheTree("bodies: {a: 1}\nbodies: [{name: a, urdf: x}]");
  expectSameAsTheTree("bodies: [{name: a, urdf: x}]\nbodies: [{name: b, urdf: y}]");
}

TEST(ConfigStream, OverridesApplyAndMayReplaceTheBodiesList) {
  const std::string yaml = "bodies: [{name: a, urdf: a.urdf}, {name: b, urdf: b.urdf}]";
  expectSameAsTheTree(yaml, {"dt=0.01", "contact.friction=0.3"});
  expectSameAsTheTree(yaml, {"bodies=[{name: z, urdf: z.urdf}]"});
  expectSameAsTheTree(yaml, {"bodies=[]"});
  expectSameAsTheTree(yaml, {"bodies=7"});
  expectSameAsTheTree("dt: 0.001", {"bodies=[{name: z, urdf: z.urdf}]"});
  const io::SimConfig c = io::parseConfigText(yaml, "world.yaml", {"bodies=[{name: z, urdf: z.urdf}]"});
  ASSERT_EQ(c.bodies.size(), 1u);
  EXPECT_EQ(c.bodies[0].name, "z");
}

}  // namespace
}  // namespace rigid_body_sim::test
