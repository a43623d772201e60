#include "yaml_split_load.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <optional>
#include <sstream>
#include <vector>

namespace rigid_body_sim::io {
namespace {

/// Builds nodes from the parser's events as yaml-cpp's own builder does
/// (tags and styles kept; a repeated key is kept twice, the first one found
/// by a look-up), except for the split sequence's items.
class SplitBuilder : public YAML::EventHandler {
 public:
  SplitBuilder(std::string split_key, const std::function<void(const YAML::Node&, std::size_t)>& on_item)
      : split_key_(std::move(split_key)), on_item_(on_item) {}

  YAML::Node root;
  bool split_seen = false;

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override { done(YAML::Node(YAML::NodeType::Null)); }
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {
    throw YAML::Exception(YAML::Mark::null_mark(), "aliases are refused");  // yamlProblem refused them first
  }
  void OnScalar(const YAML::Mark&, const std::string& tag, YAML::anchor_t, const std::string& value) override {
    YAML::Node node(value);
    node.SetTag(tag);
    done(node);
  }
  void OnSequenceStart(const YAML::Mark&, const std::string& tag, YAML::anchor_t,
                       YAML::EmitterStyle::value style) override {
    open(YAML::NodeType::Sequence, tag, style);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark&, const std::string& tag, YAML::anchor_t, YAML::EmitterStyle::value style) override {
    open(YAML::NodeType::Map, tag, style);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Open {
    YAML::Node node;
    std::optional<YAML::Node> key;  ///< a map's key waiting for its value
    bool split = false;             ///< the sequence whose items go to on_item
  };

  std::string split_key_;
  const std::function<void(const YAML::Node&, std::size_t)>& on_item_;
  std::vector<Open> open_;
  std::size_t items_ = 0;
  int split_keys_ = 0;  ///< split_key's seen among the root map's keys

  bool isSplitKey(const YAML::Node& key) const { return key.IsScalar() && key.Scalar() == split_key_; }

  void open(YAML::NodeType::value type, const std::string& tag, YAML::EmitterStyle::value style) {
    Open o{YAML::Node(type), std::nullopt, false};
    o.node.SetTag(tag);
    o.node.SetStyle(style);
    // The root map's value under its first split_key (a look-up finds the first of repeated keys).
    if (type == YAML::NodeType::Sequence && open_.size() == 1 && open_[0].key && split_keys_ == 1 &&
        isSplitKey(*open_[0].key)) {
      o.split = split_seen = true;
    }
    open_.push_back(std::move(o));
  }

  void close() {
    YAML::Node node = open_.back().node;
    open_.pop_back();
    done(node);
  }

  /// A complete node: the root, a key, a value, or an item.
  void done(const YAML::Node& node) {
    if (open_.empty()) {
      root = node;
      return;
    }
    Open& parent = open_.back();
    if (parent.node.IsSequence()) {
      if (parent.split) {
        on_item_(node, items_++);
      } else {
        parent.node.push_back(node);
      }
    } else if (!parent.key) {
      parent.key = node;
      if (open_.size() == 1 && isSplitKey(node)) ++split_keys_;
    } else {
      parent.node[*parent.key] = node;  // a node key: inserted, never merged, as YAML::Load does
      parent.key.reset();
    }
  }
};

}  // namespace

SplitLoad loadSplittingSequence(const std::string& text, const std::string& split_key,
                                const std::function<void(const YAML::Node& item, std::size_t index)>& on_item) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  SplitBuilder builder(split_key, on_item);
  if (!parser.HandleNextDocument(builder)) return {YAML::Node(), false};
  return {builder.root, builder.split_seen};
}

}  // namespace rigid_body_sim::io
