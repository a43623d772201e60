// What a request addresses (no master): a body by name ("" only when there
// is one), the axes of its vectors (the world's, its own, another body's,
// turning with it), a frame's pose, and the errors that name what exists.
#include "rigid_body_sim/ros/addressing.h"

#include <gtest/gtest.h>

#include "node_parts.h"

namespace rigid_body_sim::node {
namespace {

using test::PartsWorld;
using test::Quat;
using test::Vec3;
using World = PartsWorld;

TEST(Addressing, ABodyIsFoundByNameAndAnEmptyNameOnlyWhenItIsTheOnlyOne) {
  World two({"a", "b"});
  std::string error;
  EXPECT_EQ(two.address.body("b", error), 1);
  EXPECT_FALSE(two.address.body("", error));
  EXPECT_EQ(error, "there are several bodies: give body ('a', 'b')");
  EXPECT_FALSE(two.address.body("c", error));
  EXPECT_EQ(error, "unknown body 'c' (the bodies: 'a', 'b')");

  World one({"solo"});
  EXPECT_EQ(one.address.body("", error), 0);
  World none({});
  EXPECT_FALSE(none.address.body("", error));
  EXPECT_EQ(error, "the world has no bodies (~spawn_body adds one)");
}

TEST(Addressing, AFrameGivesTheWorldsTheBodysOwnOrAnotherBodysAxes) {
  World two({"a", "b"});
  std::string error;
  for (const char* world : {"", "map", "world"}) {
    const auto axes = two.address.axes(world, 0, error);
    ASSERT_TRUE(axes);
    EXPECT_EQ(axes->frame, core::Frame::kWorld);
    EXPECT_EQ(axes->other, -1);
  }
  for (const char* own : {"a/base", "base"}) {  // its tf frame, or its root link's name
    const auto axes = two.address.axes(own, 0, error);
    ASSERT_TRUE(axes);
    EXPECT_EQ(axes->frame, core::Frame::kBody);
    EXPECT_EQ(two.address.frameOf(*axes, 0), "a/base");
  }
  const auto other = two.address.axes("b/base", 0, error);
  ASSERT_TRUE(other);
  EXPECT_EQ(other->other, 1);
  EXPECT_EQ(two.address.frameOf(*other, 0), "b/base");
  // b is turned a quarter about z: its x axis is the world's y.
  EXPECT_TRUE((two.address.orientationOf(*other, 0) * Vec3::UnitX()).isApprox(Vec3::UnitY(), 1e-15));
  EXPECT_TRUE(two.address.orientationOf(Axes{}, 1).isApprox(Quat::Identity()));
  EXPECT_FALSE(two.address.axes("odom", 0, error));
  EXPECT_EQ(error, "unknown frame 'odom' (use 'map', the body's frame 'a/base' or another body's tf frame)");
  EXPECT_FALSE(two.address.target("a", "odom", error));
  const auto target = two.address.target("b", "a/base", error);
  ASSERT_TRUE(target);
  EXPECT_EQ(target->body, 1);
  EXPECT_EQ(target->axes.other, 0);
}

TEST(Addressing, AFramesPoseIsItsBodysNow) {
  World two({"a", "b"});
  std::string error;
  const auto X_WB = two.address.pose("b/base", error);
  ASSERT_TRUE(X_WB);
  EXPECT_EQ(X_WB->translation, Vec3(1, 0, 0));
  EXPECT_TRUE((X_WB->rotation * Vec3::UnitX()).isApprox(Vec3::UnitY(), 1e-15));
  EXPECT_EQ(two.address.pose("map", error)->translation, Vec3::Zero());
  EXPECT_FALSE(two.address.pose("a", error));  // a name, not a frame
  EXPECT_EQ(error, "frame: unknown frame 'a' (use 'map' or a body's tf frame, 'a/base', 'b/base')");
}

}  // namespace
}  // namespace rigid_body_sim::node
