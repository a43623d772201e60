// A YAML document loaded as YAML::Load would, except that the items of one
// sequence under the root map are handed over one at a time and not kept:
// the `bodies` list of a world of 10,000 bodies took 7 KB of yaml-cpp tree
// an entry, more than the bodies themselves (bench/HISTORY.md). Private to io.
#pragma once

#include <yaml-cpp/yaml.h>

#include <functional>
#include <string>

namespace rigid_body_sim::io {

struct SplitLoad {
  YAML::Node root;     ///< the document; a null node for an empty text
  bool split = false;  ///< the sequence was found and its items went to on_item
};

/// The tree of the one-document YAML `text` (already accepted by
/// yamlProblem(): aliases bounded, depth bounded), aliases copied and merge
/// keys resolved as roslaunch's reader does. When the root is a map whose
/// first `split_key` (not "") holds a sequence, each item of that sequence
/// goes to `on_item` as soon as it is read, with its index, and the tree
/// keeps an empty sequence there instead (an alias of that sequence is
/// refused). YAML::Exception for text yaml-cpp
/// cannot parse; anything `on_item` throws passes through.
SplitLoad loadSplittingSequence(const std::string& text, const std::string& split_key,
                                const std::function<void(const YAML::Node& item, std::size_t index)>& on_item);

}  // namespace rigid_body_sim::io
