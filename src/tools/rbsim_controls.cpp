// rbsim's controls: rbsim_controls.h.
#include "rbsim_controls.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <utility>

#include "rbsim_output.h"
#include "rbsim_report.h"

namespace rigid_body_sim::tools {

BodyDrives::BodyDrives(const core::Model& model, const std::vector<BodyDevices>& devices) : model_(model) {
  for (std::size_t i = 0; i < devices.size() && i < model.bodyCount(); ++i) {
    if (!devices[i].cmd_vel) continue;
    body_.push_back(i);
    drivers_.emplace_back(*devices[i].cmd_vel);
  }
}

io::BodyDrivers BodyDrives::byName() {
  return [this](const std::string& name) -> core::VelocityDriver* {
    for (std::size_t k = 0; k < body_.size(); ++k) {
      if (model_.body(body_[k]).name == name) return &drivers_[k];
    }
    return nullptr;
  };
}

void BodyDrives::loadsFor(const core::State& state, double t, core::Loads& loads) {
  loads.clear();
  for (std::size_t k = 0; k < body_.size(); ++k)
    core::addDriverLoad(drivers_[k], model_, state, body_[k], t, model_.dt(), loads);
}

ControlRun::ControlRun(const core::Scene& scene, const core::SceneState& start, std::vector<io::RobotControls> controls,
                       std::vector<io::TimedCommand> timeline, io::BodyDrivers bodies, const std::string& out_dir)
    : scene_(scene), controls_(std::move(controls)) {
  controls_.resize(scene.robots().size());
  for (std::size_t r = 0; r < controls_.size(); ++r) {
    names_.push_back(scene.robots()[r].name);
    controls_[r].restart(start.robots[r], true);
  }
  timeline_ = io::Timeline(std::move(timeline), scene.robots(), scene.model().dt(), controls_, std::move(bodies));
  if (out_dir.empty()) return;
  const double dt = scene.model().dt();
  for (std::size_t r = 0; r < controls_.size(); ++r) {
    for (std::size_t d = 0; d < controls_[r].drives.size(); ++d) {
      const std::string path = out_dir + "/" + names_[r] + "." + controls_[r].drives[d].spec().name + ".odom.csv";
      std::FILE* f = std::fopen(path.c_str(), "w");
      if (f == nullptr) throw UsageError("--out: cannot write '" + path + "': " + std::strerror(errno));
      std::fputs("t,x,y,heading,linear,lateral,angular\n", f);
      const long long every = std::max(1LL, std::llround(1.0 / (controls_[r].drive_topics[d].publish_rate * dt)));
      logs_.push_back({r, d, every, f});
    }
  }
}

ControlRun::~ControlRun() {
  for (const Log& log : logs_) std::fclose(log.file);
}

void ControlRun::finish() { closeLogs(logs_, "a drive's odometry file"); }

void ControlRun::loadsFor(const core::SceneState& state, double t, std::vector<core::ArticulationLoads>& loads) {
  if (!timeline_.empty()) warnOnce(timeline_.apply(t, scene_.robots(), controls_, efforts_), said_);
  loads.resize(controls_.size());
  const double dt = scene_.model().dt();
  for (std::size_t r = 0; r < controls_.size(); ++r) {
    controls_[r].loads(scene_.robots()[r].model, state.robots[r], t, dt, efforts_, r, loads[r]);
  }
  efforts_.dropFinished(t);
}

void ControlRun::observe(const core::SceneState& state, long long steps, double t) {
  const double dt = scene_.model().dt();
  for (std::size_t r = 0; r < controls_.size(); ++r) controls_[r].observe(state.robots[r], dt);
  rows(t, steps);
}

void ControlRun::write(double t) { rows(t, -1); }

void ControlRun::rows(double t, long long steps) {
  for (const Log& log : logs_) {
    if (steps >= 0 && steps % log.every != 0) continue;
    const core::PlanarOdometry& o = controls_[log.robot].drives[log.drive].odometry();
    std::fprintf(log.file, "%s,%s,%s,%s,%s,%s,%s\n", text(t).c_str(), text(o.x).c_str(), text(o.y).c_str(),
                 text(o.heading).c_str(), text(o.linear).c_str(), text(o.lateral).c_str(), text(o.angular).c_str());
  }
}

}  // namespace rigid_body_sim::tools
