// The sensors of a URDF's Gazebo markup: gazebo_sensors.h.
#include "gazebo_sensors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "gazebo_plugins.h"
#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::io::detail {

namespace {

/// The plugin of `sensor` this project runs: 1 laser (LaserScan), 2 Velodyne (PointCloud2), 3 IMU, 4 depth
/// camera, 5 range finder (Range), 6 bumper (contacts), 0 none.
int pluginKind(const TiXmlElement& sensor, const TiXmlElement** plugin) {
  const std::string type = attribute(sensor, "type");
  const bool ray = type == "ray" || type == "gpu_ray";
  for (const TiXmlElement* p = sensor.FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin")) {
    const std::string file = attribute(*p, "filename");
    *plugin = p;
    if (ray && (file == "libgazebo_ros_laser.so" || file == "libgazebo_ros_gpu_laser.so")) return 1;
    if (ray && (file == "libgazebo_ros_velodyne_laser.so" || file == "libgazebo_ros_velodyne_gpu_laser.so")) return 2;
    if (ray && file == "libgazebo_ros_range.so") return 5;
    if (type == "imu" && file == "libgazebo_ros_imu_sensor.so") return 3;
    if (type == "contact" && file == "libgazebo_ros_bumper.so") return 6;
    if (type == "depth" && (file == "libgazebo_ros_openni_kinect.so" || file == "libgazebo_ros_depth_camera.so")) {
      return 4;
    }
  }
  return 0;
}

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
  numbers.rate(&s, "update_rate", sensor_rate);
  Numbers(imu.key + " <plugin>").rate(&plugin, "updateRateHZ", plugin_rate);
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
  imu.frame_id = childFrame(plugin, "frameName", "", imu.key + " <plugin>");
  double offset = 0.0;
  for (const char* name : {"rpyOffset", "rpyOffsets"}) {
    if (const TiXmlElement* e = plugin.FirstChildElement(name)) {
      for (double x : Numbers(imu.key + " <plugin>").read(*e, name, 3)) offset = std::max(offset, std::abs(x));
    }
  }
  if (offset != 0.0) unread("<plugin> libgazebo_ros_imu_sensor.so <rpyOffset>", link);
  return imu;
}

/// The depth camera of `<sensor type="depth">` on `link` with
/// gazebo_ros_openni_kinect (or gazebo_ros_depth_camera): its `<pose>`,
/// `<update_rate>`, `<camera>`'s `horizontal_fov`, `image` `width` and
/// `height`, `clip` `near` and `far` and `noise` `stddev`; the plugin's
/// `cameraName` (the topics' namespace, "camera"), `depthImageTopicName`
/// ("depth/image_raw"), `depthImageCameraInfoTopicName`
/// ("depth/camera_info"), `pointCloudTopicName` ("points"), `frameName`,
/// and `pointCloudCutoff` (0.4 m) and `pointCloudCutoffMax` (5 m) within
/// the clip, the depths it reports. Its colour or IR image is not made: said.
DepthCameraEntry sensorCamera(const TiXmlElement& s, const TiXmlElement& plugin, const std::string& link,
                              const Unread& unread) {
  DepthCameraEntry c;
  c.link = link;
  c.key = "<gazebo reference=\"" + link + "\"> <sensor name=\"" + attribute(s, "name") + "\">";
  const Numbers numbers(c.key), own(c.key + " <plugin>");
  core::DepthCameraSettings& k = c.settings;
  if (const TiXmlElement* pose = s.FirstChildElement("pose")) c.pose = sdfPose(numbers.read(*pose, "pose", 6));
  numbers.rate(&s, "update_rate", c.rate);
  if (c.rate == 0.0) {  // Gazebo's "as fast as it renders": 30 Hz here, said
    c.rate = 30.0;
    unread("<sensor type=\"depth\"> <update_rate> 0 (read as 30 Hz)", link);
  }
  const TiXmlElement* camera = s.FirstChildElement("camera");
  double near = 0.1, far = 10.0, cutoff = 0.4, cutoff_max = 5.0;
  numbers.at(camera, "horizontal_fov", k.hfov);
  numbers.count(camera, "image/width", k.width, Bounds{1.0, core::ranges::kMaxPixels});
  numbers.count(camera, "image/height", k.height, Bounds{1.0, core::ranges::kMaxPixels});
  numbers.at(camera, "clip/near", near);
  numbers.at(camera, "clip/far", far);
  numbers.at(camera, "noise/stddev", k.noise);
  own.at(&plugin, "pointCloudCutoff", cutoff);
  own.at(&plugin, "pointCloudCutoffMax", cutoff_max);
  k.min_depth = std::max(near, cutoff);
  k.max_depth = std::min(far, cutoff_max);
  c.topic = childText(plugin, "cameraName", "camera");
  c.image_topic = childText(plugin, "depthImageTopicName", "depth/image_raw");
  c.info_topic = childText(plugin, "depthImageCameraInfoTopicName", "depth/camera_info");
  c.points_topic = childText(plugin, "pointCloudTopicName", "points");
  c.frame_id = childFrame(plugin, "frameName", "", c.key + " <plugin>");
  unread("<sensor type=\"depth\"> its colour or IR image (depth only here)", link);
  return c;
}

