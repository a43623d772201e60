// What the readers of a URDF's Gazebo markup share: gazebo_markup.h.
#include "gazebo_markup.h"

#include <algorithm>
#include <cctype>

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

}  // namespace rigid_body_sim::io::detail
