#include "rigid_body_sim/ros/params.h"

#include <ros/console.h>
#include <ros/param.h>

#include <filesystem>
#include <set>
#include <sstream>

namespace rigid_body_sim::node {

namespace {

using Kind = NodeParamKey::Kind;

NodeParamKey number(std::string_view key, std::string_view unit, double min, double max,
                    double* (*field)(NodeSettings&)) {
  NodeParamKey k;
  k.key = key;
  k.unit = unit;
  k.min = min;
  k.max = max;
  k.number = field;
  return k;
}

NodeParamKey flag(std::string_view key, bool* (*field)(NodeSettings&)) {
  NodeParamKey k;
  k.key = key;
  k.kind = Kind::kFlag;
  k.flag = field;
  return k;
}

NodeParamKey text(std::string_view key) {
  NodeParamKey k;
  k.key = key;
  k.kind = Kind::kText;
  return k;
}

// A tick at least every second keeps SIGINT and the services answered; at
// most 1e4 a second keeps the loop from spinning. The slowest slow motion,
// other than 0 (as fast as possible), is a 1 ms step each wall second
// (1e-300 froze the simulation without a word).
std::vector<NodeParamKey> makeKeys() {
  constexpr double kMaxRate = 1e4;  // Hz
  NodeParamKey realtime = number("realtime_factor", "", 1e-3, 1e3, [](NodeSettings& n) { return &n.realtime_factor; });
  realtime.zero_too = true;
  realtime.zero_means = "as fast as possible";
  NodeParamKey timeout =
      number("wrench_timeout", "s", 0.0, core::ranges::kMaxDuration, [](NodeSettings& n) { return &n.wrench_timeout; });
  timeout.zero_means = "held until cleared";
  // clang-format off
  return {
      number("rate", "Hz", 1.0, kMaxRate, [](NodeSettings& n) { return &n.rate; }),
      realtime,
      number("publish_rate", "Hz", core::ranges::kMinRate, core::ranges::kMaxPublishRate, [](NodeSettings& n) { return &n.publish_rate; }),
      text("world_frame"),
      timeout,
      number("covariance", "", 0.0, 1e6, [](NodeSettings& n) { return &n.covariance; }),
      number("scene_size", "m", 1e-3, 1e6, [](NodeSettings& n) { return &n.scene_size; }),
      flag("report_timing", [](NodeSettings& n) { return &n.report_timing; }),
      flag("paused", [](NodeSettings& n) { return &n.paused; }),
      flag("publish_tf", [](NodeSettings& n) { return &n.publish_tf; }),
      number("body_states_rate", "Hz", core::ranges::kMinRate, kMaxRate,
             [](NodeSettings& n) { return &n.body_states_rate; }),
      number("per_body_topics", "bodies", 0.0, 1e9, [](NodeSettings& n) { return &n.per_body_topics; }),
      text("body_states_twist"),
      text("config_file"),
  };
  // clang-format on
}

}  // namespace

const std::vector<NodeParamKey>& nodeParamKeys() {
  static const std::vector<NodeParamKey> keys = makeKeys();
  return keys;
}

const NodeParamKey* findNodeParamKey(std::string_view key) {
  for (const NodeParamKey& k : nodeParamKeys()) {
    if (k.key == key) return &k;
  }
  return nullptr;
}

void checkNodeParam(const NodeParamKey& key, double x) {
  if (key.zero_too && x == 0.0) return;
  if (!std::isfinite(x) || x < key.min || x > key.max) {
    std::ostringstream os;
    os << "parameter '~" << key.key << "' = " << x << ": must be " << (key.zero_too ? "0 (" : "")
       << (key.zero_too ? std::string(key.zero_means) + ") or " : "") << "within [" << key.min << ", " << key.max << "]"
       << (key.unit.empty() ? "" : " " + std::string(key.unit))
       << (!key.zero_too && !key.zero_means.empty() ? " (0: " + std::string(key.zero_means) + ")" : "");
    throw io::ConfigError(os.str());
  }
}

namespace {

/// A number parameter within its range: anything outside is refused with
/// the range (a rate of 1e-9 Hz would sleep 30 years between ticks and never
/// answer SIGINT; 1e300 would spin the loop at full CPU).
double numberParam(const XmlRpc::XmlRpcValue& v, const NodeParamKey& key) {
  double x = 0.0;
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
    x = static_cast<double>(const_cast<XmlRpc::XmlRpcValue&>(v));
  } else if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    x = static_cast<int>(const_cast<XmlRpc::XmlRpcValue&>(v));
  } else {
    throw io::ConfigError("parameter '~" + std::string(key.key) + "': expected a number, got " + v.toXml());
  }
  checkNodeParam(key, x);
  return x;
}

bool flagParam(const XmlRpc::XmlRpcValue& v, const std::string& key) {
  if (v.getType() != XmlRpc::XmlRpcValue::TypeBoolean) {
    throw io::ConfigError("parameter '~" + key + "': expected true or false, got " + v.toXml());
  }
  return static_cast<bool>(const_cast<XmlRpc::XmlRpcValue&>(v));
}

}  // namespace

