#include "rigid_body_sim/ros/params.h"

#include <ros/console.h>
#include <ros/param.h>

#include <filesystem>
#include <set>
#include <sstream>

namespace rigid_body_sim::node {
namespace {

double positive(const XmlRpc::XmlRpcValue& v, const std::string& key, bool allow_zero) {
  double x = 0.0;
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
    x = static_cast<double>(const_cast<XmlRpc::XmlRpcValue&>(v));
  } else if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    x = static_cast<int>(const_cast<XmlRpc::XmlRpcValue&>(v));
  } else {
    throw io::ConfigError("parameter '~" + key + "': expected a number, got " + v.toXml());
  }
  if (!std::isfinite(x) || x < 0.0 || (!allow_zero && x == 0.0)) {
    std::ostringstream os;
    os << x;
    throw io::ConfigError("parameter '~" + key + "' = " + os.str() + ": must be finite and " +
                          (allow_zero ? ">= 0" : "> 0"));
  }
  return x;
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
  const std::set<std::string> node_keys{"rate",        "realtime_factor", "publish_rate",
                                        "world_frame", "wrench_timeout",  "covariance",
                                        "scene_size",  "report_timing",   "config_file"};
  if (all.hasMember("rate")) n.rate = positive(all["rate"], "rate", false);
  if (all.hasMember("realtime_factor")) n.realtime_factor = positive(all["realtime_factor"], "realtime_factor", true);
  if (all.hasMember("publish_rate")) n.publish_rate = positive(all["publish_rate"], "publish_rate", false);
  if (all.hasMember("world_frame")) {
    if (all["world_frame"].getType() != XmlRpc::XmlRpcValue::TypeString || std::string(all["world_frame"]).empty()) {
      throw io::ConfigError("parameter '~world_frame': expected a non-empty frame name");
    }
    n.world_frame = static_cast<std::string>(all["world_frame"]);
  }
  if (all.hasMember("wrench_timeout")) {
    auto& v = all["wrench_timeout"];
    const double x = v.getType() == XmlRpc::XmlRpcValue::TypeInt ? static_cast<int>(v) : static_cast<double>(v);
    if (!std::isfinite(x)) throw io::ConfigError("parameter '~wrench_timeout': must be finite");
    n.wrench_timeout = x;
  }
  if (all.hasMember("covariance")) n.covariance = positive(all["covariance"], "covariance", true);
  if (all.hasMember("scene_size")) n.scene_size = positive(all["scene_size"], "scene_size", false);
  if (all.hasMember("report_timing")) {
    if (all["report_timing"].getType() != XmlRpc::XmlRpcValue::TypeBoolean) {
      throw io::ConfigError("parameter '~report_timing': expected true or false");
    }
    n.report_timing = static_cast<bool>(all["report_timing"]);
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
