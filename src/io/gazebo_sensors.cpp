// The sensors of a URDF's Gazebo markup: gazebo_sensors.h.
#include "gazebo_sensors.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
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

/// The plugin of `sensor` this project runs: 1 laser (LaserScan), 2 Velodyne (PointCloud2), 3 IMU, 0 none.
int pluginKind(const TiXmlElement& sensor, const TiXmlElement** plugin) {
  const std::string type = attribute(sensor, "type");
  const bool ray = type == "ray" || type == "gpu_ray";
  for (const TiXmlElement* p = sensor.FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin")) {
    const std::string file = attribute(*p, "filename");
    *plugin = p;
    if (ray && (file == "libgazebo_ros_laser.so" || file == "libgazebo_ros_gpu_laser.so")) return 1;
    if (ray && (file == "libgazebo_ros_velodyne_laser.so" || file == "libgazebo_ros_velodyne_gpu_laser.so")) return 2;
    if (type == "imu" && file == "libgazebo_ros_imu_sensor.so") return 3;
  }
  return 0;
}

/// A model plugin (`<gazebo><plugin>`) this project runs: gazebo_ros_imu, gazebo_ros_p3d.
bool readsModelPlugin(const TiXmlElement& plugin) {
  const std::string file = attribute(plugin, "filename");
  return file == "libgazebo_ros_imu.so" || file == "libgazebo_ros_p3d.so";
}

/// The text of `parent`'s child `name`, or `fallback`.
std::string childText(const TiXmlElement& parent, const char* name, const std::string& fallback) {
  const TiXmlElement* e = parent.FirstChildElement(name);
  return e != nullptr && e->GetText() != nullptr ? e->GetText() : fallback;
}

