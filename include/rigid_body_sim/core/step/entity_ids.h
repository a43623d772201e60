// Stable handles of a world's entities (its free bodies, its robots), which
// outlive the edits of others: the tables hold entities densely, so a
// delete moves every later one down an index, but an EntityId names its
// entity, not a place. An id is a slot and the generation the slot had when
// the entity took it (Box2D v3's b2BodyId): deleting the entity frees the
// slot and ages it, so the old id is refused ever after, even once a new
// entity has the slot, and never reaches another entity.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace rigid_body_sim::core {

struct EntityId {
  std::uint32_t slot = 0;
  std::uint32_t generation = 0;  ///< 0 is no generation: a default id names nothing

  friend bool operator==(EntityId a, EntityId b) { return a.slot == b.slot && a.generation == b.generation; }
  friend bool operator!=(EntityId a, EntityId b) { return !(a == b); }
};

/// The ids of one kind of entity, kept beside a dense table of them: which
/// index each id names now, and each index's id.
class EntityIds {
 public:
  /// `count` entities at indices 0 .. count - 1, each with a new id.
  explicit EntityIds(std::size_t count = 0);

  /// A new entity at `index` (at most size()): the ones at and after it move
  /// up one index. Returns its id.
  EntityId insert(std::size_t index);
  /// The entity at `index` goes (std::out_of_range if none): the later ones
  /// move down one index, and its id is refused from now on.
  void erase(std::size_t index);

  /// The index `id` names now, or nothing for an id of an entity gone (or
  /// never made).
  std::optional<std::size_t> find(EntityId id) const;
  /// The id of the entity at `index` (std::out_of_range if none).
  EntityId at(std::size_t index) const;
  std::size_t size() const { return slot_of_.size(); }

 private:
  static constexpr std::size_t kFree = static_cast<std::size_t>(-1);
  struct Slot {
    std::uint32_t generation = 0;
    std::size_t index = kFree;  ///< where its entity is now; kFree when it has none
  };
  void renumberFrom(std::size_t index);

  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_;     ///< slots to reuse, last freed first
  std::vector<std::uint32_t> slot_of_;  ///< per index: its entity's slot
};

}  // namespace rigid_body_sim::core
