// What the readers of a URDF's Gazebo markup share (private to io): its
// attributes and texts, its numbers read as Gazebo reads them (an error
// naming the element), SDF's poses, and how each says what it does not run.
#pragma once

#include <tinyxml.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rigid_body_sim/core/bodies/geometry.h"

namespace rigid_body_sim::io::detail {

/// What a reader does not run is told here: (kind, link or name), one warning per kind.
using Unread = std::function<void(const std::string& kind, const std::string& name)>;

/// `e`'s attribute `name`, or "".
std::string attribute(const TiXmlElement& e, const char* name);

/// The text of `parent`'s child `name`, or `fallback`.
std::string childText(const TiXmlElement& parent, const char* name, const std::string& fallback);

/// childText of a tf frame id: one leading '/' dropped (as gazebo_ros's
/// tf::resolve drops it), the rest refused (std::invalid_argument naming
/// `where` and the element) unless io::frameIdProblem finds none; "" when
/// not given and `fallback` is "".
std::string childFrame(const TiXmlElement& parent, const char* name, const std::string& fallback,
                       const std::string& where);

/// childText of a topic: refused (std::invalid_argument naming `where` and
/// the element) unless ROS can name it: letters, digits, '_' and '/'.
std::string childTopic(const TiXmlElement& parent, const char* name, const std::string& fallback,
                       const std::string& where);

/// `parent`'s child `name` as SDF's bool ("true", "1"; "false", "0"), or `fallback`.
/// Throws std::invalid_argument naming `where` and the element for another text.
bool childFlag(const TiXmlElement& parent, const char* name, bool fallback, const std::string& where);

/// SDF's `<pose>` x y z roll pitch yaw: a translation, then fixed-axis rotations about x, y, z.
core::Pose sdfPose(const std::vector<double>& p);

/// The range a number of the markup must be in: [lo, hi], or (lo, hi] when
/// `lo_open`; `unit` for the refusal ("Hz"). The bounds come from
/// core/bodies/ranges.h, as the config's keys do.
struct Bounds {
  double lo;
  double hi;
  bool lo_open = false;
  const char* unit = "";
  /// "> 0 N*m", ">= 0", "within [0.01, 10000] Hz".
  std::string words() const;
};

/// At most the first 60 characters of a markup's text, for a refusal.
std::string shownText(const char* text);

/// Reads the numbers of elements under one sensor or plugin, each error naming its path.
class Numbers {
 public:
  explicit Numbers(std::string where) : where_(std::move(where)) {}
  /// The numbers of `e`'s text (`count` of them), or throws naming `path`.
  std::vector<double> read(const TiXmlElement& e, const std::string& path, std::size_t count) const;
  /// `path` (a/b/c) under `root`, if there, into `x`.
  void at(const TiXmlElement* root, const std::string& path, double& x) const {
    if (const TiXmlElement* e = find(root, path)) x = read(*e, path, 1)[0];
  }
  /// The same, refused naming `path` unless within `bounds`.
  void at(const TiXmlElement* root, const std::string& path, double& x, const Bounds& bounds) const;
  /// A rate (Hz), if there, into `hz`: 0 (Gazebo's "as fast as it can"),
  /// or within the publish rates of core/bodies/ranges.h.
  void rate(const TiXmlElement* root, const std::string& path, double& hz) const;
  /// A whole number (no fraction) within `bounds`, if there, into `n`.
  void count(const TiXmlElement* root, const std::string& path, int& n, const Bounds& bounds) const;
  static const TiXmlElement* find(const TiXmlElement* root, const std::string& path);
  /// Throws std::invalid_argument: "WHERE <path> = 'text': why".
  [[noreturn]] void fail(const std::string& path, const char* text, const std::string& why) const;

 private:
  std::string where_;
};

}  // namespace rigid_body_sim::io::detail
