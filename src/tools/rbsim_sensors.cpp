// rbsim's sensors: rbsim_sensors.h.
#include "rbsim_sensors.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <utility>

#include "rbsim_output.h"

namespace rigid_body_sim::tools {
namespace {

using Kind = core::LinkSensors::Kind;

constexpr const char* kImuHeader = "t,qx,qy,qz,qw,wx,wy,wz,ax,ay,az\n";
constexpr const char* kOdometryHeader = "t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz\n";
constexpr const char* kGnssHeader = "t,latitude,longitude,altitude,v_north,v_west,v_up\n";
constexpr const char* kFieldHeader = "t,x,y,z\n";
constexpr const char* kRangeHeader = "t,range\n";
constexpr const char* kImageHeader = "t,image\n";
constexpr const char* kWrenchHeader = "t,fx,fy,fz,tx,ty,tz\n";

/// A lidar's header: t and a column per ray, r0 to r(n-1), fan by fan.
std::string scanHeader(std::size_t rays) {
  std::string h = "t";
  for (std::size_t k = 0; k < rays; ++k) h += ",r" + std::to_string(k);
  return h + "\n";
}

/// A topic as a file name's part: no leading '/', each '/' a '.'.
std::string fileName(std::string topic) {
  topic.erase(0, topic.find_first_not_of('/'));
  std::replace(topic.begin(), topic.end(), '/', '.');
  return topic;
}

void append(std::vector<double>& out, const core::Vec3& v) { out.insert(out.end(), {v.x(), v.y(), v.z()}); }

/// An IMU row's values after t: q_WS, ω and the specific force in its axes.
std::vector<double> imuValues(const core::ImuReading& r) {
  std::vector<double> v{r.q_WS.x(), r.q_WS.y(), r.q_WS.z(), r.q_WS.w()};
  append(v, r.w_S);
  append(v, r.f_S);
  return v;
}

/// An odometry row's values after t: the pose in the world, the twist in the link's axes.
std::vector<double> odometryValues(const core::OdomReport& o) {
  std::vector<double> v;
  append(v, o.p_WL);
  v.insert(v.end(), {o.q_WL.x(), o.q_WL.y(), o.q_WL.z(), o.q_WL.w()});
  append(v, o.v_L);
  append(v, o.w_L);
  return v;
}

/// A row: t and `values`, 17 digits each.
void writeRow(std::FILE* file, double t, const std::vector<double>& values) {
  std::string line = text(t);
  for (const double x : values) line += "," + text(x);
  line += "\n";
  std::fputs(line.c_str(), file);
}

/// A contact sensor's sample as a JSON line: t and each pair touching its
/// link (the `body` side), by name, in its frame.
std::string contactsLine(const core::Model& model, const std::vector<core::ContactPairReport>& pairs, double t) {
  Json out = {{"t", t}, {"contacts", Json::array()}};
  for (const core::ContactPairReport& p : pairs) {
    Json points = Json::array();
    for (const core::Vec3& q : p.points_W) points.push_back(vec(q));
    out["contacts"].push_back({{"body", model.body(p.body).name},
                               {"other", p.other >= 0 ? Json(model.body(p.other).name) : Json(nullptr)},
                               {"scene_item", p.item >= 0 ? Json(p.item) : Json(nullptr)},
                               {"points", points},
                               {"normal", vec(p.normal_W)},
                               {"depth", num(p.depth)},
                               {"normal_force", vec(p.normal_force_W)},
                               {"friction_force", vec(p.friction_force_W)}});
  }
  return out.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace

SensorRun::SensorRun(const core::Scene& scene, const core::SceneState& start,
                     const std::vector<io::RobotSensors>& sensors, double publish_rate, const std::string& out_dir)
    : scene_(scene) {
  const double dt = scene.model().dt();
  for (std::size_t r = 0; r < scene.robots().size(); ++r) {
    const io::RobotSensors none;
    const io::RobotSensors& s = r < sensors.size() ? sensors[r] : none;
    sensors_.push_back(io::linkSensors(s, scene.robots()[r].model, start.robots[r], dt, publish_rate));
    if (out_dir.empty()) continue;
    for (std::size_t i = 0; i < s.imus.size(); ++i) {
      open(out_dir, r, s.imus[i].entry.topic, kImuHeader, Kind::kImu, i);
    }
    for (std::size_t i = 0; i < s.odometry.size(); ++i) {
      const io::OdometryEntry& e = s.odometry[i].entry;
      open(out_dir, r, e.topic, kOdometryHeader, Kind::kOdometry, i);
      if (!e.ground_truth.empty()) {
        open(out_dir, r, e.ground_truth, kOdometryHeader, Kind::kOdometry, i, true);
      }
    }
    for (std::size_t i = 0; i < s.gnss.size(); ++i) {
      open(out_dir, r, s.gnss[i].entry.topic, kGnssHeader, Kind::kGnss, i);
    }
    for (std::size_t i = 0; i < s.magnetometers.size(); ++i) {
      open(out_dir, r, s.magnetometers[i].entry.topic, kFieldHeader, Kind::kMagnetometer, i);
    }
    for (std::size_t i = 0; i < s.lidars.size(); ++i) {
      const io::LidarEntry& e = s.lidars[i].entry;
      const std::string header = e.range ? kRangeHeader : scanHeader(sensors_[r].lidars()[i].lidar.rayCount());
      open(out_dir, r, e.topic, header, Kind::kLidar, i);
    }
    for (std::size_t i = 0; i < s.cameras.size(); ++i) {
      const io::DepthCameraEntry& e = s.cameras[i].entry;
      const std::string topic = e.image_topic.rfind('/', 0) == 0 ? e.image_topic : e.topic + "/" + e.image_topic;
      open(out_dir, r, topic, kImageHeader, Kind::kDepthCamera, i);
    }
    for (std::size_t i = 0; i < s.force_torques.size(); ++i) {
      open(out_dir, r, s.force_torques[i].entry.topic, kWrenchHeader, Kind::kForceTorque, i);
    }
    for (std::size_t i = 0; i < s.contact_sensors.size(); ++i) {
      open(out_dir, r, s.contact_sensors[i].entry.topic, "", Kind::kContacts, i);
    }
  }
  if (out_dir.empty()) {  // nothing reads them: not read
    for (core::LinkSensors& s : sensors_) {
      for (std::size_t i = 0; i < s.lidars().size(); ++i) s.want(Kind::kLidar, i, false);
      for (std::size_t i = 0; i < s.depthCameras().size(); ++i) s.want(Kind::kDepthCamera, i, false);
      for (std::size_t i = 0; i < s.forceTorques().size(); ++i) s.want(Kind::kForceTorque, i, false);
      for (std::size_t i = 0; i < s.contactSensors().size(); ++i) s.want(Kind::kContacts, i, false);
    }
  }
}

void SensorRun::open(const std::string& out_dir, std::size_t robot, const std::string& topic, const std::string& header,
                     Kind kind, std::size_t index, bool truth) {
  Log log{robot, kind, index, truth, nullptr, out_dir + "/" + scene_.robots()[robot].name + "." + fileName(topic)};
  const std::string path = log.stem + (kind == Kind::kContacts ? ".jsonl" : ".csv");  // JSON lines: one a sample
  if (std::find(paths_.begin(), paths_.end(), path) != paths_.end()) {
    throw UsageError("--out: two of robot '" + scene_.robots()[robot].name + "''s sensors would write '" + path +
                     "' (their topics are the same)");
  }
  log.file = std::fopen(path.c_str(), "w");
  if (log.file == nullptr) throw UsageError("--out: cannot write '" + path + "': " + std::strerror(errno));
  std::fputs(header.c_str(), log.file);
  paths_.push_back(path);
  logs_.push_back(std::move(log));
}

SensorRun::~SensorRun() {
  for (const Log& log : logs_) std::fclose(log.file);
}

void SensorRun::finish() { closeLogs(logs_, "a sensor's file"); }

void SensorRun::before(const core::SceneState& state) {
  for (std::size_t r = 0; r < sensors_.size(); ++r) sensors_[r].before(scene_.robots()[r].model, state.robots[r]);
}

void SensorRun::sample(const core::SceneState& state, const core::SceneLoads& loads, const core::SceneWorkspace& ws,
                       long long steps, double t) {
  ledger_.update(state.bodies, ws.bodies.contacts);
  core::StepContacts contacts(scene_.model(), state.bodies, ledger_, ws.bodies.contacts);
  bool any = false;
  for (std::size_t r = 0; r < sensors_.size(); ++r) {
    if (sensors_[r].empty()) continue;
    const core::StepForces forces{r < loads.robots.size() ? &loads.robots[r] : nullptr, &contacts};
    any = sensors_[r].sample(scene_, r, state.bodies, state.robots[r], steps, t, forces) || any;
  }
  if (!any) return;
  for (const Log& log : logs_) {
    if (sensors_[log.robot].fresh(log.kind, log.index)) row(log, steps, t);
  }
}

std::string SensorRun::writeImage(const Log& log, long long steps) const {
  const core::DepthCameraChannel& c = sensors_[log.robot].depthCameras()[log.index];
  const int width = c.camera.settings().width, height = c.camera.settings().height;
  const std::string path = log.stem + "." + std::to_string(steps) + ".pfm";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw UsageError("--out: cannot write '" + path + "': " + std::strerror(errno));
  // PFM: one channel of little-endian float32 (the scale's sign), rows from the bottom.
  std::fprintf(f, "Pf\n%d %d\n-1.0\n", width, height);
  const auto w = static_cast<std::size_t>(width);
  std::vector<float> pixels(w);
  for (auto v = static_cast<std::size_t>(height); v-- > 0;) {
    for (std::size_t u = 0; u < w; ++u) pixels[u] = static_cast<float>(c.depth[v * w + u]);
    std::fwrite(pixels.data(), sizeof(float), pixels.size(), f);
  }
  const bool whole = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !whole) throw UsageError("--out: '" + path + "' could not be written whole");
  return path.substr(path.find_last_of('/') + 1);
}

void SensorRun::row(const Log& log, long long steps, double t) const {
  const core::LinkSensors& s = sensors_[log.robot];
  std::vector<double> v;
  switch (log.kind) {
    case Kind::kImu:
      v = imuValues(s.imus()[log.index].reading);
      break;
    case Kind::kOdometry: {
      const core::OdometryChannel& c = s.odometry()[log.index];
      v = odometryValues(log.truth ? c.truth : c.report);
      break;
    }
    case Kind::kGnss: {
      const core::GnssFix& f = s.gnss()[log.index].fix;
      v = {f.latitude, f.longitude, f.altitude};
      append(v, f.v_NWU);
      break;
    }
    case Kind::kMagnetometer:
      append(v, s.magnetometers()[log.index].field_S);
      break;
    case Kind::kLidar: {
      const core::LidarChannel& c = s.lidars()[log.index];
      if (c.finder) {
        v = {c.reading};
      } else {
        v = c.ranges;
      }
      break;
    }
    case Kind::kDepthCamera: {
      const std::string line = text(t) + "," + writeImage(log, steps) + "\n";
      std::fputs(line.c_str(), log.file);
      return;
    }
    case Kind::kForceTorque: {
      const core::Vec6& w = s.forceTorques()[log.index].wrench;  // [torque; force]
      append(v, w.tail<3>());
      append(v, w.head<3>());
      break;
    }
    case Kind::kContacts:
      std::fputs((contactsLine(scene_.model(), s.contactSensors()[log.index].pairs, t) + "\n").c_str(), log.file);
      return;
  }
  writeRow(log.file, t, v);
}

std::vector<BodyDevices> bodyDevices(const io::SimConfig& config, const std::vector<int>& entry) {
  if (!config.bodies_listed) return {BodyDevices{config.imu, config.odom_noise, config.cmd_vel}};
  std::vector<BodyDevices> devices(config.bodies.size());
  for (std::size_t k = 0; k < config.bodies.size(); ++k) {
    const int body = k < entry.size() ? entry[k] : static_cast<int>(k);
    if (body < 0) continue;
    devices.at(static_cast<std::size_t>(body)) = {config.bodies[k].imu, config.bodies[k].odom_noise,
                                                  config.bodies[k].cmd_vel};
  }
  return devices;
}

BodySensorRun::BodySensorRun(const core::Model& model, const core::State& start,
                             const std::vector<BodyDevices>& devices, double publish_rate, const std::string& out_dir)
    : model_(model), publish_every_(std::max(1LL, std::llround(1.0 / (publish_rate * model.dt())))) {
  std::vector<std::string> paths;
  const auto open = [&](std::size_t k, const std::string& topic, const char* header, Log::What what) {
    const std::string name = model.body(body_[k]).name;
    const std::string path = out_dir + "/" + name + "." + fileName(topic) + ".csv";
    if (std::find(paths.begin(), paths.end(), path) != paths.end()) {
      throw UsageError("--out: two of body '" + name + "''s sensors would write '" + path +
                       "' (their topics are the same)");
    }
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (f == nullptr) throw UsageError("--out: cannot write '" + path + "': " + std::strerror(errno));
    std::fputs(header, f);
    paths.push_back(path);
    logs_.push_back({k, what, f});
  };
  for (std::size_t i = 0; i < devices.size() && i < model.bodyCount(); ++i) {
    const BodyDevices& d = devices[i];
    if (!d.imu && !d.odom_noise) continue;
    sensors_.push_back(io::bodySensors(model.body(i), d.imu, d.odom_noise, model.dt()));
    sensors_.back().start(model.body(i), start.bodies[i], 0.0);
    body_.push_back(i);
    if (out_dir.empty()) continue;
    const std::size_t k = sensors_.size() - 1;
    if (d.imu) open(k, d.imu->topic, kImuHeader, Log::What::kImu);
    if (d.odom_noise) {
      open(k, "odom", kOdometryHeader, Log::What::kOdometry);
      open(k, "ground_truth", kOdometryHeader, Log::What::kTruth);
    }
  }
  reports_.resize(sensors_.size());
}

BodySensorRun::~BodySensorRun() {
  for (const Log& log : logs_) std::fclose(log.file);
}

void BodySensorRun::finish() { closeLogs(logs_, "a body's sensor file"); }

void BodySensorRun::sample(const core::State& state, long long steps, double t) {
  if (logs_.empty()) return;  // nothing reads them
  const bool report = steps % publish_every_ == 0;
  for (std::size_t k = 0; k < sensors_.size(); ++k) {
    const core::BodyModel& body = model_.body(body_[k]);
    const core::BodyState& s = state.bodies[body_[k]];
    if (steps > 0) sensors_[k].sample(body, s, model_.gravity(), steps);
    if (report && sensors_[k].noisy()) reports_[k] = sensors_[k].report(core::linkState(body, s), t);
  }
  for (const Log& log : logs_) {
    const core::BodySensors& sensors = sensors_[log.body];
    const std::size_t i = body_[log.body];
    switch (log.what) {
      case Log::What::kImu:
        if (steps > 0 && sensors.imuFresh()) writeRow(log.file, t, imuValues(sensors.imuReading()));
        break;
      case Log::What::kOdometry:
        if (report) writeRow(log.file, t, odometryValues(reports_[log.body]));
        break;
      case Log::What::kTruth:
        if (report) {
          writeRow(log.file, t, odometryValues(core::exactOdom(core::linkState(model_.body(i), state.bodies[i]))));
        }
        break;
    }
  }
}

}  // namespace rigid_body_sim::tools
