// The keys of a config file that belong to sim_node itself (its loop, its
// topics and frames: ~rate, ~publish_rate, ~world_frame, ...) beside the
// simulation's. The node reads them as its parameters (ros/params.h, each
// with its range); rbsim, which reads the node's files unchanged, sets them
// aside and names them once as not applying. settings_test holds this list
// and the node's parameter table equal.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rigid_body_sim::io {

/// Every top-level key of the node's own, in ros/params.h's order.
const std::vector<std::string>& nodeKeys();

/// Whether `key` is one of nodeKeys().
bool isNodeKey(std::string_view key);

}  // namespace rigid_body_sim::io
