#include "rigid_body_sim/ros/body_directory.h"

namespace rigid_body_sim::node {
namespace {

std::optional<int> find(const std::unordered_map<std::string, int>& map, const std::string& key) {
  const auto it = map.find(key);
  if (it == map.end()) return std::nullopt;
  return it->second;
}

}  // namespace

void BodyDirectory::assign(std::vector<Entry> bodies) {
  by_name_.clear();
  by_frame_.clear();
  owner_.clear();
  bodies_.clear();
  bodies_.reserve(bodies.size());
  for (Entry& e : bodies) add(std::move(e));
}

void BodyDirectory::add(Entry body) {
  const int index = static_cast<int>(bodies_.size());
  by_name_.emplace(body.name, index);
  by_frame_.emplace(body.frame, index);
  owner_.emplace(body.frame, index);
  for (const std::string& frame : body.other_frames) owner_.emplace(frame, index);
  bodies_.push_back(std::move(body));
}

void BodyDirectory::erase(std::size_t i) {
  const Entry& gone = bodies_.at(i);
  by_name_.erase(gone.name);
  by_frame_.erase(gone.frame);
  owner_.erase(gone.frame);
  for (const std::string& frame : gone.other_frames) owner_.erase(frame);
  bodies_.erase(bodies_.begin() + static_cast<std::ptrdiff_t>(i));
  const int index = static_cast<int>(i);
  for (auto* map : {&by_name_, &by_frame_, &owner_}) {
    for (auto& [key, body] : *map) {
      if (body > index) --body;
    }
  }
}

std::optional<int> BodyDirectory::byName(const std::string& name) const { return find(by_name_, name); }

std::optional<int> BodyDirectory::byFrame(const std::string& frame) const { return find(by_frame_, frame); }

std::optional<int> BodyDirectory::ownerOf(const std::string& frame) const { return find(owner_, frame); }

std::string BodyDirectory::names(std::size_t most) const {
  std::string out;
  for (std::size_t i = 0; i < bodies_.size() && i < most; ++i) out += (i ? ", '" : "'") + bodies_[i].name + "'";
  if (bodies_.size() > most) out += " and " + std::to_string(bodies_.size() - most) + " more";
  return out;
}

std::string BodyDirectory::frames(std::size_t most) const {
  std::string out;
  for (std::size_t i = 0; i < bodies_.size() && i < most; ++i) out += ", '" + bodies_[i].frame + "'";
  if (bodies_.size() > most) out += " and " + std::to_string(bodies_.size() - most) + " more";
  return out;
}

}  // namespace rigid_body_sim::node