YAML::Node toYaml(const XmlRpc::XmlRpcValue& value) {
  auto& v = const_cast<XmlRpc::XmlRpcValue&>(value);  // XmlRpc's accessors are not const
  switch (v.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return YAML::Node(static_cast<bool>(v));
    case XmlRpc::XmlRpcValue::TypeInt:
      return YAML::Node(static_cast<int>(v));
    case XmlRpc::XmlRpcValue::TypeDouble:
      return YAML::Node(static_cast<double>(v));
    case XmlRpc::XmlRpcValue::TypeString:
      return YAML::Node(static_cast<std::string>(v));
    case XmlRpc::XmlRpcValue::TypeArray: {
      YAML::Node seq(YAML::NodeType::Sequence);
      for (int i = 0; i < v.size(); ++i) seq.push_back(toYaml(v[i]));
      return seq;
    }
    case XmlRpc::XmlRpcValue::TypeStruct: {
      YAML::Node map(YAML::NodeType::Map);
      for (auto it = v.begin(); it != v.end(); ++it) map[it->first] = toYaml(it->second);
      return map;
    }
    default:
      return YAML::Node();
  }
}

NodeParams readParams(const ros::NodeHandle& private_nh) {
  XmlRpc::XmlRpcValue all;
  if (!ros::param::get(private_nh.getNamespace(), all) || all.getType() != XmlRpc::XmlRpcValue::TypeStruct) {
    all = XmlRpc::XmlRpcValue();
    all.begin();  // an empty struct: no private parameters
  }
  NodeParams p;
  NodeSettings& n = p.node;
  for (const NodeParamKey& k : nodeParamKeys()) {
    const std::string key(k.key);
    if (!all.hasMember(key)) continue;
    if (k.number) *k.number(n) = numberParam(all[key], k);
    if (k.flag) *k.flag(n) = flagParam(all[key], key);
  }
  if (all.hasMember("world_frame")) {
    if (all["world_frame"].getType() != XmlRpc::XmlRpcValue::TypeString || std::string(all["world_frame"]).empty()) {
      throw io::ConfigError("parameter '~world_frame': expected a non-empty frame name");
    }
    n.world_frame = static_cast<std::string>(all["world_frame"]);
  }
  if (all.hasMember("body_states_twist")) {
    XmlRpc::XmlRpcValue& v = all["body_states_twist"];
    if (v.getType() != XmlRpc::XmlRpcValue::TypeString) {
      throw io::ConfigError("parameter '~body_states_twist': expected 'body' or 'world', got " + v.toXml());
    }
    const std::string twist = static_cast<std::string>(v);
    if (twist != "body" && twist != "world") {
      throw io::ConfigError("parameter '~body_states_twist' = '" + twist + "': expected 'body' or 'world'");
    }
    n.body_states_twist_in_world = twist == "world";
  }
  if (all.hasMember("config_file")) {
    if (all["config_file"].getType() != XmlRpc::XmlRpcValue::TypeString) {
      throw io::ConfigError("parameter '~config_file': expected a file path");
    }
    n.config_file = static_cast<std::string>(all["config_file"]);
    // The file roslaunch's <rosparam> loaded, read once more as rbsim reads
    // it, for what the parameter server cannot show: a key given twice
    // (PyYAML keeps the last silently) and aliases. Refused naming the line.
    io::loadYamlFile(n.config_file);
  }
  // Everything else is a simulation key: the same parser as rbsim's config.
  // A `bodies` list goes over an entry at a time, each let go once read: as
  // one YAML tree it held 7.5 KB a body (bench/HISTORY.md).
  YAML::Node sim(YAML::NodeType::Map);
  XmlRpc::XmlRpcValue* bodies = nullptr;
  for (auto it = all.begin(); it != all.end(); ++it) {
    if (findNodeParamKey(it->first) || it->first == "physics") continue;  // ~physics: dynamic_reconfigure's own
    if (it->first == "bodies" && it->second.getType() == XmlRpc::XmlRpcValue::TypeArray) {
      bodies = &it->second;
      continue;
    }
    sim[it->first] = toYaml(it->second);
  }
  const std::string base_dir = std::filesystem::path(n.config_file).parent_path().string();
  if (bodies) {
    const auto entry = [bodies](std::size_t i) {
      XmlRpc::XmlRpcValue& v = (*bodies)[static_cast<int>(i)];
      YAML::Node yaml = toYaml(v);
      v = XmlRpc::XmlRpcValue();  // read: let it go
      return yaml;
    };
    p.sim = io::parseConfigWithBodies(sim, static_cast<std::size_t>(bodies->size()), entry, base_dir);
  } else {
    p.sim = io::parseConfig(sim, base_dir);
  }
  p.sim_yaml = sim;
  return p;
}

}  // namespace rigid_body_sim::node
