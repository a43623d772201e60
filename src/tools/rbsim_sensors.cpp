// rbsim's sensors: rbsim_sensors.h.
#include "rbsim_sensors.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "rbsim_output.h"

namespace rigid_body_sim::tools {
namespace {

using Kind = core::LinkSensors::Kind;

constexpr const char* kImuHeader = "t,qx,qy,qz,qw,wx,wy,wz,ax,ay,az\n";
constexpr const char* kOdometryHeader = "t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz\n";
constexpr const char* kGnssHeader = "t,latitude,longitude,altitude,v_north,v_west,v_up\n";
constexpr const char* kFieldHeader = "t,x,y,z\n";

/// A topic as a file name's part: no leading '/', each '/' a '.'.
std::string fileName(std::string topic) {
  topic.erase(0, topic.find_first_not_of('/'));
  std::replace(topic.begin(), topic.end(), '/', '.');
  return topic;
}

void append(std::vector<double>& out, const core::Vec3& v) { out.insert(out.end(), {v.x(), v.y(), v.z()}); }

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
      open(out_dir, r, s.imus[i].entry.topic, kImuHeader, {r, Kind::kImu, i, false, nullptr});
    }
    for (std::size_t i = 0; i < s.odometry.size(); ++i) {
      const io::OdometryEntry& e = s.odometry[i].entry;
      open(out_dir, r, e.topic, kOdometryHeader, {r, Kind::kOdometry, i, false, nullptr});
      if (!e.ground_truth.empty()) {
        open(out_dir, r, e.ground_truth, kOdometryHeader, {r, Kind::kOdometry, i, true, nullptr});
      }
    }
    for (std::size_t i = 0; i < s.gnss.size(); ++i) {
      open(out_dir, r, s.gnss[i].entry.topic, kGnssHeader, {r, Kind::kGnss, i, false, nullptr});
    }
    for (std::size_t i = 0; i < s.magnetometers.size(); ++i) {
      open(out_dir, r, s.magnetometers[i].entry.topic, kFieldHeader, {r, Kind::kMagnetometer, i, false, nullptr});
    }
  }
}

void SensorRun::open(const std::string& out_dir, std::size_t robot, const std::string& topic, const char* header,
                     Log log) {
  const std::string path = out_dir + "/" + scene_.robots()[robot].name + "." + fileName(topic) + ".csv";
  if (std::find(paths_.begin(), paths_.end(), path) != paths_.end()) {
    throw UsageError("--out: two of robot '" + scene_.robots()[robot].name + "''s sensors would write '" + path +
                     "' (their topics are the same)");
  }
  log.file = std::fopen(path.c_str(), "w");
  if (log.file == nullptr) throw UsageError("--out: cannot write '" + path + "': " + std::strerror(errno));
  std::fputs(header, log.file);
  paths_.push_back(path);
  logs_.push_back(log);
}

SensorRun::~SensorRun() {
  for (const Log& log : logs_) std::fclose(log.file);
}

void SensorRun::finish() {
  std::vector<Log> logs;
  logs.swap(logs_);
  bool whole = true;
  for (const Log& log : logs) whole = std::ferror(log.file) == 0 && std::fclose(log.file) == 0 && whole;
  if (!whole) throw UsageError("--out: a sensor's file could not be written whole");
}

void SensorRun::sample(const core::SceneState& state, long long steps, double t) {
  bool any = false;
  for (std::size_t r = 0; r < sensors_.size(); ++r) {
    if (sensors_[r].empty()) continue;
    any = sensors_[r].sample(scene_.robots()[r].model, state.robots[r], steps, t, scene_.model().gravity()) || any;
  }
  if (!any) return;
  for (const Log& log : logs_) {
    if (sensors_[log.robot].fresh(log.kind, log.index)) row(log, t);
  }
}

void SensorRun::row(const Log& log, double t) const {
  const core::LinkSensors& s = sensors_[log.robot];
  std::vector<double> v;
  switch (log.kind) {
    case Kind::kImu: {
      const core::ImuReading& r = s.imus()[log.index].reading;
      v = {r.q_WS.x(), r.q_WS.y(), r.q_WS.z(), r.q_WS.w()};
      append(v, r.w_S);
      append(v, r.f_S);
      break;
    }
    case Kind::kOdometry: {
      const core::OdometryChannel& c = s.odometry()[log.index];
      const core::OdomReport& o = log.truth ? c.truth : c.report;
      append(v, o.p_WL);
      v.insert(v.end(), {o.q_WL.x(), o.q_WL.y(), o.q_WL.z(), o.q_WL.w()});
      append(v, o.v_L);
      append(v, o.w_L);
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
  }
  std::string line = text(t);
  for (const double x : v) line += "," + text(x);
  line += "\n";
  std::fputs(line.c_str(), log.file);
}

}  // namespace rigid_body_sim::tools
