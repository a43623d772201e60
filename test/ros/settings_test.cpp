// Settings in one place (issue 32): every key of config/default.yaml and
// every entry of cfg/Physics.cfg maps to one settings field, by one name,
// with one range that the config parser, the model and the node all apply.
// No master needed.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/setting_keys.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/node_keys.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/ros/params.h"

namespace {

using rigid_body_sim::core::Model;
using rigid_body_sim::core::ModelSpec;
using rigid_body_sim::core::SettingKey;
using rigid_body_sim::node::NodeParamKey;
using rigid_body_sim::node::NodeSettings;
using Kind = SettingKey::Kind;

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// default.yaml's keys as "section.name" (or "name" at the top level), with
/// their values. `initial` and `scene` are the start state and the scene,
/// not settings, and `urdf` how the loaders read a URDF (UrdfKey below);
/// the devices are commented out there.
std::map<std::string, YAML::Node> defaultYamlKeys() {
  const YAML::Node root = YAML::LoadFile(std::string(RBS_SOURCE_DIR) + "/config/default.yaml");
  std::map<std::string, YAML::Node> keys;
  for (const auto& entry : root) {
    const std::string name = entry.first.as<std::string>();
    if (name == "initial" || name == "scene" || name == "urdf" || name == "devices") continue;
    if (entry.second.IsMap()) {
      for (const auto& inner : entry.second) keys[name + "." + inner.first.as<std::string>()] = inner.second;
    } else {
      keys[name] = entry.second;
    }
  }
  return keys;
}

/// A config of one key set to `value`, parsed and built as rbsim and the
/// node build one; the refusal's text, or "" when accepted.
std::string refusal(const SettingKey& k, const std::string& value) {
  std::string yaml;
  if (k.section().empty()) {
    yaml = std::string(k.key) + ": " + value;
  } else {
    yaml = std::string(k.section()) + ": {" + std::string(k.name()) + ": " + value + "}";
  }
  try {
    const rigid_body_sim::io::SimConfig c = rigid_body_sim::io::parseConfig(YAML::Load(yaml), "");
    const Model model(c.model);
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string text(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

// rbsim sets the node's own keys aside by io::nodeKeys(): the same keys,
// in the same order, as the node's parameter table.
TEST(Settings, TheNodeKeysRbsimSetsAsideAreTheNodesParameters) {
  std::vector<std::string> params;
  for (const NodeParamKey& k : rigid_body_sim::node::nodeParamKeys()) params.emplace_back(k.key);
  EXPECT_EQ(rigid_body_sim::io::nodeKeys(), params);
  EXPECT_TRUE(rigid_body_sim::io::isNodeKey("publish_rate"));
  EXPECT_FALSE(rigid_body_sim::io::isNodeKey("dt"));
}

// rbsim's odometry with no rate of its own reports at the node's
// ~publish_rate: its default is the node's, and a file's value is read.
TEST(Settings, RbsimReadsTheNodesPublishRateWithTheNodesDefault) {
  EXPECT_EQ(rigid_body_sim::io::SimConfig{}.publish_rate, rigid_body_sim::node::NodeSettings{}.publish_rate);
  std::vector<std::string> set_aside;
  EXPECT_EQ(rigid_body_sim::io::parseConfigText("publish_rate: 40\n", "config", {}, "", &set_aside).publish_rate, 40.0);
  EXPECT_EQ(set_aside, std::vector<std::string>{"publish_rate"});
  try {
    rigid_body_sim::io::parseConfigText("publish_rate: -1\n", "config", {}, "", &set_aside);
    ADD_FAILURE() << "a negative publish_rate was taken";
  } catch (const rigid_body_sim::io::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("publish_rate"), std::string::npos) << e.what();
  }
}

TEST(Settings, TheUrdfKeyIsTheLoadersDefault) {
  const YAML::Node root = YAML::LoadFile(std::string(RBS_SOURCE_DIR) + "/config/default.yaml");
  ASSERT_TRUE(root["urdf"].IsMap());
  ASSERT_EQ(root["urdf"].size(), 1u);
  EXPECT_EQ(root["urdf"]["repair"].as<bool>(), rigid_body_sim::io::SimConfig().urdf_repair);
  EXPECT_EQ(root["urdf"]["repair"].as<bool>(), rigid_body_sim::io::UrdfOptions().repair);
  EXPECT_FALSE(rigid_body_sim::io::parseConfig(YAML::Load("urdf: {repair: false}"), "").urdf_repair);
  EXPECT_THROW(rigid_body_sim::io::parseConfig(YAML::Load("urdf: {repiar: false}"), ""),
               rigid_body_sim::io::ConfigError);
}

TEST(Settings, TheDevicesKeyIsTheConfigsDefault) {
  const YAML::Node root = YAML::LoadFile(std::string(RBS_SOURCE_DIR) + "/config/default.yaml");
  ASSERT_TRUE(root["devices"].IsMap());
  ASSERT_EQ(root["devices"].size(), 1u);
  EXPECT_EQ(root["devices"]["memory"].as<std::uintmax_t>() << 20, rigid_body_sim::io::SimConfig().device_memory);
  EXPECT_EQ(rigid_body_sim::io::parseConfig(YAML::Load("devices: {memory: 3}"), "").device_memory, 3u << 20);
}

TEST(Settings, EveryKeyOfTheDefaultConfigIsOneSettingWithItsDefault) {
  const std::map<std::string, YAML::Node> yaml = defaultYamlKeys();
  ModelSpec defaults;  // the fields' own defaults, which no file sets
  for (const auto& [key, value] : yaml) {
    int found = 0;
    for (const SettingKey& k : rigid_body_sim::core::settingKeys()) found += k.key == key ? 1 : 0;
    ASSERT_EQ(found, 1) << key << " in config/default.yaml is not one settings key";
    const SettingKey& k = *rigid_body_sim::core::findSettingKey(key);
    // The file's default is the field's.
    if (k.number) {
      EXPECT_EQ(value.as<double>(), *k.number(defaults)) << key;
    }
    if (k.count) {
      EXPECT_EQ(value.as<int>(), *k.count(defaults)) << key;
    }
    if (k.flag) {
      EXPECT_EQ(value.as<bool>(), *k.flag(defaults)) << key;
    }
    if (k.vector) {
      for (int i = 0; i < 3; ++i) EXPECT_EQ(value[i].as<double>(), (*k.vector(defaults))[i]) << key;
    }
    if (k.kind == Kind::kChoice) {
      EXPECT_NE(std::string(k.choices).find(value.as<std::string>()), std::string::npos) << key;
    }
  }
  // And every setting is in the file, so the file documents them all.
  for (const SettingKey& k : rigid_body_sim::core::settingKeys()) {
    EXPECT_EQ(yaml.count(std::string(k.key)), 1u) << k.key << " is missing from config/default.yaml";
  }
}

TEST(Settings, EachRangeIsTheOneTheParserAndTheModelApply) {
  // At the edge of its range a value is accepted; just beyond, it is refused
  // with the key's name and that range, whoever checks it.
  int checked = 0;
  for (const SettingKey& k : rigid_body_sim::core::settingKeys()) {
    const std::string key(k.key);
    if (k.kind == Kind::kNumber) {
      const double low = k.min_open ? k.min : std::nextafter(k.min, -INFINITY);
      const std::string refused = refusal(k, text(low));
      EXPECT_EQ(refused.rfind(key + " = ", 0), 0u) << key << ": " << refused;
      EXPECT_NE(refused.find(k.range()), std::string::npos) << key << ": " << refused;
      if (!k.min_open) {
        EXPECT_EQ(refusal(k, text(k.min)), "") << key;
      }
      if (std::isfinite(k.max)) {
        EXPECT_EQ(refusal(k, text(k.max)), "") << key;
        const std::string high = refusal(k, text(std::nextafter(k.max, INFINITY)));
        EXPECT_EQ(high.rfind(key + " = ", 0), 0u) << key << ": " << high;
      }
      ++checked;
    } else if (k.kind == Kind::kCount) {
      EXPECT_EQ(refusal(k, text(k.min)), "") << key;
      EXPECT_EQ(refusal(k, text(k.max)), "") << key;
      for (const double beyond : {k.min - 1, k.max + 1}) {
        const std::string refused = refusal(k, text(beyond));
        EXPECT_EQ(refused.rfind(key + " = ", 0), 0u) << key << ": " << refused;
        EXPECT_NE(refused.find(k.range()), std::string::npos) << key << ": " << refused;
      }
      EXPECT_NE(refusal(k, "2.5"), "") << key;  // whole numbers only
      ++checked;
    } else if (k.kind == Kind::kVector) {
      EXPECT_EQ(refusal(k, "[0, 0, " + text(-k.max) + "]"), "") << key;
      EXPECT_EQ(refusal(k, "[0, 0, " + text(-std::nextafter(k.max, INFINITY)) + "]").rfind(key + " = ", 0), 0u);
      ++checked;
    }
  }
  EXPECT_GE(checked, 25);
}

TEST(Settings, AModelBuiltInCodeMeetsTheSameRange) {
  // contact.iterations was capped at 1e6 by the parser and at 1e4 by the
  // model; now both are the key's one range.
  const SettingKey& k = *rigid_body_sim::core::findSettingKey("contact.iterations");
  ModelSpec spec;
  *k.count(spec) = static_cast<int>(k.max) + 1;
  EXPECT_THROW(Model{spec}, std::invalid_argument);
  EXPECT_NE(refusal(k, text(k.max + 1)), "");
  *k.count(spec) = static_cast<int>(k.max);
  EXPECT_NO_THROW(Model{spec});
}

struct CfgEntry {
  std::string name, type;
  double value = 0.0;
  double min = -INFINITY, max = INFINITY;
};

/// The entries of cfg/Physics.cfg: `group.add("name", type, 0, "doc", default[, min, max])`.
std::vector<CfgEntry> cfgEntries() {
  const std::string cfg = read(std::string(RBS_SOURCE_DIR) + "/cfg/Physics.cfg");
  const std::regex add(R"re(\.add\("(\w+)",\s*(\w+),\s*0,\s*"[^"]*",\s*([^,)]+)(?:,\s*([^,)]+),\s*([^,)]+))?\))re");
  const std::map<std::string, double> names{{"W", 1e9}, {"-W", -1e9}, {"True", 1}, {"False", 0}};
  const auto value = [&](const std::string& s) { return names.count(s) ? names.at(s) : std::stod(s); };
  std::vector<CfgEntry> entries;
  for (auto it = std::sregex_iterator(cfg.begin(), cfg.end(), add); it != std::sregex_iterator(); ++it) {
    CfgEntry e;
    e.name = (*it)[1];
    e.type = (*it)[2];
    e.value = value((*it)[3]);
    if ((*it)[4].matched) {
      e.min = value((*it)[4]);
      e.max = value((*it)[5]);
    }
    entries.push_back(e);
  }
  return entries;
}

