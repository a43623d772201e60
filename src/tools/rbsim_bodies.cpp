// rbsim's run of a world of bodies alone: rbsim_bodies.h.
#include "rbsim_bodies.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "rbsim_controls.h"
#include "rbsim_loop.h"
#include "rbsim_output.h"
#include "rbsim_report.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/step/diagnostics.h"
#include "rigid_body_sim/core/step/step.h"
#include "rigid_body_sim/io/orientation.h"

namespace rigid_body_sim::tools {
namespace {

using core::Vec3;

/// Angular momentum of the world: one body's about its centre of mass; with
/// several, the total about the world origin (Σ I ω + r × m v).
Vec3 angularMomentum(const core::Model& model, const core::State& state) {
  if (model.bodyCount() == 1) return core::angularMomentumWorld(model.body(0), state.bodies[0]);
  return bodiesAngularMomentum(model, state, model.bodyCount());
}

}  // namespace

int runBodies(io::World world, bool listed, const RunOptions& options, const std::vector<BodyDevices>& devices,
              std::vector<io::TimedCommand> timeline) {
  const core::Model& model = world.model;
  core::State& state = world.state;
  const std::size_t n = model.bodyCount();
  const double dt = model.dt();
  BodyDrives drives(model, devices);
  std::vector<io::RobotControls> no_controls;  // a world of bodies alone has no robot for them
  core::JointEffortSchedule no_efforts;
  io::Timeline commands(std::move(timeline), {}, dt, no_controls, drives.byName());  // refused before any warning
  for (const std::string& note : world.notes) std::fprintf(stderr, "rbsim: warning: %s\n", note.c_str());
  if (!model.scene().empty()) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::string warning = io::touchesNothing(model.body(i));
      if (!warning.empty()) std::fprintf(stderr, "rbsim: warning: %s\n", warning.c_str());
    }
  }

  const long long steps = stepCount(options.duration, dt);
  const double energy_start = core::totalEnergy(model, state);
  const Vec3 momentum_start = angularMomentum(model, state);

  std::unique_ptr<CsvWriter> csv;
  if (!options.csv.empty()) csv = std::make_unique<CsvWriter>(options.csv, listed);
  const auto write_rows = [&](long long done) {
    for (std::size_t i = 0; i < n; ++i)
      csv->row(done * dt, model.body(i).name, core::linkState(model.body(i), state.bodies[i]));
  };
  core::Workspace workspace;
  std::vector<std::string> said;  // the timeline's notes, each said once
  core::Loads loads;
  BodySensorRun sensors(model, state, devices, options.publish_rate, options.out_dir);
  sensors.sample(state, 0, 0.0);    // as the node publishes its odometry at start
  std::vector<char> limited(n, 0);  // bodies the speed limits have held back, warned once each
  double max_penetration = 0.0;     // m, over the states at the start of every step
  // Progress bar only for runs that take a while (about a second or more).
  const bool progress = isatty(STDERR_FILENO) && steps * static_cast<long long>(n) >= 2'000'000;
  const LoopTimes times = runLoop(
      steps, csv != nullptr, options.every, progress,
      [&](long long k) {
        const double t = static_cast<double>(k - 1) * dt;  // the step's start, as the node's clock: steps × dt
        if (!commands.empty()) warnOnce(commands.apply(t, {}, no_controls, no_efforts), said);
        if (!drives.empty()) drives.loadsFor(state, t, loads);
        core::step(model, state, loads, &workspace);
        sensors.sample(state, k, static_cast<double>(k) * dt);
        max_penetration = std::max(max_penetration, workspace.deepest_penetration);
        if (!workspace.speed_limited.empty() || !workspace.diverged.empty()) {
          checkStep(model, workspace, k * dt, limited);
        }
      },
      write_rows);
  const double wall_s = times.wall_s;
  const double ns_per_step = times.ns_per_step;

  // Reported as steps × Δt: state.time accumulates Δt and carries its rounding.
  const double sim_time = static_cast<double>(steps) * dt;
  const double energy_end = core::totalEnergy(model, state);
  const Vec3 momentum_end = angularMomentum(model, state);
  // The final state (the loop saw every earlier state), and rest of all bodies.
  bool at_rest = true;
  int resting = 0;
  std::vector<char> rest(n);
  for (std::size_t i = 0; i < n; ++i) {
    max_penetration = std::max(max_penetration,
                               -std::min(0.0, core::minSeparation(model, state.bodies[i], static_cast<int>(i), 0.0)));
    rest[i] = core::atRest(model, state.bodies[i]);
    at_rest = at_rest && rest[i];
    resting += rest[i];
  }
  Json out = {
      {"steps", steps}, {"sim_time", num(sim_time)}, {"wall_s", num(wall_s)}, {"ns_per_step", num(ns_per_step)}};
  if (!listed) out["final"] = finalJson(core::linkState(model.body(0), state.bodies[0]));
  out["energy"] = {{"start", num(energy_start)}, {"end", num(energy_end)}};
  out["angular_momentum"] = {{"start", vec(momentum_start)}, {"end", vec(momentum_end)}};
  out["max_penetration"] = num(max_penetration);
  out["at_rest"] = at_rest;
  Json limited_json = Json::array();
  for (std::size_t i = 0; i < n; ++i) {
    if (limited[i]) limited_json.push_back(model.body(i).name);
  }
  out["speed_limited"] = limited_json;
  if (csv) csv->finish();
  sensors.finish();
  JsonLine line(out, "bodies");
  for (std::size_t i = 0; i < n; ++i) {
    line.element({{"name", model.body(i).name},
                  {"final", finalJson(core::linkState(model.body(i), state.bodies[i]))},
                  {"at_rest", static_cast<bool>(rest[i])}});
  }
  line.finish();

  if (!options.quiet) {
    const auto rel = [](double a, double b) { return a == 0.0 ? std::abs(b) : (b - a) / std::abs(a); };
    if (listed) {
      std::fprintf(stderr,
                   "rbsim: %zu bodies for %.6g s: %lld steps of %.6g s, %.3g s wall, %.1f ns/step (%.1f per body)\n", n,
                   sim_time, steps, dt, wall_s, ns_per_step, ns_per_step / n);
      std::fprintf(stderr, "  at rest           %d of %zu\n", resting, n);
    } else {
      const core::BodyModel& bm = model.body(0);
      const core::LinkState final_link = core::linkState(bm, state.bodies[0]);
      const Vec3 angles = io::rpyFromQuaternion(final_link.q_WL);
      std::fprintf(stderr, "rbsim: '%s' (%.6g kg) for %.6g s: %lld steps of %.6g s, %.3g s wall, %.1f ns/step\n",
                   bm.name.c_str(), bm.mass, sim_time, steps, dt, wall_s, ns_per_step);
      std::fprintf(stderr, "  final position    [%.6g, %.6g, %.6g] m, rpy [%.6g, %.6g, %.6g] rad\n",
                   final_link.p_WL.x(), final_link.p_WL.y(), final_link.p_WL.z(), angles.x(), angles.y(), angles.z());
      std::fprintf(stderr, "  final velocity    [%.6g, %.6g, %.6g] m/s, angular [%.6g, %.6g, %.6g] rad/s\n",
                   final_link.v_WL.x(), final_link.v_WL.y(), final_link.v_WL.z(), final_link.w_W.x(),
                   final_link.w_W.y(), final_link.w_W.z());
    }
    std::fprintf(stderr, "  energy            %.9g J -> %.9g J (relative change %.2e)\n", energy_start, energy_end,
                 rel(energy_start, energy_end));
    std::fprintf(stderr, "  |L| %s %.9g -> %.9g kg m^2/s (relative change %.2e)\n", listed ? "about 0  " : "about CoM",
                 momentum_start.norm(), momentum_end.norm(), rel(momentum_start.norm(), momentum_end.norm()));
    std::fprintf(stderr, "  contacts          deepest penetration %.3g mm, %s at the end\n", 1e3 * max_penetration,
                 at_rest ? "at rest" : "moving");
  }
  return 0;
}

}  // namespace rigid_body_sim::tools