/// gazebo_ros_range's reading of the ray sensor `l` (ROSbot's sonars): its
/// `topicName` ("/range", the plugin's), `frameName` (the link; the
/// plugin's "/world" is no frame a range is in), `updateRate` (0: the
/// sensor's) under the sensor's rate, `gaussianNoise` on the reading, `fov`
/// (0.05 rad) and `radiation` ("ultrasound" or "infrared").
RangeEntry rangeFinder(const TiXmlElement& plugin, LidarEntry& l) {
  const std::string where = l.key + " <plugin>";
  const Numbers own(where);
  RangeEntry r;
  if (plugin.FirstChildElement("topicName") == nullptr) l.topic = "/range";
  double rate = 0.0;
  own.rate(&plugin, "updateRate", rate);
  if (rate > 0.0 && rate < l.rate) l.rate = rate;
  own.at(&plugin, "gaussianNoise", r.settings.noise, Bounds{0.0, core::ranges::kMaxExtent, false, "m"});
  own.at(&plugin, "fov", r.field_of_view, Bounds{0.0, 2.0 * M_PI, false, "rad"});
  const std::string radiation = childText(plugin, "radiation", "ultrasound");
  if (radiation != "ultrasound" && radiation != "infrared") {
    throw std::invalid_argument(where + " <radiation> = '" + shownText(radiation.c_str()) +
                                "': must be ultrasound or infrared");
  }
  r.infrared = radiation == "infrared";
  return r;
}

/// The contact sensor of `<sensor type="contact">` on `link` with
/// gazebo_ros_bumper: `<update_rate>` (0: every step), the plugin's
/// `bumperTopicName` ("bumper_states") and `frameName` ("world": the
/// world's; else a frame fixed to the link). It reports every contact of
/// the moving link carrying `link`, whichever of its collisions touches
/// (`<contact><collision>` names one of Gazebo's, which URDF collisions
/// lumped into one link do not keep).
ContactSensorEntry sensorContact(const TiXmlElement& s, const TiXmlElement& plugin, const std::string& link) {
  ContactSensorEntry c;
  c.link = link;
  c.key = "<gazebo reference=\"" + link + "\"> <sensor name=\"" + attribute(s, "name") + "\">";
  Numbers(c.key).rate(&s, "update_rate", c.rate);
  c.topic = childTopic(plugin, "bumperTopicName", "bumper_states", c.key + " <plugin>");
  const std::string frame = childFrame(plugin, "frameName", "world", c.key + " <plugin>");
  c.frame_id = frame == "world" || frame == "map" ? "" : frame;
  return c;
}

}  // namespace

RobotDevices gazeboSensors(const TiXmlElement& robot, const Unread& unread) {
  RobotDevices out;
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
      if (kind == 4) {
        out.cameras.push_back(sensorCamera(*s, *plugin, link, unread));
        continue;
      }
      if (kind == 6) {
        out.contact_sensors.push_back(sensorContact(*s, *plugin, link));
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
      numbers.rate(s, "update_rate", l.rate);
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
        // Gazebo: samples × resolution readings. Read as a count, not a
        // double cast to int: 4294967297 once wrapped to one ray.
        int n = *samples;
        double resolution = 1.0;
        numbers.count(ray, at + "samples", n, Bounds{1.0, core::ranges::kMaxRays});
        numbers.at(ray, at + "resolution", resolution, Bounds{0.0, core::ranges::kMaxRays, true});
        const double readings = std::round(n * resolution);
        if (!(readings >= 1.0 && readings <= core::ranges::kMaxRays)) {
          throw std::invalid_argument(l.key + " <" + at + "samples> x <resolution>: " + std::to_string(readings) +
                                      " readings, not within [1, 1e6]");
        }
        *samples = static_cast<int>(readings);
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
      l.frame_id = childFrame(*plugin, "frameName", "", l.key + " <plugin>");
      if (kind == 2) {  // the Velodyne plugin's own range and noise
        if (l.topic == "scan") l.topic = "points";
        const Numbers own(l.key + " <plugin>");
        own.at(plugin, "min_range", c.min_range);
        own.at(plugin, "max_range", c.max_range);
        own.at(plugin, "gaussianNoise", c.noise);
        l.organized = childFlag(*plugin, "organize_cloud", false, l.key + " <plugin>");
      }
      if (kind == 5) l.range = rangeFinder(*plugin, l);
      out.lidars.push_back(std::move(l));
    }
  }
  return out;
}

}  // namespace rigid_body_sim::io::detail
