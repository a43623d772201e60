// What the readers of a URDF's Gazebo markup share (private to io): its
// attributes and texts, its numbers read as Gazebo reads them (an error
// naming the element), SDF's poses, and how each says what it does not run.
#pragma once

#include <tinyxml.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/geometry.h"

namespace rigid_body_sim::io::detail {

/// What a reader does not run is told here: (kind, link or name), one warning per kind.
using Unread = std::function<void(const std::string& kind, const std::string& name)>;

/// `e`'s attribute `name`, or "".
std::string attribute(const TiXmlElement& e, const char* name);

/// The text of `parent`'s child `name`, or `fallback`.
std::string childText(const TiXmlElement& parent, const char* name, const std::string& fallback);

/// childText of a topic: refused (std::invalid_argument naming `where` and
/// the element) unless ROS can name it: letters, digits, '_' and '/'.
std::string childTopic(const TiXmlElement& parent, const char* name, const std::string& fallback,
                       const std::string& where);

/// `parent`'s child `name` as SDF's bool ("true", "1"; "false", "0"), or `fallback`.
/// Throws std::invalid_argument naming `where` and the element for another text.
bool childFlag(const TiXmlElement& parent, const char* name, bool fallback, const std::string& where);

/// SDF's `<pose>` x y z roll pitch yaw: a translation, then fixed-axis rotations about x, y, z.
core::Pose sdfPose(const std::vector<double>& p);

/// Reads the numbers of elements under one sensor or plugin, each error naming its path.
class Numbers {
 public:
  explicit Numbers(std::string where) : where_(std::move(where)) {}
  /// The numbers of `e`'s text (`count` of them), or throws naming `path`.
  std::vector<double> read(const TiXmlElement& e, const std::string& path, std::size_t count) const {
    const char* text = e.GetText();
    std::istringstream in(text != nullptr ? text : "");
    std::vector<double> out;
    std::string word;
    while (in >> word) {
      char* end = nullptr;
      const double x = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0' || !std::isfinite(x)) fail(path, text);
      out.push_back(x);
    }
    if (out.size() != count) fail(path, text);
    return out;
  }
  /// `path` (a/b/c) under `root`, if there, into `x`.
  void at(const TiXmlElement* root, const std::string& path, double& x) const {
    if (const TiXmlElement* e = find(root, path)) x = read(*e, path, 1)[0];
  }
  static const TiXmlElement* find(const TiXmlElement* root, const std::string& path) {
    std::istringstream parts(path);
    std::string part;
    const TiXmlElement* e = root;
    while (e != nullptr && std::getline(parts, part, '/')) e = e->FirstChildElement(part.c_str());
    return e;
  }

 private:
  [[noreturn]] void fail(const std::string& path, const char* text) const {
    throw std::invalid_argument(where_ + " <" + path + "> = '" + (text != nullptr ? text : "") +
                                "': not the number(s) Gazebo reads there");
  }
  std::string where_;
};

}  // namespace rigid_body_sim::io::detail
