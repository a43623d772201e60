// A robot from a config (io/robot.h, through io::loadScene as rbsim --urdf
// and the node load one): its base at `initial`, its twist in the base's
// own axes, its joints by name; the refusals name the key.
#include "rigid_body_sim/io/robot.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>

#include "../test_util.h"
#include "rigid_body_sim/io/scene_loader.h"

namespace rigid_body_sim::test {
namespace {

/// A cart on one wheel: the base floats unless `root` is `world`.
io::UrdfText cart(bool on_world) {
  const std::string inertial =
      "<inertial><mass value='1'/><inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial>";
  const std::string world = on_world ? "<link name='world'/><joint name='mount' type='fixed'><parent link='world'/>"
                                       "<child link='body'/></joint>"
                                     : "";
  return {"<robot name='cart'>" + world + "<link name='body'>" + inertial +
              "<collision><geometry><box size='0.4 0.2 0.1'/></geometry></collision></link>"
              "<joint name='axle' type='continuous'><parent link='body'/><child link='wheel'/>"
              "<origin xyz='0 0 -0.1'/><axis xyz='0 1 0'/></joint><link name='wheel'>" +
              inertial + "<collision><geometry><sphere radius='0.05'/></geometry></collision></link></robot>",
          "cart.urdf", ""};
}

io::SimConfig config(const std::string& yaml) { return io::parseConfig(YAML::Load(yaml)); }

/// The world of the cart alone under `yaml`.
io::SceneSetup load(const std::string& yaml, bool on_world) {
  return io::loadScene(config(yaml), [&] { return cart(on_world); });
}

TEST(Robot, StartsAtTheConfigsBasePoseTwistAndJoints) {
  const io::SceneSetup world = load(R"(
initial:
  position: [1, 2, 3]
  quaternion: [0, 0, 0.7071067811865476, 0.7071067811865476]
  linear_velocity: [1, 0, 0]
  angular_velocity: [0, 0, 2]
  joint_positions: {axle: 0.5}
  joint_velocities: {axle: -3}
)",
                                    false);
  const core::ArticulationState& start = world.state.robots.at(0);
  EXPECT_EQ(start.X_WB.translation, Vec3(1, 2, 3));
  // Turned 90° about z: world x is the base's −y.
  EXPECT_LT((start.V_B.tail<3>() - Vec3(0, -1, 0)).norm(), 1e-15);
  EXPECT_LT((start.V_B.head<3>() - Vec3(0, 0, 2)).norm(), 1e-15);
  EXPECT_EQ(start.q(0), 0.5);
  EXPECT_EQ(start.v(0), -3.0);
  // Both links collide (the default scene is the ground), in one group.
  const core::Model& bodies = world.scene.model();
  ASSERT_EQ(bodies.bodyCount(), 2u);
  EXPECT_EQ(world.scene.robots().at(0).link, (std::vector<int>{0, 1}));
  EXPECT_EQ(bodies.body(0).collision_group, bodies.body(1).collision_group);
  EXPECT_GE(bodies.body(0).collision_group, 0);
}

TEST(Robot, RefusesAMovingStartForAFixedBaseAndKeysItWouldNotRead) {
  const auto refused = [](const std::string& yaml, bool on_world, const std::string& what) {
    try {
      load(yaml, on_world);
      ADD_FAILURE() << "accepted: " << yaml;
    } catch (const io::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  // Placed, it is accepted; set moving, not.
  EXPECT_NO_THROW(load("initial: {position: [0, 0, 1]}", true));
  refused("initial: {angular_velocity: [0, 0, 1]}", true, "robot 'cart' is fixed to the world");
  refused("initial: {linear_velocity: [1e9, 0, 0]}", false, "initial.linear_velocity");
  refused("initial: {joint_positions: {wheel: 1}}", false, "wheel");
  // Keys a robot would not read are refused, not ignored.
  refused("damping: {linear: 0.1}", false, "'damping': robot 'cart' is damped by its joints");
  refused("contact: {method: penalty_quadratic}", false, "'contact.method'");
  refused("gyroscopic: false", false, "'gyroscopic'");
}

}  // namespace
}  // namespace rigid_body_sim::test