TEST(Settings, EveryLiveTuningEntryIsOneSettingByItsNameAndNeverNarrowsItsRange) {
  const std::vector<CfgEntry> entries = cfgEntries();
  ASSERT_GE(entries.size(), 10u);  // the regular expression read the file
  ModelSpec model_defaults;
  NodeSettings node_defaults;
  for (const CfgEntry& e : entries) {
    std::vector<std::string> matches;
    double in_code = NAN, lo = NAN, hi = NAN;
    for (const SettingKey& k : rigid_body_sim::core::settingKeys()) {
      if (k.reconfigureName() == e.name && k.number) {
        matches.push_back("config key " + std::string(k.key));
        in_code = *k.number(model_defaults);
        lo = k.min;
        hi = k.max;
      }
      for (int i = 0; i < 3 && k.vector; ++i) {
        if (k.reconfigureName() + "_" + "xyz"[i] == e.name) {
          matches.push_back("config key " + std::string(k.key) + "[" + std::to_string(i) + "]");
          in_code = (*k.vector(model_defaults))[i];
          lo = -k.max;
          hi = k.max;
        }
      }
    }
    if (const NodeParamKey* n = rigid_body_sim::node::findNodeParamKey(e.name)) {
      matches.push_back("parameter ~" + std::string(n->key));
      if (n->number) {
        in_code = *n->number(node_defaults);
        lo = n->zero_too ? 0.0 : n->min;
        hi = n->max;
      }
      if (n->flag) in_code = *n->flag(node_defaults) ? 1 : 0;
    }
    ASSERT_EQ(matches.size(), 1u) << e.name << " in cfg/Physics.cfg: " << ::testing::PrintToString(matches);
    EXPECT_EQ(e.value, in_code) << e.name << ": the cfg's default is not the setting's";
    if (e.type == "double_t") {
      // dynamic_reconfigure clamps to the cfg's bounds before the node sees a
      // value: they must lie outside the setting's range, which alone refuses.
      EXPECT_LT(e.min, lo) << e.name;
      EXPECT_GT(e.max, hi) << e.name;
    }
  }
}

TEST(Settings, EveryNodeParameterHasOneRange) {
  for (const NodeParamKey& k : rigid_body_sim::node::nodeParamKeys()) {
    if (!k.number) continue;
    const std::string key(k.key);
    EXPECT_NO_THROW(rigid_body_sim::node::checkNodeParam(k, k.min)) << key;
    EXPECT_NO_THROW(rigid_body_sim::node::checkNodeParam(k, k.max)) << key;
    for (const double beyond : {std::nextafter(k.min, -INFINITY), std::nextafter(k.max, INFINITY), double(NAN)}) {
      if (k.zero_too && beyond == 0.0) continue;
      try {
        rigid_body_sim::node::checkNodeParam(k, beyond);
        ADD_FAILURE() << key << " accepted " << beyond;
      } catch (const rigid_body_sim::io::ConfigError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("parameter '~" + key + "' = ", 0), 0u) << e.what();
      }
    }
  }
  EXPECT_NO_THROW(rigid_body_sim::node::checkNodeParam(*rigid_body_sim::node::findNodeParamKey("realtime_factor"), 0));
}

}  // namespace
