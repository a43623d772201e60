// Reading typed fields from a YAML config, each error naming its key (the
// config parser's own helpers; private to io).
#pragma once

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::io::yaml_fields {

/// The node as one line of flow YAML, for messages.
std::string show(const YAML::Node& node);
/// Throws ConfigError "config key 'KEY': WHY".
[[noreturn]] void fail(const std::string& key, const std::string& why);
/// "path.key" ("key" at the root).
std::string join(const std::string& path, const std::string& key);
/// Refuses keys outside `known` (a typo must not silently fall back to a default).
void requireKnownKeys(const YAML::Node& map, const std::string& path, const std::set<std::string>& known);
/// The keys of `map` outside `known` that a controller's YAML may carry for
/// others to read (ROS parameters nobody reads are no error in ROS): each
/// "path.key". A key within two edits of a known one is refused as the typo
/// it most likely is, naming the one it resembles.
std::vector<std::string> keysNotRead(const YAML::Node& map, const std::string& path,
                                     const std::set<std::string>& known);
double number(const YAML::Node& node, const std::string& key);  ///< finite
double positiveNumber(const YAML::Node& node, const std::string& key);
double publishRate(const YAML::Node& node, const std::string& key);  ///< Hz, within ranges' publish rates
int integer(const YAML::Node& node, const std::string& key);         ///< a number with no fraction, |x| <= 1e9
core::Vec3 vec3(const YAML::Node& node, const std::string& key);     ///< [x, y, z]
bool boolean(const YAML::Node& node, const std::string& key);
/// `path.rpy` or `path.quaternion` ([x, y, z, w], unit within 1e-3), or the identity.
core::Quat orientation(const YAML::Node& node, const std::string& path);
std::string text(const YAML::Node& node, const std::string& key);     ///< non-empty
std::string frameId(const YAML::Node& node, const std::string& key);  ///< a tf frame id (io::frameIdProblem)

}  // namespace rigid_body_sim::io::yaml_fields
