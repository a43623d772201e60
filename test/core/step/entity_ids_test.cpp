// Stable ids over a dense table (core::EntityIds): each names its entity
// at the index it has now, through inserts and erases of others; an id of
// an erased entity is refused, its slot reused under a new generation.
#include "rigid_body_sim/core/step/entity_ids.h"

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

namespace rigid_body_sim::core {
namespace {

TEST(EntityIds, NameTheirEntityThroughOthersEdits) {
  EntityIds ids(3);
  const EntityId a = ids.at(0), b = ids.at(1), c = ids.at(2);
  const EntityId front = ids.insert(0);  // everything moves up
  EXPECT_EQ(ids.find(front), 0u);
  EXPECT_EQ(ids.find(a), 1u);
  EXPECT_EQ(ids.find(c), 3u);
  ids.erase(2);  // b
  EXPECT_EQ(ids.find(b), std::nullopt);
  EXPECT_EQ(ids.find(c), 2u);
  EXPECT_EQ(ids.size(), 3u);
  const EntityId d = ids.insert(3);
  EXPECT_EQ(d.slot, b.slot);  // reused, under a new generation
  EXPECT_NE(d.generation, b.generation);
  EXPECT_EQ(ids.find(b), std::nullopt);
  EXPECT_EQ(ids.find(d), 3u);
  EXPECT_EQ(ids.find(EntityId{}), std::nullopt);
  EXPECT_EQ(ids.find(EntityId{99, 1}), std::nullopt);
  EXPECT_THROW(ids.at(4), std::out_of_range);
  EXPECT_THROW(ids.erase(4), std::out_of_range);
  EXPECT_THROW(ids.insert(5), std::out_of_range);
  EXPECT_EQ(ids.size(), 4u);  // the refusals changed nothing
}

// Against a plain list of who is where, over random inserts and erases: an
// id is found exactly where its entity is, and every erased one is refused.
TEST(EntityIds, AgreeWithAListOverRandomEdits) {
  EntityIds ids;
  std::vector<EntityId> where;  // where[i]: the id of the entity at i
  std::vector<EntityId> gone;
  std::mt19937 rng(7);
  for (int n = 0; n < 2000; ++n) {
    if (where.empty() || rng() % 3 != 0) {
      const std::size_t i = rng() % (where.size() + 1);
      where.insert(where.begin() + static_cast<std::ptrdiff_t>(i), ids.insert(i));
    } else {
      const std::size_t i = rng() % where.size();
      ids.erase(i);
      gone.push_back(where[i]);
      where.erase(where.begin() + static_cast<std::ptrdiff_t>(i));
    }
  }
  ASSERT_EQ(ids.size(), where.size());
  ASSERT_GT(gone.size(), 100u);
  for (std::size_t i = 0; i < where.size(); ++i) {
    EXPECT_EQ(ids.find(where[i]), i);
    EXPECT_EQ(ids.at(i), where[i]);
  }
  for (const EntityId& id : gone) EXPECT_EQ(ids.find(id), std::nullopt);
}

}  // namespace
}  // namespace rigid_body_sim::core
