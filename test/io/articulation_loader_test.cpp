// The articulation loader: a robot's links, joints and their fields from
// URDF, the world root, and refusals that name the joint or link. Test
// models inline; one is stepped and swings with its closed-form period.
#include "rigid_body_sim/io/articulation_loader.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../core/articulations/lone_robot.h"
#include "../test_util.h"

namespace rigid_body_sim::test {
namespace {

using core::JointType;
using core::Vec3;

std::string inertial(double mass, const std::string& xyz = "0 0 0",
                     const std::string& inertia = "ixx='0.02' iyy='0.02' izz='0.001' ixy='0' ixz='0' iyz='0'") {
  return "<inertial><origin xyz='" + xyz + "'/><mass value='" + std::to_string(mass) + "'/><inertia " + inertia +
         "/></inertial>";
}

std::string link(const std::string& name, const std::string& inside) {
  return "<link name='" + name + "'>" + inside + "</link>";
}

std::string joint(const std::string& name, const std::string& type, const std::string& parent, const std::string& child,
                  const std::string& xyz, const std::string& inside = "") {
  return "<joint name='" + name + "' type='" + type + "'><parent link='" + parent + "'/><child link='" + child +
         "'/><origin xyz='" + xyz + "'/>" + inside + "</joint>";
}

/// A rod hanging from a pivot 2 m above the world origin, about y.
std::string pendulum(const std::string& joint_inside) {
  return "<robot name='pendulum'>" + link("world", "") +
         joint("pivot", "revolute", "world", "rod", "0 0 2", joint_inside) +
         link("rod", inertial(1.5, "0 0 -0.5", "ixx='0.125' iyy='0.125' izz='0.001' ixy='0' ixz='0' iyz='0'") +
                         "<collision><origin xyz='0 0 -0.5'/><geometry><cylinder radius='0.02' length='1'/>"
                         "</geometry></collision>") +
         "</robot>";
}

const std::string kPivot =
    "<axis xyz='0 2 0'/><limit lower='-1.5' upper='1.6' effort='5' velocity='3'/>"
    "<dynamics damping='0.1' friction='0.2'/>";

core::ArticulationModel load(const std::string& xml) { return io::loadArticulationString(xml, "robot.urdf"); }

void expectRefused(const std::string& xml, std::initializer_list<std::string> parts) {
  expectThrowsWith<io::UrdfError>([&] { load(xml); }, parts);
}

/// Refused with urdf.repair: false (what the default repairs: urdf_repair_test).
void expectRefusedStrictly(const std::string& xml, std::initializer_list<std::string> parts) {
  expectThrowsWith<io::UrdfError>(
      [&] {
        io::loadArticulationString(xml, "robot.urdf", "", io::UrdfOptions{false, nullptr});
      },
      parts);
}

TEST(ArticulationLoader, APendulumOnTheWorldHasItsJointsFields) {
  const core::ArticulationModel model = load(pendulum(kPivot));
  EXPECT_EQ(model.name, "pendulum");
  EXPECT_TRUE(model.fixed_base);
  ASSERT_EQ(model.links.size(), 2u);
  EXPECT_EQ(model.links[0].name, "world");
  EXPECT_EQ(model.links[0].mass.mass, 0.0);
  const core::ArticulatedLink& rod = model.links[1];
  EXPECT_EQ(rod.name, "rod");
  EXPECT_EQ(rod.joint, "pivot");
  EXPECT_EQ(rod.parent, 0);
  EXPECT_EQ(rod.type, JointType::Revolute);
  EXPECT_EQ(rod.axis_J, Vec3::UnitY());  // made unit length
  EXPECT_EQ(rod.X_PJ.translation, Vec3(0, 0, 2));
  EXPECT_EQ(rod.limits.lower, -1.5);
  EXPECT_EQ(rod.limits.upper, 1.6);
  EXPECT_EQ(rod.limits.effort, 5.0);
  EXPECT_EQ(rod.limits.velocity, 3.0);
  EXPECT_EQ(rod.damping, 0.1);
  EXPECT_EQ(rod.friction, 0.2);
  EXPECT_EQ(rod.mass.mass, 1.5);
  EXPECT_EQ(rod.mass.p_FC, Vec3(0, 0, -0.5));
  ASSERT_EQ(rod.collision.size(), 1u);
  EXPECT_EQ(rod.collision[0].kind, core::CollisionShape::Kind::kCylinder);
}

// Loaded from URDF and stepped: released from horizontal it swings with
// the period 4 √(I/(m g l)) K(sin(θ₀/2)) (I about the pivot).
TEST(ArticulationLoader, ALoadedPendulumSwingsWithItsPeriod) {
  const core::ArticulationModel model =
      load(pendulum("<axis xyz='0 1 0'/><limit lower='-3' upper='3' effort='1' velocity='9'/>"));
  core::ArticulationState state = core::restState(model);
  state.q(0) = M_PI / 2.0;
  std::vector<double> up;
  LoneRobot alone(model, Vec3(0, 0, -9.81), 1e-3);
  for (int n = 0; n < 8000; ++n) {
    const double before = state.q(0);
    alone.step(state);
    if (before < 0.0 && state.q(0) >= 0.0) up.push_back(1e-3 * (n + before / (before - state.q(0))));
  }
  ASSERT_GE(up.size(), 3u);
  const double period = (up.back() - up.front()) / static_cast<double>(up.size() - 1);
  const double m = 1.5, l = 0.5, I = 0.125 + m * l * l;
  EXPECT_NEAR(period / (4.0 * std::sqrt(I / (m * 9.81 * l)) * std::comp_ellint_1(std::sin(M_PI / 4.0))), 1.0, 1e-3);
}

// A floating base with a sensor lumped into it by a fixed joint, a
// continuous wheel, a prismatic slider carrying a revolute finger that a
// second finger mimics.
TEST(ArticulationLoader, AFloatingRobotLumpsFixedLinksAndReadsEveryJointType) {
  const std::string xml =
      "<robot name='rover'>" + link("base", inertial(10.0)) + joint("mount", "fixed", "base", "sensor", "0.2 0 0.1") +
      link("sensor", inertial(1.0)) +
      joint("axle", "continuous", "base", "wheel", "0 0.3 0", "<axis xyz='0 1 0'/><limit effort='20' velocity='10'/>") +
      link("wheel", inertial(2.0)) +
      joint("lift", "prismatic", "base", "slider", "0 0 0.5",
            "<axis xyz='0 0 1'/><limit lower='0' upper='0.4' effort='100' velocity='1'/>") +
      link("slider", inertial(1.0)) +
      joint("finger1", "revolute", "slider", "left", "0 0.05 0",
            "<axis xyz='1 0 0'/><limit lower='-1' upper='1' effort='2' velocity='1'/>") +
      link("left", inertial(0.1)) +
      joint("finger2", "revolute", "slider", "right", "0 -0.05 0",
            "<axis xyz='1 0 0'/><limit lower='-1' upper='1' effort='2' velocity='1'/>"
            "<mimic joint='finger1' multiplier='-1' offset='0.1'/>") +
      link("right", inertial(0.1)) + "</robot>";
  const core::ArticulationModel model = load(xml);
  EXPECT_FALSE(model.fixed_base);
  ASSERT_EQ(model.links.size(), 5u);
  const core::ArticulatedLink& base = model.links[0];
  EXPECT_DOUBLE_EQ(base.mass.mass, 11.0);
  EXPECT_TRUE(base.mass.p_FC.isApprox(Vec3(0.2, 0, 0.1) / 11.0));
  ASSERT_EQ(base.fixed_links.size(), 1u);
  EXPECT_EQ(base.fixed_links[0].name, "sensor");
  // Breadth first, siblings by joint name (urdfdom's order): axle, lift, then
  // the fingers on the slider.
  EXPECT_EQ(model.links[1].joint, "axle");
  EXPECT_EQ(model.links[1].type, JointType::Continuous);
  EXPECT_TRUE(std::isinf(model.links[1].limits.lower));
  EXPECT_TRUE(std::isinf(model.links[1].limits.upper));
  EXPECT_EQ(model.links[1].limits.effort, 20.0);
  EXPECT_EQ(model.links[2].joint, "lift");
  EXPECT_EQ(model.links[2].type, JointType::Prismatic);
  EXPECT_EQ(model.links[2].limits.upper, 0.4);
  EXPECT_EQ(model.links[3].parent, 2);
  EXPECT_EQ(model.links[4].joint, "finger2");
  EXPECT_EQ(model.links[4].mimic.joint, 3);
  EXPECT_EQ(model.links[4].mimic.multiplier, -1.0);
  EXPECT_EQ(model.links[4].mimic.offset, 0.1);
  // A joint without <dynamics> or with no position limits has none.
  EXPECT_EQ(model.links[1].damping, 0.0);
  EXPECT_EQ(model.dofCount(), 6 + 4);
}

TEST(ArticulationLoader, RefusesWhatCannotBeSimulatedNamingTheJointOrLink) {
  expectRefused(pendulum(kPivot).replace(pendulum(kPivot).find("revolute"), 8, "floating"),
                {"robot.urdf", "joint 'pivot' is floating", "revolute, continuous, prismatic or fixed"});
  expectRefused(pendulum("<axis xyz='0 0 0'/><limit lower='0' upper='1' effort='1' velocity='1'/>"),
                {"joint 'pivot'", "<axis xyz>", "not zero"});
  expectRefused(pendulum("<axis xyz='0 1 0'/><limit lower='1' upper='0.5' effort='1' velocity='1'/>"),
                {"joint 'pivot' limit", "lower must not exceed upper"});
  expectRefused(pendulum("<axis xyz='0 1 0'/><limit lower='0' upper='1' effort='1' velocity='1'/>"
                         "<dynamics damping='-1'/>"),
                {"joint 'pivot' dynamics damping"});
  expectRefusedStrictly(pendulum("<axis xyz='0 1 0'/><limit lower='0' upper='1' effort='1' velocity='1'/>"
                                 "<mimic joint='elbow'/>"),
                        {"joint 'pivot' <mimic joint> = 'elbow'", "no moving joint"});
  const std::string massless = "<robot name='r'>" + link("world", "") +
                               joint("pivot", "continuous", "world", "rod", "0 0 1", "<axis xyz='0 1 0'/>") +
                               link("rod",
                                    "<inertial><mass value='0'/><inertia ixx='0' iyy='0' izz='0' ixy='0' "
                                    "ixz='0' iyz='0'/></inertial>") +
                               "</robot>";
  // Nothing with mass moves: strictly refused naming the joint; repaired, it is held and nothing moves.
  expectRefusedStrictly(massless, {"joint 'pivot' moves only massless links"});
  expectRefused(massless, {"robot 'r' has no mass anywhere and no <collision> to give it one"});
  const std::string no_inertial = "<robot name='r'>" + link("world", "") +
                                  joint("pivot", "continuous", "world", "rod", "0 0 1", "<axis xyz='0 1 0'/>") +
                                  link("rod", "") + "</robot>";
  expectRefusedStrictly(no_inertial, {"link 'rod' has no <inertial>"});
  const std::string flat = "<robot name='r'>" + link("world", "") +
                           joint("pivot", "continuous", "world", "rod", "0 0 1", "<axis xyz='0 1 0'/>") +
                           link("rod", inertial(1.0, "0 0 0", "ixx='1' iyy='1' izz='3' ixy='0' ixz='0' iyz='0'")) +
                           "</robot>";
  expectRefusedStrictly(flat, {"link 'rod'", "triangle inequality"});
  // Nothing moving: a body, not a robot (the fuzzer's find: a lone `world`).
  expectRefused("<robot name='arm'><link name='world'/></robot>", {"robot 'arm' has no revolute"});
  expectRefused("<robot name='box'>" + link("box", inertial(1.0)) + "</robot>", {"robot 'box'", "it is one body"});
  // A cycle of joints is refused before urdfdom reads it (urdf_parse).
  const std::string cycle = "<robot name='r'>" + link("a", inertial(1.0)) + link("b", inertial(1.0)) +
                            joint("ab", "continuous", "a", "b", "0 0 1", "<axis xyz='0 1 0'/>") +
                            joint("ba", "continuous", "b", "a", "0 0 1", "<axis xyz='0 1 0'/>") + "</robot>";
  expectThrowsWith<io::UrdfError>([&] { load(cycle); }, {"robot.urdf"});
}

}  // namespace
}  // namespace rigid_body_sim::test
