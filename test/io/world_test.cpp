// A world from a config (src/io/world.cpp): the bodies list, or one body.
#include "rigid_body_sim/io/world.h"

#include <gtest/gtest.h>

#include <string>

#include "../test_util.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::test {
namespace {

TEST(World, AWorldLoadsEveryBodyUnderItsName) {
  const io::SimConfig c = io::parseConfig(io::loadYamlFile(std::string(RBS_SOURCE_DIR) + "/config/world.yaml"),
                                          std::string(RBS_SOURCE_DIR) + "/config");
  const io::World w = io::buildWorld(c);
  ASSERT_EQ(w.model.bodyCount(), 4u);
  EXPECT_EQ(w.model.body(0).name, "box");
  EXPECT_EQ(w.model.body(0).link, "base_link");
  EXPECT_EQ(w.model.body(2).name, "bunny");
  EXPECT_EQ(w.model.body(2).link, "bunny");
  ASSERT_EQ(w.state.bodies.size(), 4u);
  EXPECT_NEAR(core::linkState(w.model.body(1), w.state.bodies[1]).p_WL.z(), 1.0, 1e-15);
  EXPECT_FALSE(w.model.body(2).solid_B.empty());  // the bunny's mesh, sampled, for the others to hit
}

TEST(World, WithoutABodiesListItIsTheOneBodyGivenAtTheInitialPose) {
  const io::SimConfig c = io::parseConfig(YAML::Load("scene: []\ninitial: {position: [1, 2, 3]}"));
  int calls = 0;
  const io::World w = io::loadWorld(c, [&] {
    ++calls;
    return shippedBox();
  });
  EXPECT_EQ(calls, 1);
  ASSERT_EQ(w.model.bodyCount(), 1u);
  EXPECT_EQ(core::linkState(w.model.body(0), w.state.bodies[0]).p_WL, Vec3(1, 2, 3));
  expectThrowsWith<io::ConfigError>([&] { io::loadWorld(c, {}); }, {"bodies", "no single body"});
}

TEST(World, ABodiesListIsLoadedThroughTheLoaderGivenAndTheSingleBodyIsNotAsked) {
  const io::SimConfig c = io::parseConfig(YAML::Load(
      "scene: []\nbodies: [{name: a, urdf: first}, {name: b, urdf: second, initial: {position: [0, 0, 5]}}]"));
  std::string asked;
  const io::World w = io::loadWorld(
      c, []() -> core::BodySpec { throw std::logic_error("not asked for with a bodies list"); },
      [&](const io::BodyEntry& e) {
        asked += e.urdf + " ";
        return shippedBox();
      });
  EXPECT_EQ(asked, "first second ");
  ASSERT_EQ(w.model.bodyCount(), 2u);
  EXPECT_EQ(w.model.body(1).name, "b");
  EXPECT_EQ(core::linkState(w.model.body(1), w.state.bodies[1]).p_WL, Vec3(0, 0, 5));
}

TEST(World, AnEmptyBodiesListIsAnEmptyWorld) {
  const io::SimConfig c = io::parseConfig(YAML::Load("bodies: []"));
  EXPECT_TRUE(c.bodies_listed);
  const io::World w = io::loadWorld(c, []() -> core::BodySpec { throw std::logic_error("not asked for"); });
  EXPECT_EQ(w.model.bodyCount(), 0u);
  EXPECT_TRUE(w.state.bodies.empty());
  EXPECT_FALSE(io::parseConfig(YAML::Load("dt: 0.001")).bodies_listed);
}

}  // namespace
}  // namespace rigid_body_sim::test
