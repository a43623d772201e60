// The node's own config keys: node_keys.h.
#include "rigid_body_sim/io/node_keys.h"

#include <algorithm>

namespace rigid_body_sim::io {

const std::vector<std::string>& nodeKeys() {
  static const std::vector<std::string> keys = {"rate",
                                                "realtime_factor",
                                                "publish_rate",
                                                "world_frame",
                                                "wrench_timeout",
                                                "covariance",
                                                "scene_size",
                                                "report_timing",
                                                "paused",
                                                "publish_tf",
                                                "body_states_rate",
                                                "per_body_topics",
                                                "body_states_twist",
                                                "config_file"};
  return keys;
}

bool isNodeKey(std::string_view key) {
  const std::vector<std::string>& keys = nodeKeys();
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

}  // namespace rigid_body_sim::io
