// Config parsing: the shipped defaults, overrides, and refusals that name the key.
#include "rigid_body_sim/io/config.h"

#include <gtest/gtest.h>

#include "../test_util.h"

namespace rigid_body_sim::test {
namespace {

io::SimConfig parse(const std::string& yaml) { return io::parseConfig(YAML::Load(yaml)); }

void expectRefused(const std::string& yaml, std::initializer_list<std::string> parts) {
  expectThrowsWith<io::ConfigError>([&] { parse(yaml); }, parts);
}

TEST(Config, ShippedDefaultsAreTheCodeDefaults) {
  const io::SimConfig file = io::parseConfig(io::loadYamlFile(std::string(RBS_SOURCE_DIR) + "/config/default.yaml"));
  const io::SimConfig code = parse("");
  EXPECT_EQ(file.model.dt, code.model.dt);
  EXPECT_EQ(file.model.gravity_W, code.model.gravity_W);
  EXPECT_EQ(file.model.gyroscopic, code.model.gyroscopic);
  EXPECT_EQ(file.model.damping.linear_rate, code.model.damping.linear_rate);
  EXPECT_EQ(file.model.damping.angular_rate, code.model.damping.angular_rate);
  EXPECT_EQ(file.model.damping.linear_drag, code.model.damping.linear_drag);
  EXPECT_EQ(file.model.damping.angular_drag, code.model.damping.angular_drag);
  EXPECT_EQ(file.initial.p_WL, code.initial.p_WL);
  EXPECT_EQ(file.initial.q_WL.coeffs(), code.initial.q_WL.coeffs());
  EXPECT_EQ(file.initial.v_WL, code.initial.v_WL);
  EXPECT_EQ(file.initial.w_W, code.initial.w_W);
}

TEST(Config, ReadsEveryKey) {
  const io::SimConfig c = parse(R"(
dt: 0.002
gravity: [0, 0, -1.62]
gyroscopic: false
damping: {linear: 0.1, angular: 0.2, linear_drag: 0.3, angular_drag: 0.0004}
initial:
  position: [1, 2, 3]
  quaternion: [0, 0, 1, 0]
  linear_velocity: [4, 5, 6]
  angular_velocity: [0.01, 3, 0.01]
)");
  EXPECT_EQ(c.model.dt, 0.002);
  EXPECT_EQ(c.model.gravity_W, Vec3(0, 0, -1.62));
  EXPECT_FALSE(c.model.gyroscopic);
  EXPECT_EQ(c.model.damping.linear_rate, 0.1);
  EXPECT_EQ(c.model.damping.angular_rate, 0.2);
  EXPECT_EQ(c.model.damping.linear_drag, 0.3);
  EXPECT_EQ(c.model.damping.angular_drag, 0.0004);
  EXPECT_EQ(c.initial.p_WL, Vec3(1, 2, 3));
  // [x, y, z, w] = [0, 0, 1, 0]: half a turn about z (not about x, Eigen's (w, x, y, z) order).
  EXPECT_LT((c.initial.q_WL * Vec3::UnitX() - Vec3(-1, 0, 0)).norm(), 1e-15);
  EXPECT_EQ(c.initial.q_WL.z(), 1.0);
  EXPECT_EQ(c.initial.v_WL, Vec3(4, 5, 6));
  EXPECT_EQ(c.initial.w_W, Vec3(0.01, 3, 0.01));
}

TEST(Config, RpyFollowsTheUrdfConvention) {
  // Fixed axes: roll about x first, then pitch about y, then yaw about z.
  const io::SimConfig c = parse("initial: {rpy: [1.5707963267948966, 0, 1.5707963267948966]}");
  EXPECT_LT((c.initial.q_WL * Vec3::UnitY() - Vec3(0, 0, 1)).norm(), 1e-15);   // roll: y → z, yaw keeps z
  EXPECT_LT((c.initial.q_WL * Vec3::UnitX() - Vec3(0, 1, 0)).norm(), 1e-15);   // yaw: x → y
}

TEST(Config, OverridesSetAnyKeyWithAYamlValue) {
  YAML::Node tree = YAML::Load("dt: 0.001\ninitial: {position: [0, 0, 1]}");
  io::applyOverride(tree, "gravity=[0,0,0]");
  io::applyOverride(tree, "initial.angular_velocity=[0.01,3,0.01]");
  io::applyOverride(tree, "damping.linear=0.5");  // creates the map
  io::applyOverride(tree, "gyroscopic=false");
  io::applyOverride(tree, "dt=0.01");
  const io::SimConfig c = io::parseConfig(tree);
  EXPECT_EQ(c.model.gravity_W, Vec3::Zero());
  EXPECT_EQ(c.initial.w_W, Vec3(0.01, 3, 0.01));
  EXPECT_EQ(c.initial.p_WL, Vec3(0, 0, 1));  // untouched sibling
  EXPECT_EQ(c.model.damping.linear_rate, 0.5);
  EXPECT_FALSE(c.model.gyroscopic);
  EXPECT_EQ(c.model.dt, 0.01);
  YAML::Node empty;
  io::applyOverride(empty, "initial.position=[1,2,3]");
  EXPECT_EQ(io::parseConfig(empty).initial.p_WL, Vec3(1, 2, 3));
}

TEST(Config, BadOverridesAreRefused) {
  YAML::Node tree = YAML::Load("dt: 0.001");
  expectThrowsWith<io::ConfigError>([&] { io::applyOverride(tree, "gravity"); }, {"--set 'gravity'", "KEY=VALUE"});
  expectThrowsWith<io::ConfigError>([&] { io::applyOverride(tree, "dt.x=1"); }, {"'dt.x'", "not a map"});
  expectThrowsWith<io::ConfigError>([&] { io::applyOverride(tree, "gravity=[0,0"); }, {"not YAML"});
}

TEST(Config, RefusalsNameTheKeyAndTheValue) {
  expectRefused("dampign: {linear: 1}", {"config key 'dampign'", "unknown key"});
  expectRefused("damping: {lineer: 1}", {"'damping.lineer'", "unknown key", "linear_drag"});
  expectRefused("dt: fast", {"'dt'", "expected a number, got fast"});
  expectRefused("dt: .nan", {"'dt'", "finite"});
  expectRefused("gravity: [0, 0]", {"'gravity'", "expected [x, y, z], got [0, 0]"});
  expectRefused("gravity: [0, 0, x]", {"'gravity[2]'", "got x"});
  expectRefused("gyroscopic: maybe", {"'gyroscopic'", "true or false"});
  expectRefused("initial: {rpy: [0, 0, 0], quaternion: [0, 0, 0, 1]}", {"not both"});
  expectRefused("initial: {quaternion: [0, 0, 0, 2]}", {"'initial.quaternion'", "norm 2"});
  expectRefused("initial: {quaternion: [0, 0, 1]}", {"[x, y, z, w]"});
  expectRefused("[1, 2]", {"expected a map"});
}

TEST(Config, ModelValidationNamesTheField) {
  const io::SimConfig c = parse("dt: -0.001");
  expectThrowsWith<std::invalid_argument>([&] { io::buildModel(c, issueBox()); }, {"dt = -0.001", "> 0 s"});
}

}  // namespace
}  // namespace rigid_body_sim::test
