// Islands (src/core/island.cpp): which bodies contacts join, and the
// contacts sorted island by island for the impulse solve.
#include "contacts/island.h"

#include <gtest/gtest.h>

#include "../../test_util.h"
#include "step/scratch.h"

namespace rigid_body_sim::test {
namespace {

/// n boxes in free space.
core::Model boxes(int n) {
  core::ModelSpec ms = spec(shippedBox(), 1e-3, Vec3::Zero());
  ms.bodies.clear();
  for (int i = 0; i < n; ++i) {
    core::BodySpec b = boxBody(Vec3(0.1, 0.1, 0.1));
    b.name = "box" + std::to_string(i);
    ms.bodies.push_back(b);
  }
  return core::Model(ms);
}

core::Contact contact(int body, int other, int item = -1) {
  core::Contact c;
  c.body = body;
  c.other = other;
  c.item = item;
  return c;
}

TEST(Islands, ContactsBetweenAwakeBodiesJoinThemTheSceneAndSleepersDoNot) {
  const core::Model model = boxes(7);
  core::State s = core::restState(model);
  s.bodies[6].asleep = true;
  core::Workspace ws;
  ws.contacts = {contact(0, -1, 0), contact(0, 2), contact(1, 3), contact(3, 4), contact(5, 6)};
  core::findIslands(model, s, ws);
  // {0, 2}, {1, 3, 4}, and 5 and 6 on their own: 6 sleeps, so it is ground to 5.
  EXPECT_EQ(ws.scratch->island_root, (std::vector<int>{0, 1, 0, 1, 1, 5, 6}));
}

TEST(Islands, ChainsJoinWhateverTheOrderOfTheirContacts) {
  const core::Model model = boxes(5);
  const core::State s = core::restState(model);
  core::Workspace ws;
  ws.contacts = {contact(4, 3), contact(2, 1), contact(3, 2), contact(1, 0)};
  core::findIslands(model, s, ws);
  EXPECT_EQ(ws.scratch->island_root, (std::vector<int>{0, 0, 0, 0, 0}));  // the root is the smallest index
}

TEST(Islands, ContactsAreGroupedIslandByIslandInContactOrder) {
  const core::Model model = boxes(4);
  const core::State s = core::restState(model);
  core::Workspace ws;
  // Islands {0, 2} (contacts 0, 2) and {1, 3} (contacts 1, 3).
  ws.contacts = {contact(0, -1, 0), contact(1, 3), contact(2, 0), contact(3, -1, 0)};
  core::groupContactsByIsland(model, s, ws);
  EXPECT_EQ(ws.scratch->island_contacts, (std::vector<int>{0, 2, 1, 3}));
  EXPECT_EQ(ws.scratch->island_starts, (std::vector<int>{0, 2, 4}));
}

// A sleeper's own points against an awake body's solid make contacts whose
// `body` is the sleeper. Such a contact moves only the awake body, so it
// belongs to that body's island: filed under the sleeper, it formed an island
// of its own, which another core could solve while this one solved the awake
// body's other contacts, both changing its velocity (a race, and results
// that depended on the thread count).
TEST(Islands, AContactOfASleeperGoesWithTheAwakeBodyItTouches) {
  const core::Model model = boxes(3);
  core::State s = core::restState(model);
  s.bodies[2].asleep = true;
  core::Workspace ws;
  ws.contacts = {contact(0, -1, 0), contact(1, -1, 0), contact(2, 0)};
  core::groupContactsByIsland(model, s, ws);
  EXPECT_EQ(ws.scratch->island_contacts, (std::vector<int>{0, 2, 1}));
  EXPECT_EQ(ws.scratch->island_starts, (std::vector<int>{0, 2, 3}));
}

}  // namespace
}  // namespace rigid_body_sim::test
