#include "yaml_split_load.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <map>
#include <optional>
#include <sstream>
#include <vector>

namespace rigid_body_sim::io {
namespace {

/// Builds nodes from the parser's events as yaml-cpp's own builder does
/// (tags and styles kept; a repeated key is kept twice, the first one found
/// by a look-up), except for the split sequence's items, and with what
/// roslaunch's YAML reader does beyond it: an alias is a copy of its
/// anchor's node (not the same node, so an override of one leaves the other),
/// and a merge key `<<: *base` (or `<<: [*a, *b]`) gives a map the keys of
/// those maps it does not have itself, the first map's first.
class SplitBuilder : public YAML::EventHandler {
 public:
  SplitBuilder(std::string split_key, const std::function<void(const YAML::Node&, std::size_t)>& on_item)
      : split_key_(std::move(split_key)), on_item_(on_item) {}

  YAML::Node root;
  bool split_seen = false;

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t anchor) override { done(YAML::Node(YAML::NodeType::Null), anchor); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const auto node = anchors_.find(anchor);
    if (node == anchors_.end()) throw YAML::ParserException(mark, "an alias of the split list, or of no anchor");
    done(YAML::Clone(node->second));  // yamlProblem bounded what the aliases repeat
  }
  void OnScalar(const YAML::Mark&, const std::string& tag, YAML::anchor_t anchor, const std::string& value) override {
    YAML::Node node(value);
    node.SetTag(tag);
    done(node, anchor);
  }
  void OnSequenceStart(const YAML::Mark&, const std::string& tag, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value style) override {
    open(YAML::NodeType::Sequence, tag, style, anchor);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark&, const std::string& tag, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value style) override {
    open(YAML::NodeType::Map, tag, style, anchor);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Open {
    YAML::Node node;
    std::optional<YAML::Node> key;  ///< a map's key waiting for its value
    bool split = false;             ///< the sequence whose items go to on_item
    YAML::anchor_t anchor = YAML::NullAnchor;
  };

  std::string split_key_;
  const std::function<void(const YAML::Node&, std::size_t)>& on_item_;
  std::vector<Open> open_;
  std::size_t items_ = 0;
  int split_keys_ = 0;  ///< split_key's seen among the root map's keys
  std::map<YAML::anchor_t, YAML::Node> anchors_;

  bool isSplitKey(const YAML::Node& key) const {
    return !split_key_.empty() && key.IsScalar() && key.Scalar() == split_key_;
  }

  void open(YAML::NodeType::value type, const std::string& tag, YAML::EmitterStyle::value style,
            YAML::anchor_t anchor) {
    Open o{YAML::Node(type), std::nullopt, false, anchor};
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
    const YAML::anchor_t anchor = open_.back().split ? YAML::NullAnchor : open_.back().anchor;
    open_.pop_back();
    if (node.IsMap()) merge(node);
    done(node, anchor);
  }

  /// Resolves a map's merge key `<<` (YAML 1.1's merge type, as PyYAML reads it).
  static void merge(YAML::Node& map) {
    const YAML::Node& read = map;  // look-ups that never insert
    const YAML::Node from = read["<<"];
    if (!from) return;
    std::vector<YAML::Node> sources;
    if (from.IsMap()) {
      sources.push_back(from);
    } else if (from.IsSequence()) {
      for (const YAML::Node& m : from) sources.push_back(m);
    }
    for (const YAML::Node& m : sources) {
      if (!m.IsMap()) throw YAML::ParserException(YAML::Mark::null_mark(), "a merge key (<<) takes maps");
      for (const auto& kv : m) {
        if (!kv.first.IsScalar()) throw YAML::ParserException(YAML::Mark::null_mark(), "a merged map's keys are names");
      }
    }
    map.remove("<<");
    for (const YAML::Node& m : sources) {
      for (const auto& kv : m) {
        if (!read[kv.first.Scalar()]) map[kv.first.Scalar()] = YAML::Clone(kv.second);
      }
    }
  }

  /// A complete node: the root, a key, a value, or an item; kept under its anchor.
  void done(const YAML::Node& node, YAML::anchor_t anchor = YAML::NullAnchor) {
    if (anchor != YAML::NullAnchor) anchors_[anchor] = node;
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
