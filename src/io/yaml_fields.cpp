// The config parser's typed fields (yaml_fields.h).
#include "yaml_fields.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/orientation.h"

namespace rigid_body_sim::io::yaml_fields {

using core::Quat;
using core::Vec3;

std::string show(const YAML::Node& node) {
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

[[noreturn]] void fail(const std::string& key, const std::string& why) {
  throw ConfigError("config key '" + key + "': " + why);
}

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

void requireKnownKeys(const YAML::Node& map, const std::string& path, const std::set<std::string>& known) {
  if (!map.IsMap()) fail(path.empty() ? "<root>" : path, "expected a map, got " + show(map));
  for (const auto& kv : map) {
    if (!kv.first.IsScalar()) fail(path.empty() ? "<root>" : path, "a key must be a plain name, got " + show(kv.first));
    const std::string key = kv.first.as<std::string>();
    if (!known.count(key)) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      fail(join(path, key), "unknown key (known here: " + list + ")");
    }
  }
}

namespace {

/// Levenshtein distance between `a` and `b`, or 3 once it is past 2.
int editsUpTo2(const std::string& a, const std::string& b) {
  if (a.size() > b.size() + 2 || b.size() > a.size() + 2) return 3;
  std::vector<int> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return std::min(row[b.size()], 3);
}

}  // namespace

std::vector<std::string> keysNotRead(const YAML::Node& map, const std::string& path,
                                     const std::set<std::string>& known) {
  if (!map.IsMap()) fail(path.empty() ? "<root>" : path, "expected a map, got " + show(map));
  std::vector<std::string> out;
  for (const auto& kv : map) {
    if (!kv.first.IsScalar()) fail(path.empty() ? "<root>" : path, "a key must be a plain name, got " + show(kv.first));
    const std::string key = kv.first.as<std::string>();
    if (known.count(key)) continue;
    for (const std::string& k : known) {
      if (key.size() >= 4 && editsUpTo2(key, k) <= 2) fail(join(path, key), "unknown key: did you mean " + k + "?");
    }
    out.push_back(join(path, key));
  }
  return out;
}

double number(const YAML::Node& node, const std::string& key) {
  double x = 0.0;
  try {
    if (!node.IsScalar()) throw YAML::Exception(YAML::Mark(), "");
    x = node.as<double>();
  } catch (const YAML::Exception&) {
    fail(key, "expected a number, got " + show(node));
  }
  if (!std::isfinite(x)) fail(key, "expected a finite number, got " + show(node));
  return x;
}

Vec3 vec3(const YAML::Node& node, const std::string& key) {
  if (!node.IsSequence() || node.size() != 3) fail(key, "expected [x, y, z], got " + show(node));
  return {number(node[0], key + "[0]"), number(node[1], key + "[1]"), number(node[2], key + "[2]")};
}

bool boolean(const YAML::Node& node, const std::string& key) {
  try {
    if (node.IsScalar()) return node.as<bool>();
  } catch (const YAML::Exception&) {
  }
  fail(key, "expected true or false, got " + show(node));
}

double positiveNumber(const YAML::Node& node, const std::string& key) {
  const double x = number(node, key);
  if (!(x > 0.0)) fail(key, "must be > 0, got " + show(node));
  return x;
}

double publishRate(const YAML::Node& node, const std::string& key) {
  const double x = number(node, key);
  if (!(x >= core::ranges::kMinRate && x <= core::ranges::kMaxPublishRate)) {
    std::ostringstream why;
    why << "must be within [" << core::ranges::kMinRate << ", " << core::ranges::kMaxPublishRate << "] Hz, got "
        << show(node);
    fail(key, why.str());
  }
  return x;
}

int integer(const YAML::Node& node, const std::string& key) {
  const double x = number(node, key);
  if (x != std::floor(x) || std::abs(x) > 1e9) fail(key, "expected a whole number, got " + show(node));
  return static_cast<int>(x);
}

Quat orientation(const YAML::Node& node, const std::string& path) {
  if (node["rpy"] && node["quaternion"]) fail(path, "give " + path + ".rpy or " + path + ".quaternion, not both");
  if (node["rpy"]) return quaternionFromRpy(vec3(node["rpy"], join(path, "rpy")));
  if (!node["quaternion"]) return Quat::Identity();
  const YAML::Node q = node["quaternion"];
  const std::string key = join(path, "quaternion");
  if (!q.IsSequence() || q.size() != 4) fail(key, "expected [x, y, z, w], got " + show(q));
  const Quat value = quaternionFromXyzw(number(q[0], key + "[0]"), number(q[1], key + "[1]"), number(q[2], key + "[2]"),
                                        number(q[3], key + "[3]"));
  if (std::abs(value.norm() - 1.0) > 1e-3) {
    std::ostringstream os;
    os << value.norm();
    fail(key, "norm " + os.str() + " is not 1 (within 1e-3): " + show(q));
  }
  return value.normalized();
}

std::string text(const YAML::Node& node, const std::string& key) {
  if (!node.IsScalar() || node.as<std::string>().empty()) fail(key, "expected a non-empty string, got " + show(node));
  return node.as<std::string>();
}

std::string frameId(const YAML::Node& node, const std::string& key) {
  std::string frame = text(node, key);
  if (const std::string problem = frameIdProblem(frame); !problem.empty()) fail(key, problem);
  return frame;
}

}  // namespace rigid_body_sim::io::yaml_fields
