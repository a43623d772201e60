// What the readers of a URDF's Gazebo markup share: gazebo_markup.h.
#include "gazebo_markup.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::io::detail {

std::string attribute(const TiXmlElement& e, const char* name) {
  const char* value = e.Attribute(name);
  return value != nullptr ? value : "";
}

std::string childText(const TiXmlElement& parent, const char* name, const std::string& fallback) {
  const TiXmlElement* e = parent.FirstChildElement(name);
  return e != nullptr && e->GetText() != nullptr ? e->GetText() : fallback;
}

std::string childTopic(const TiXmlElement& parent, const char* name, const std::string& fallback,
                       const std::string& where) {
  std::string topic = childText(parent, name, fallback);
  const bool named = !topic.empty() && std::all_of(topic.begin(), topic.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/';
  });
  if (!named) throw std::invalid_argument(where + " <" + name + "> = '" + topic + "': no ROS topic name");
  return topic;
}

std::string childFrame(const TiXmlElement& parent, const char* name, const std::string& fallback,
                       const std::string& where) {
  std::string frame = childText(parent, name, fallback);
  if (frame.empty() && fallback.empty()) return frame;
  if (frame.size() > 1 && frame.front() == '/') frame.erase(0, 1);
  if (const std::string problem = frameIdProblem(frame); !problem.empty()) {
    throw std::invalid_argument(where + " <" + name + ">: " + problem);
  }
  return frame;
}

bool childFlag(const TiXmlElement& parent, const char* name, bool fallback, const std::string& where) {
  const TiXmlElement* e = parent.FirstChildElement(name);
  if (e == nullptr || e->GetText() == nullptr) return fallback;
  const std::string text = e->GetText();
  if (text == "true" || text == "1") return true;
  if (text == "false" || text == "0") return false;
  throw std::invalid_argument(where + " <" + name + "> = '" + text + "': not true or false");
}

core::Pose sdfPose(const std::vector<double>& p) {
  core::Pose X;
  X.translation = core::Vec3(p[0], p[1], p[2]);
  X.rotation = core::Quat(Eigen::AngleAxisd(p[5], core::Vec3::UnitZ()) * Eigen::AngleAxisd(p[4], core::Vec3::UnitY()) *
                          Eigen::AngleAxisd(p[3], core::Vec3::UnitX()));
  return X;
}

std::string Bounds::words() const {
  const auto num = [](double x) {
    std::ostringstream os;
    os << x;
    return os.str();
  };
  const std::string u = *unit != '\0' ? std::string(" ") + unit : "";
  if (std::isinf(hi)) return (lo_open ? "> " : ">= ") + num(lo) + u;
  return std::string("within ") + (lo_open ? "(" : "[") + num(lo) + ", " + num(hi) + "]" + u;
}

std::string shownText(const char* text) {
  const std::string t = text != nullptr ? text : "";
  return t.size() <= 60 ? t : t.substr(0, 60) + "...";
}

std::vector<double> Numbers::read(const TiXmlElement& e, const std::string& path, std::size_t count) const {
  const char* text = e.GetText();
  std::istringstream in(text != nullptr ? text : "");
  std::vector<double> out;
  std::string word;
  while (out.size() <= count && in >> word) {
    char* end = nullptr;
    const double x = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0' || !std::isfinite(x))
      fail(path, text, "not the number(s) Gazebo reads there");
    out.push_back(x);
  }
  if (out.size() != count) fail(path, text, "not the number(s) Gazebo reads there");
  return out;
}

void Numbers::at(const TiXmlElement* root, const std::string& path, double& x, const Bounds& b) const {
  const TiXmlElement* e = find(root, path);
  if (e == nullptr) return;
  const double v = read(*e, path, 1)[0];
  if (!(b.lo_open ? v > b.lo : v >= b.lo) || !(v <= b.hi)) fail(path, e->GetText(), "must be " + b.words());
  x = v;
}

void Numbers::rate(const TiXmlElement* root, const std::string& path, double& hz) const {
  const TiXmlElement* e = find(root, path);
  if (e == nullptr) return;
  const Bounds publish{core::ranges::kMinRate, core::ranges::kMaxPublishRate, false, "Hz"};
  const double v = read(*e, path, 1)[0];
  if (v != 0.0 && !(v >= publish.lo && v <= publish.hi)) {
    fail(path, e->GetText(), "must be 0 (as fast as it can) or " + publish.words());
  }
  hz = v;
}

void Numbers::count(const TiXmlElement* root, const std::string& path, int& n, const Bounds& b) const {
  const TiXmlElement* e = find(root, path);
  if (e == nullptr) return;
  double v = 0.0;
  at(root, path, v, b);
  if (v != std::floor(v)) fail(path, e->GetText(), "must be a whole number " + b.words());
  n = static_cast<int>(v);  // within bounds, which are ints
}

const TiXmlElement* Numbers::find(const TiXmlElement* root, const std::string& path) {
  std::istringstream parts(path);
  std::string part;
  const TiXmlElement* e = root;
  while (e != nullptr && std::getline(parts, part, '/')) e = e->FirstChildElement(part.c_str());
  return e;
}

void Numbers::fail(const std::string& path, const char* text, const std::string& why) const {
  throw std::invalid_argument(where_ + " <" + path + "> = '" + shownText(text) + "': " + why);
}

}  // namespace rigid_body_sim::io::detail
