// The bodies of the node's world by name and by tf frame, in hash maps: a
// request or a ~NAME/wrench message finds its body in constant time, where
// a scan of the model built a string of every name per message. Made again
// after each edit of the world (a deletion moves the later indices).
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace rigid_body_sim::node {

class BodyDirectory {
 public:
  /// What a body is called: its name, its tf frame (its root link's), and
  /// its other frames (fixed links, sensors), in the model's order.
  struct Entry {
    std::string name;
    std::string frame;
    std::vector<std::string> other_frames;
  };

  /// Forgets what it held and indexes `bodies` (entry i is body i).
  void assign(std::vector<Entry> bodies);
  /// Indexes one more body, last (a spawn: the others are not touched).
  void add(Entry body);
  /// Forgets body i; the later ones move down by one (a delete).
  void erase(std::size_t i);

  std::size_t size() const { return bodies_.size(); }
  const Entry& entry(std::size_t i) const { return bodies_[i]; }

  /// The body named `name`, if there is one.
  std::optional<int> byName(const std::string& name) const;
  /// The body whose tf frame (root link) is `frame`, if there is one.
  std::optional<int> byFrame(const std::string& frame) const;
  /// The body any of whose frames (tf frame, fixed links, sensors) is `frame`.
  std::optional<int> ownerOf(const std::string& frame) const;

  /// "'a', 'b', 'c'" for a message: the first `most` names, then how many
  /// more (a world of 10,000 bodies does not list them all in one error).
  std::string names(std::size_t most = 20) const;
  /// The same for the tf frames, each after ", ".
  std::string frames(std::size_t most = 20) const;

 private:
  std::vector<Entry> bodies_;
  std::unordered_map<std::string, int> by_name_, by_frame_, owner_;
};

}  // namespace rigid_body_sim::node
