#include "rigid_body_sim/core/step/entity_ids.h"

#include <stdexcept>
#include <string>

namespace rigid_body_sim::core {

EntityIds::EntityIds(std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) insert(i);
}

EntityId EntityIds::insert(std::size_t index) {
  if (index > slot_of_.size()) {
    throw std::out_of_range("entity index " + std::to_string(index) + ": past the end (" +
                            std::to_string(slot_of_.size()) + " entities)");
  }
  std::uint32_t slot = 0;
  if (free_.empty()) {
    slot = static_cast<std::uint32_t>(slots_.size());
    slots_.emplace_back();
  } else {
    slot = free_.back();
    free_.pop_back();
  }
  Slot& s = slots_[slot];
  if (s.generation == 0) s.generation = 1;  // a new slot's first; a reused one aged when it was freed
  slot_of_.insert(slot_of_.begin() + static_cast<std::ptrdiff_t>(index), slot);
  renumberFrom(index);
  return {slot, s.generation};
}

void EntityIds::erase(std::size_t index) {
  const EntityId gone = at(index);
  Slot& s = slots_[gone.slot];
  s.index = kFree;
  if (++s.generation == 0) s.generation = 1;  // the old id no longer matches, reused or not (0 names nothing)
  free_.push_back(gone.slot);
  slot_of_.erase(slot_of_.begin() + static_cast<std::ptrdiff_t>(index));
  renumberFrom(index);
}

std::optional<std::size_t> EntityIds::find(EntityId id) const {
  if (id.generation == 0 || id.slot >= slots_.size()) return std::nullopt;
  const Slot& s = slots_[id.slot];
  if (s.generation != id.generation || s.index == kFree) return std::nullopt;
  return s.index;
}

EntityId EntityIds::at(std::size_t index) const {
  if (index >= slot_of_.size()) {
    throw std::out_of_range("entity index " + std::to_string(index) + ": no such entity (" +
                            std::to_string(slot_of_.size()) + ")");
  }
  const std::uint32_t slot = slot_of_[index];
  return {slot, slots_[slot].generation};
}

void EntityIds::renumberFrom(std::size_t index) {
  for (std::size_t i = index; i < slot_of_.size(); ++i) slots_[slot_of_[i]].index = i;
}

}  // namespace rigid_body_sim::core
