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
  bodies_ = std::move(bodies);
  by_name_.clear();
  by_frame_.clear();
  owner_.clear();
  by_name_.reserve(bodies_.size());
  by_frame_.reserve(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const int index = static_cast<int>(i);
    const Entry& e = bodies_[i];
    by_name_.emplace(e.name, index);
    by_frame_.emplace(e.frame, index);
    owner_.emplace(e.frame, index);
    for (const std::string& frame : e.other_frames) owner_.emplace(frame, index);
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
