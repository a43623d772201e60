// The node's bodies by name and by frame (body_directory.h), no master needed.
#include "rigid_body_sim/ros/body_directory.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using rigid_body_sim::node::BodyDirectory;

BodyDirectory threeBodies() {
  BodyDirectory d;
  d.assign(
      {{"crate", "crate/base_link", {"crate/lid"}}, {"ball", "ball/ball", {"ball/imu_link"}}, {"arm", "arm/base", {}}});
  return d;
}

TEST(BodyDirectory, FindsABodyByNameByTfFrameAndByAnyOfItsFrames) {
  const BodyDirectory d = threeBodies();
  EXPECT_EQ(d.byName("ball"), 1);
  EXPECT_EQ(d.byName("arm"), 2);
  EXPECT_FALSE(d.byName("ball/ball"));
  EXPECT_FALSE(d.byName(""));
  EXPECT_EQ(d.byFrame("crate/base_link"), 0);
  EXPECT_FALSE(d.byFrame("crate/lid"));  // a fixed link is no body's tf frame
  EXPECT_EQ(d.ownerOf("crate/lid"), 0);
  EXPECT_EQ(d.ownerOf("ball/imu_link"), 1);
  EXPECT_EQ(d.ownerOf("arm/base"), 2);
  EXPECT_FALSE(d.ownerOf("world"));
}

// A delete forgets the body and its frames; the later bodies move down.
TEST(BodyDirectory, EraseMovesTheLaterBodiesDown) {
  BodyDirectory d = threeBodies();
  d.erase(1);
  EXPECT_FALSE(d.byName("ball"));
  EXPECT_FALSE(d.byFrame("ball/ball"));
  EXPECT_FALSE(d.ownerOf("ball/imu_link"));
  EXPECT_EQ(d.byName("crate"), 0);
  EXPECT_EQ(d.ownerOf("crate/lid"), 0);
  EXPECT_EQ(d.byName("arm"), 1);
  EXPECT_EQ(d.byFrame("arm/base"), 1);
  EXPECT_EQ(d.size(), 2u);
  EXPECT_EQ(d.entry(1).name, "arm");
  d.add({"ball", "ball/ball", {}});  // the name is free again
  EXPECT_EQ(d.byName("ball"), 2);
}

TEST(BodyDirectory, AssignForgetsWhatItHeld) {
  BodyDirectory d = threeBodies();
  d.assign({{"crate", "crate/base_link", {"crate/lid"}}, {"arm", "arm/base", {}}});
  EXPECT_FALSE(d.byName("ball"));
  EXPECT_FALSE(d.ownerOf("ball/imu_link"));
  EXPECT_EQ(d.byName("arm"), 1);
  EXPECT_EQ(d.byFrame("arm/base"), 1);
  EXPECT_EQ(d.size(), 2u);
}

// A spawn indexes one more body, last, as assign() would have.
TEST(BodyDirectory, AddIndexesOneMoreLast) {
  BodyDirectory d = threeBodies();
  d.add({"probe", "probe/base", {"probe/imu"}});
  EXPECT_EQ(d.byName("probe"), 3);
  EXPECT_EQ(d.byFrame("probe/base"), 3);
  EXPECT_EQ(d.ownerOf("probe/imu"), 3);
  EXPECT_EQ(d.byName("ball"), 1);
  EXPECT_EQ(d.size(), 4u);
  EXPECT_EQ(d.entry(3).name, "probe");
}

// A message lists a few names, then says how many more: an error in a
// world of 10,000 bodies is one line, not 10,000 names.
TEST(BodyDirectory, ListsTheFirstNamesThenHowManyMore) {
  const BodyDirectory d = threeBodies();
  EXPECT_EQ(d.names(), "'crate', 'ball', 'arm'");
  EXPECT_EQ(d.names(2), "'crate', 'ball' and 1 more");
  EXPECT_EQ(d.frames(1), ", 'crate/base_link' and 2 more");
  std::vector<BodyDirectory::Entry> many;
  for (int i = 0; i < 10000; ++i) many.push_back({"b" + std::to_string(i), "b" + std::to_string(i) + "/l", {}});
  BodyDirectory big;
  big.assign(std::move(many));
  EXPECT_EQ(big.byName("b9999"), 9999);
  EXPECT_LT(big.names().size(), 200u);
  EXPECT_NE(big.names().find("and 9980 more"), std::string::npos);
}

}  // namespace
