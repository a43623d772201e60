// A robot's joints at the start: the config keys initial.joint_positions and
// initial.joint_velocities, read in order and applied by name, mimics
// following; refusals name the key and the joint.
#include "rigid_body_sim/io/joint_start.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "../test_util.h"
#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/world.h"

namespace rigid_body_sim::test {
namespace {

/// An arm on the world: shoulder (revolute, ±1.5), elbow (continuous), a
/// slider (prismatic, [0, 0.2]) and a finger mimicking the elbow.
core::ArticulationModel arm() {
  const auto link = [](const std::string& name) {
    return "<link name='" + name +
           "'><inertial><mass value='1'/><inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' "
           "iyz='0'/></inertial></link>";
  };
  const auto joint = [](const std::string& name, const std::string& type, const std::string& parent,
                        const std::string& child, const std::string& inside) {
    return "<joint name='" + name + "' type='" + type + "'><parent link='" + parent + "'/><child link='" + child +
           "'/><origin xyz='0 0 0.3'/><axis xyz='0 1 0'/>" + inside + "</joint>";
  };
  const std::string limit = "<limit lower='-1.5' upper='1.5' effort='10' velocity='2'/>";
  return io::loadArticulationString(
      "<robot name='arm'><link name='world'/>" + joint("shoulder", "revolute", "world", "upper", limit) +
          link("upper") + joint("elbow", "continuous", "upper", "fore", "") + link("fore") +
          joint("slider", "prismatic", "fore", "tip", "<limit lower='0' upper='0.2' effort='10' velocity='1'/>") +
          link("tip") +
          joint("finger", "continuous", "fore", "claw", "<mimic joint='elbow' multiplier='-2' offset='0.1'/>") +
          link("claw") + "</robot>",
      "arm.urdf");
}

io::InitialJoints initialOf(const std::string& yaml) { return io::parseConfig(YAML::Load(yaml)).initial_joints; }

TEST(JointStart, ConfigKeysAreReadInOrderAndAppliedByName) {
  const io::InitialJoints initial = initialOf(R"(
initial:
  joint_positions: {elbow: 7.0, shoulder: -0.5, slider: 0.2}
  joint_velocities: {elbow: 3.0}
)");
  ASSERT_EQ(initial.positions.size(), 3u);
  EXPECT_EQ(initial.positions[0].first, "elbow");  // the file's order
  EXPECT_EQ(initial.positions[0].second, 7.0);
  const core::ArticulationModel model = arm();
  core::ArticulationState state = core::restState(model);
  io::startJoints(model, initial, {}, "initial", state);
  const auto at = [&](const std::string& joint) {
    for (std::size_t i = 1; i < model.links.size(); ++i) {
      if (model.links[i].joint == joint) return static_cast<int>(i) - 1;
    }
    ADD_FAILURE() << "no joint " << joint;
    return 0;
  };
  EXPECT_EQ(state.q(at("shoulder")), -0.5);
  EXPECT_EQ(state.q(at("elbow")), 7.0);  // a continuous joint is not wrapped
  EXPECT_EQ(state.v(at("elbow")), 3.0);
  EXPECT_EQ(state.q(at("slider")), 0.2);
  // The finger follows the elbow: −2 · 7 + 0.1, at −2 · 3 rad/s.
  EXPECT_DOUBLE_EQ(state.q(at("finger")), -13.9);
  EXPECT_DOUBLE_EQ(state.v(at("finger")), -6.0);
}

TEST(JointStart, RefusesNamingTheKeyAndTheJointAndChangesNothing) {
  const core::ArticulationModel model = arm();
  const auto refused = [&](const std::string& yaml, std::initializer_list<std::string> parts) {
    core::ArticulationState state = core::restState(model);
    const core::ArticulationState before = state;
    core::SpeedLimits limits;
    limits.max_angular_speed = 50.0;
    expectThrowsWith<io::ConfigError>([&] { io::startJoints(model, initialOf(yaml), limits, "initial", state); },
                                      parts);
    EXPECT_EQ(state.q, before.q);
  };
  refused("initial: {joint_positions: {shoulder: 0.3, wrist: 1.0}}",
          {"'initial.joint_positions.wrist' = 1", "robot 'arm' has no moving joint"});
  refused("initial: {joint_positions: {shoulder: 1.6}}",
          {"'initial.joint_positions.shoulder' = 1.6", "outside the joint's limits [-1.5, 1.5]"});
  refused("initial: {joint_positions: {slider: -0.01}}", {"initial.joint_positions.slider", "limits [0, 0.2]"});
  refused("initial: {joint_positions: {finger: 0.5}}", {"initial.joint_positions.finger", "follows joint 'elbow'"});
  refused("initial: {joint_velocities: {elbow: -60}}",
          {"'initial.joint_velocities.elbow' = -60", "limits.max_angular_speed = 50"});
  // What the parser refuses, by key.
  expectThrowsWith<io::ConfigError>([] { initialOf("initial: {joint_positions: [1, 2]}"); },
                                    {"initial.joint_positions", "a map from joint name"});
  expectThrowsWith<io::ConfigError>([] { initialOf("initial: {joint_positions: {elbow: fast}}"); },
                                    {"initial.joint_positions.elbow"});
  expectThrowsWith<io::ConfigError>([] { initialOf("initial: {joint_velocities: {elbow: .nan}}"); },
                                    {"initial.joint_velocities.elbow"});
}

// Until rbsim and the node take robots, a world of bodies refuses joint
// values rather than ignoring them.
TEST(JointStart, AWorldOfBodiesRefusesJointValues) {
  const io::SimConfig config = io::parseConfig(YAML::Load("initial: {joint_positions: {elbow: 1.0}}"));
  expectThrowsWith<io::ConfigError>([&] { io::loadWorld(config, [] { return core::BodySpec(); }); },
                                    {"initial.joint_positions", "a body has no moving joints"});
}

}  // namespace
}  // namespace rigid_body_sim::test