/// SDF's `<pose>` x y z roll pitch yaw: a translation, then fixed-axis rotations about x, y, z.
core::Pose sdfPose(const std::vector<double>& p) {
  core::Pose X;
  X.translation = core::Vec3(p[0], p[1], p[2]);
  X.rotation = core::Quat(Eigen::AngleAxisd(p[5], core::Vec3::UnitZ()) * Eigen::AngleAxisd(p[4], core::Vec3::UnitY()) *
                          Eigen::AngleAxisd(p[3], core::Vec3::UnitX()));
  return X;
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

bool readsMarkup(const TiXmlElement& e) {
  const std::string tag = e.Value();
  const TiXmlElement* plugin = nullptr;
  if (tag == "sensor") return pluginKind(e, &plugin) != 0;
  return tag == "plugin" && readsModelPlugin(e);
}

namespace {

/// The IMU of `<sensor type="imu">` on `link` with gazebo_ros_imu_sensor:
/// its `<pose>`; the plugin's `updateRateHZ` (1 Hz when not given, as the
/// plugin's default; 0: each sensor update) under the sensor's
/// `<update_rate>` (0: every step); `gaussianNoise` on every reading, with
/// the sensor's own `<imu>` noise σ; `topicName` ("imu_data"), `frameName`.
ImuEntry sensorImu(const TiXmlElement& s, const TiXmlElement& plugin, const std::string& link, const Unread& unread) {
  ImuEntry imu;
  imu.link = link;
  imu.key = "<gazebo reference=\"" + link + "\"> <sensor name=\"" + attribute(s, "name") + "\">";
  const Numbers numbers(imu.key);
  core::ImuSettings& c = imu.settings;
  if (const TiXmlElement* pose = s.FirstChildElement("pose")) c.X_LS = sdfPose(numbers.read(*pose, "pose", 6));
  double sensor_rate = 0.0, plugin_rate = 1.0;
  numbers.at(&s, "update_rate", sensor_rate);
  Numbers(imu.key + " <plugin>").at(&plugin, "updateRateHZ", plugin_rate);
  const auto every = [](double hz) { return hz > 0.0 ? hz : std::numeric_limits<double>::infinity(); };
  c.rate = std::min(every(sensor_rate), every(plugin_rate));  // capped at one a step when mounted
  double sigma = 0.0, own = 0.0;
  Numbers(imu.key + " <plugin>").at(&plugin, "gaussianNoise", sigma);
  for (const char* axis : {"x", "y", "z"}) {  // SDF's per-axis noise: the largest σ
    double gyro = 0.0, accel = 0.0;
    numbers.at(&s, std::string("imu/angular_velocity/") + axis + "/noise/stddev", gyro);
    numbers.at(&s, std::string("imu/linear_acceleration/") + axis + "/noise/stddev", accel);
    own = std::max({own, gyro, accel});
  }
  c.gyro_noise = c.accel_noise = std::hypot(sigma, own);
  c.orientation_noise = sigma;
  imu.topic = childText(plugin, "topicName", "imu_data");
  imu.frame_id = childText(plugin, "frameName", "");
  double offset = 0.0;
  for (const char* name : {"rpyOffset", "rpyOffsets"}) {
    if (const TiXmlElement* e = plugin.FirstChildElement(name)) {
      for (double x : Numbers(imu.key + " <plugin>").read(*e, name, 3)) offset = std::max(offset, std::abs(x));
    }
  }
  if (offset != 0.0) unread("<plugin> libgazebo_ros_imu_sensor.so <rpyOffset>", link);
  return imu;
}

/// The IMU of gazebo_ros_imu's model plugin: on `bodyName`, `updateRate`
/// (0 or none: every step), `gaussianNoise`, `topicName` ("/default_imu"),
/// `frameName` (bodyName). Its readings follow REP 145 here: the plugin's
/// own leave gravity out of the acceleration.
ImuEntry pluginImu(const TiXmlElement& plugin, const std::string& link, const Unread& unread) {
  ImuEntry imu;
  imu.key = "<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">";
  imu.link = link;
  const Numbers numbers(imu.key);
  double rate = 0.0, sigma = 0.0;
  numbers.at(&plugin, "updateRate", rate);
  numbers.at(&plugin, "gaussianNoise", sigma);
  imu.settings.rate = rate > 0.0 ? rate : std::numeric_limits<double>::infinity();
  imu.settings.gyro_noise = imu.settings.accel_noise = sigma;
  imu.topic = childText(plugin, "topicName", "/default_imu");
  imu.frame_id = childText(plugin, "frameName", imu.link);
  if (plugin.FirstChildElement("rpyOffset") != nullptr || plugin.FirstChildElement("rpyOffsets") != nullptr) {
    unread("<plugin> libgazebo_ros_imu.so <rpyOffset>", imu.link);
  }
  return imu;
}

/// The odometry of gazebo_ros_p3d's model plugin: `bodyName` on
/// `topicName` ("odom"), at `updateRate` (0 or none: every step), its
/// `gaussianNoise` on the pose and the twist (p3d puts it on the twist
/// alone, and the covariances on both), in the world frame (a `frameName`
/// naming a link is read as the world, and said).
OdometryEntry pluginOdometry(const TiXmlElement& plugin, const std::string& link, const Unread& unread) {
  OdometryEntry o;
  o.key = "<gazebo> <plugin name=\"" + attribute(plugin, "name") + "\">";
  o.link = link;
  const Numbers numbers(o.key);
  double rate = 0.0, sigma = 0.0;
  numbers.at(&plugin, "updateRate", rate);
  numbers.at(&plugin, "gaussianNoise", sigma);
  o.rate = rate > 0.0 ? rate : std::numeric_limits<double>::infinity();
  if (sigma > 0.0) o.noise = core::OdomNoiseSettings{sigma, sigma, sigma, sigma, 0.0, 0.0, 0.0, 0};
  o.topic = childText(plugin, "topicName", "odom");
  const std::string frame = childText(plugin, "frameName", "world");
  if (frame != "world" && frame != "/world" && frame != "map" && frame != "/map") {
    unread("<plugin> libgazebo_ros_p3d.so <frameName> of a link (read as the world)", link);
  }
  for (const char* name : {"xyzOffsets", "rpyOffsets", "xyzOffset", "rpyOffset"}) {
    if (const TiXmlElement* e = plugin.FirstChildElement(name)) {
      for (double x : numbers.read(*e, name, 3)) {
        if (x != 0.0) unread(std::string("<plugin> libgazebo_ros_p3d.so <") + name + ">", link);
      }
    }
  }
  return o;
}

/// A model plugin's sensor into `out`; one without its `bodyName` is told
/// to `unread`, as Gazebo does not run it.
void readModelPlugin(const TiXmlElement& plugin, const Unread& unread, LinkSensors& out) {
  const std::string file = attribute(plugin, "filename");
  const std::string link = childText(plugin, "bodyName", "");
  if (link.empty()) {
    unread("<plugin> " + file + " without <bodyName> (Gazebo does not run it)", attribute(plugin, "name"));
  } else if (file == "libgazebo_ros_imu.so") {
    out.imus.push_back(pluginImu(plugin, link, unread));
  } else {
    out.odometry.push_back(pluginOdometry(plugin, link, unread));
  }
}

}  // namespace

LinkSensors gazeboSensors(const TiXmlElement& robot, const Unread& unread) {
  LinkSensors out;
  for (const TiXmlElement* g = robot.FirstChildElement("gazebo"); g; g = g->NextSiblingElement("gazebo")) {
    const std::string link = attribute(*g, "reference");
    if (link.empty()) {
      for (const TiXmlElement* p = g->FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin")) {
        if (readsModelPlugin(*p)) readModelPlugin(*p, unread, out);
      }
      continue;
    }
    for (const TiXmlElement* s = g->FirstChildElement("sensor"); s; s = s->NextSiblingElement("sensor")) {
      const TiXmlElement* plugin = nullptr;
      const int kind = pluginKind(*s, &plugin);
      if (kind == 0) continue;
      if (kind == 3) {
        out.imus.push_back(sensorImu(*s, *plugin, link, unread));
        continue;
      }
      LidarEntry l;
      l.link = link;
      l.key = "<gazebo reference=\"" + link + "\"> <sensor name=\"" + attribute(*s, "name") + "\">";
      const Numbers numbers(l.key);
      core::LidarSettings& c = l.settings;
      c.min_angle = c.max_angle = 0.0;  // SDF's defaults: one ray straight ahead
      c.samples = 640;
      c.min_range = 0.0;  // <range><min> and <max> are required in SDF
      if (const TiXmlElement* pose = s->FirstChildElement("pose")) l.pose = sdfPose(numbers.read(*pose, "pose", 6));
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
      out.lidars.push_back(std::move(l));
    }
  }
  return out;
}

}  // namespace rigid_body_sim::io::detail
