// The sensors of a URDF's Gazebo markup: gazebo_sensors.h.
#include "gazebo_sensors.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace rigid_body_sim::io::detail {

namespace {

std::string attribute(const TiXmlElement& e, const char* name) {
  const char* value = e.Attribute(name);
  return value != nullptr ? value : "";
}

/// The plugin of `sensor` this project runs: 1 laser (LaserScan), 2 Velodyne (PointCloud2), 0 none.
int pluginKind(const TiXmlElement& sensor, const TiXmlElement** plugin) {
  for (const TiXmlElement* p = sensor.FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin")) {
    const std::string file = attribute(*p, "filename");
    *plugin = p;
    if (file == "libgazebo_ros_laser.so" || file == "libgazebo_ros_gpu_laser.so") return 1;
    if (file == "libgazebo_ros_velodyne_laser.so" || file == "libgazebo_ros_velodyne_gpu_laser.so") return 2;
  }
  return 0;
}

/// Reads the numbers of elements under one sensor, each error naming its path.
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

}  // namespace

bool readsSensor(const TiXmlElement& sensor) {
  const std::string type = attribute(sensor, "type");
  const TiXmlElement* plugin = nullptr;
  return (type == "ray" || type == "gpu_ray") && pluginKind(sensor, &plugin) != 0;
}

std::vector<LidarEntry> gazeboLidars(const TiXmlElement& robot, const Unread& unread) {
  std::vector<LidarEntry> out;
  for (const TiXmlElement* g = robot.FirstChildElement("gazebo"); g; g = g->NextSiblingElement("gazebo")) {
    const std::string link = attribute(*g, "reference");
    if (link.empty()) continue;
    for (const TiXmlElement* s = g->FirstChildElement("sensor"); s; s = s->NextSiblingElement("sensor")) {
      if (!readsSensor(*s)) continue;
      const TiXmlElement* plugin = nullptr;
      const int kind = pluginKind(*s, &plugin);
      LidarEntry l;
      l.link = link;
      l.key = "<gazebo reference=\"" + link + "\"> <sensor name=\"" + attribute(*s, "name") + "\">";
      const Numbers numbers(l.key);
      core::LidarSettings& c = l.settings;
      c.min_angle = c.max_angle = 0.0;  // SDF's defaults: one ray straight ahead
      c.samples = 640;
      c.min_range = 0.0;  // <range><min> and <max> are required in SDF
      if (const TiXmlElement* pose = s->FirstChildElement("pose")) {
        const std::vector<double> p = numbers.read(*pose, "pose", 6);
        l.pose.translation = core::Vec3(p[0], p[1], p[2]);
        l.pose.rotation =
            core::Quat(Eigen::AngleAxisd(p[5], core::Vec3::UnitZ()) * Eigen::AngleAxisd(p[4], core::Vec3::UnitY()) *
                       Eigen::AngleAxisd(p[3], core::Vec3::UnitX()));
      }
      numbers.at(s, "update_rate", l.rate);
      if (l.rate == 0.0) {  // Gazebo's "every physics step": 10 Hz here, said
        l.rate = 10.0;
        unread("<sensor> <update_rate> 0 (read as 10 Hz)", link);
      }
      const TiXmlElement* ray = s->FirstChildElement("ray");
      for (const auto& [axis, samples, lo, hi] :
           {std::tuple{"horizontal", &c.samples, &c.min_angle, &c.max_angle},
            std::tuple{"vertical", &c.vertical_samples, &c.vertical_min_angle, &c.vertical_max_angle}}) {
        const std::string at = std::string("scan/") + axis + "/";
        if (Numbers::find(ray, std::string("scan/") + axis) == nullptr) continue;
        double n = *samples, resolution = 1.0;
        numbers.at(ray, at + "samples", n);
        numbers.at(ray, at + "resolution", resolution);
        *samples = static_cast<int>(std::lround(n * resolution));  // Gazebo: samples × resolution readings
        numbers.at(ray, at + "min_angle", *lo);
        numbers.at(ray, at + "max_angle", *hi);
      }
      numbers.at(ray, "range/min", c.min_range);
      numbers.at(ray, "range/max", c.max_range);
      numbers.at(ray, "noise/stddev", c.noise);
      double mean = 0.0;
      numbers.at(ray, "noise/mean", mean);
      if (mean != 0.0) unread("<sensor> <noise><mean>", link);
      if (const TiXmlElement* t = plugin->FirstChildElement("topicName"); t && t->GetText()) l.topic = t->GetText();
      if (const TiXmlElement* f = plugin->FirstChildElement("frameName"); f && f->GetText()) {
        l.frame_id = f->GetText();
      }
      if (kind == 2) {  // the Velodyne plugin's own range and noise
        if (l.topic == "scan") l.topic = "points";
        const Numbers own(l.key + " <plugin>");
        own.at(plugin, "min_range", c.min_range);
        own.at(plugin, "max_range", c.max_range);
        own.at(plugin, "gaussianNoise", c.noise);
      }
      out.push_back(std::move(l));
    }
  }
  return out;
}

}  // namespace rigid_body_sim::io::detail
