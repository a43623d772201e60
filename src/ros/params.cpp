#include "rigid_body_sim/ros/params.h"

#include <ros/console.h>
#include <ros/param.h>

#include <filesystem>
#include <set>
#include <sstream>

namespace rigid_body_sim::node {

void requireParamWithin(double x, const std::string& key, double lo, double hi, const std::string& unit) {
  if (!std::isfinite(x) || x < lo || x > hi) {
    std::ostringstream os;
    os << "parameter '~" << key << "' = " << x << ": must be within [" << lo << ", " << hi << "]"
       << (unit.empty() ? "" : " " + unit);
    throw io::ConfigError(os.str());
  }
}

void requireRealtimeFactor(double x) {
  using R = NodeSettings;
  if (x == 0.0) return;
  if (!std::isfinite(x) || x < R::kMinRealtimeFactor || x > R::kMaxRealtimeFactor) {
    std::ostringstream os;
    os << "parameter '~realtime_factor' = " << x << ": must be 0 (as fast as possible) or within ["
       << R::kMinRealtimeFactor << ", " << R::kMaxRealtimeFactor << "]";
    throw io::ConfigError(os.str());
  }
}

namespace {

/// A number parameter within [lo, hi]: anything outside is refused with the
/// range (a rate of 1e-9 Hz would sleep 30 years between ticks and never
/// answer SIGINT; 1e300 would spin the loop at full CPU).
double number(const XmlRpc::XmlRpcValue& v, const std::string& key, double lo, double hi, const std::string& unit) {
  double x = 0.0;
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
    x = static_cast<double>(const_cast<XmlRpc::XmlRpcValue&>(v));
  } else if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    x = static_cast<int>(const_cast<XmlRpc::XmlRpcValue&>(v));
  } else {
    throw io::ConfigError("parameter '~" + key + "': expected a number, got " + v.toXml());
  }
  requireParamWithin(x, key, lo, hi, unit);
  return x;
}

bool flag(const XmlRpc::XmlRpcValue& v, const std::string& key) {
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
  const std::set<std::string> node_keys{
      "rate",       "realtime_factor", "publish_rate", "world_frame", "wrench_timeout",   "covariance",
      "scene_size", "report_timing",   "config_file",  "publish_tf",  "body_states_rate", "body_states_twist",
      "paused",     "per_body_topics", "physics"};  // ~physics: the dynamic_reconfigure server's own
  using R = NodeSettings;
  if (all.hasMember("rate")) n.rate = number(all["rate"], "rate", R::kMinRate, R::kMaxRate, "Hz");
  if (all.hasMember("realtime_factor")) {
    n.realtime_factor = number(all["realtime_factor"], "realtime_factor", 0.0, R::kMaxRealtimeFactor, "");
    requireRealtimeFactor(n.realtime_factor);
  }
  if (all.hasMember("publish_rate")) {
    n.publish_rate = number(all["publish_rate"], "publish_rate", R::kMinPublishRate, R::kMaxRate, "Hz");
  }
  if (all.hasMember("world_frame")) {
    if (all["world_frame"].getType() != XmlRpc::XmlRpcValue::TypeString || std::string(all["world_frame"]).empty()) {
      throw io::ConfigError("parameter '~world_frame': expected a non-empty frame name");
    }
    n.world_frame = static_cast<std::string>(all["world_frame"]);
  }
  if (all.hasMember("wrench_timeout")) {
    n.wrench_timeout =
        number(all["wrench_timeout"], "wrench_timeout", 0.0, R::kMaxDuration, "s (0: held until cleared)");
  }
  if (all.hasMember("covariance")) n.covariance = number(all["covariance"], "covariance", 0.0, 1e6, "");
  if (all.hasMember("scene_size")) n.scene_size = number(all["scene_size"], "scene_size", 1e-3, 1e6, "m");
  if (all.hasMember("report_timing")) n.report_timing = flag(all["report_timing"], "report_timing");
  if (all.hasMember("publish_tf")) n.publish_tf = flag(all["publish_tf"], "publish_tf");
  if (all.hasMember("paused")) n.paused = flag(all["paused"], "paused");
  if (all.hasMember("per_body_topics")) {
    n.per_body_topics = number(all["per_body_topics"], "per_body_topics", 0.0, 1e9, "bodies");
  }
  if (all.hasMember("body_states_rate")) {
    n.body_states_rate = number(all["body_states_rate"], "body_states_rate", R::kMinPublishRate, R::kMaxRate, "Hz");
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
  }
  // Everything else is a simulation key: the same parser as rbsim's config.
  YAML::Node sim(YAML::NodeType::Map);
  for (auto it = all.begin(); it != all.end(); ++it) {
    if (!node_keys.count(it->first)) sim[it->first] = toYaml(it->second);
  }
  p.sim = io::parseConfig(sim, std::filesystem::path(n.config_file).parent_path().string());
  p.sim_yaml = sim;
  return p;
}

}  // namespace rigid_body_sim::node
