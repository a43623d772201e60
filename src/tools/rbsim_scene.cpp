// rbsim's run of a world of bodies and robots: rbsim_scene.h.
#include "rbsim_scene.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "rbsim_controls.h"
#include "rbsim_loop.h"
#include "rbsim_output.h"
#include "rbsim_report.h"
#include "rbsim_sensors.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/step/diagnostics.h"
#include "rigid_body_sim/io/scene_loader.h"
#include "rigid_body_sim/io/world.h"

namespace rigid_body_sim::tools {
namespace {

double sceneEnergy(const core::Scene& scene, const core::SceneState& state) {
  const core::Model& model = scene.model();
  double energy = 0.0;
  for (std::size_t i = 0; i < scene.freeBodyCount(); ++i) {
    const core::BodyState& s = state.bodies.bodies[i];
    energy += core::kineticEnergy(model.body(i), s) + core::potentialEnergy(model.body(i), s, model.gravity());
  }
  for (std::size_t r = 0; r < scene.robots().size(); ++r) {
    energy += robotEnergy(scene.robots()[r].model, state.robots[r], model.gravity());
  }
  return energy;
}

/// About the world origin: the free bodies' and the robots'.
core::Vec3 sceneAngularMomentum(const core::Scene& scene, const core::SceneState& state) {
  core::Vec3 L = bodiesAngularMomentum(scene.model(), state.bodies, scene.freeBodyCount());
  for (std::size_t r = 0; r < scene.robots().size(); ++r) {
    L += robotAngularMomentum(scene.robots()[r].model, state.robots[r]);
  }
  return L;
}

}  // namespace

int runScene(io::SceneSetup setup, const RunOptions& options, std::vector<io::TimedCommand> timeline,
             const std::vector<BodyDevices>& devices) {
  for (const std::string& note : setup.notes) std::fprintf(stderr, "rbsim: warning: %s\n", note.c_str());
  const core::Scene& scene = setup.scene;
  core::SceneState& state = setup.state;
  const core::Model& model = scene.model();
  const std::vector<core::SceneRobot>& robots = scene.robots();
  const std::size_t free = scene.freeBodyCount();
  if (!model.scene().empty()) {
    for (std::size_t i = 0; i < free; ++i) {
      const std::string warning = io::touchesNothing(model.body(i));
      if (!warning.empty()) std::fprintf(stderr, "rbsim: warning: %s\n", warning.c_str());
    }
    for (const core::SceneRobot& robot : robots) {
      if (robot.link.empty()) {
        std::fprintf(stderr,
                     "rbsim: warning: robot '%s' has no <collision> geometry on a moving link: it touches nothing, "
                     "as in Gazebo\n",
                     robot.name.c_str());
      }
    }
  }
  const double dt = model.dt();
  const long long steps = stepCount(options.duration, dt);
  const double energy_start = sceneEnergy(scene, state);
  const core::Vec3 momentum_start = sceneAngularMomentum(scene, state);

  // The CSV's joint columns: every robot's, ROBOT/JOINT (a robot alone's, JOINT).
  const bool alone = setup.entry.size() == 1 && setup.entry[0] < 0;
  std::vector<std::string> joints;
  std::vector<int> first_joint;
  for (const core::SceneRobot& robot : robots) {
    first_joint.push_back(static_cast<int>(joints.size()));
    for (int i = 1; i <= robot.model.jointCount(); ++i) {
      joints.push_back((alone ? "" : robot.name + "/") + robot.model.links[i].joint);
    }
  }
  std::unique_ptr<CsvWriter> csv;
  if (!options.csv.empty()) csv = std::make_unique<CsvWriter>(options.csv, !alone, joints);
  const auto write_rows = [&](long long done) {
    if (alone) {
      const core::ArticulationState& s = state.robots[0];
      csv->row(done * dt, core::baseLinkState(s), s.q, s.v);
      return;
    }
    for (const int e : setup.entry) {
      if (e >= 0) {
        csv->row(done * dt, model.body(e).name, core::linkState(model.body(e), state.bodies.bodies[e]));
      } else {
        const int r = -1 - e;
        const core::ArticulationState& s = state.robots[r];
        csv->row(done * dt, robots[r].name, core::baseLinkState(s), first_joint[r], s.q, s.v);
      }
    }
  };
  core::SceneWorkspace ws;
  core::SceneLoads loads;
  BodyDrives drives(model, devices);
  ControlRun controls(scene, state, std::move(setup.controls), std::move(timeline), drives.byName(), options.out_dir);
  controls.write(0.0);
  SensorRun sensors(scene, state, setup.sensors, options.publish_rate, options.out_dir);
  BodySensorRun body_sensors(model, state.bodies, devices, options.publish_rate, options.out_dir);
  body_sensors.sample(state.bodies, 0, 0.0);        // as the node publishes its odometry at start
  std::vector<char> limited(model.bodyCount(), 0);  // free bodies the speed limits held back, warned once each
  std::vector<char> robot_limited(robots.size(), 0);
  double max_penetration = 0.0;  // m, over the states at the start of every step
  const LoopTimes times = runLoop(
      steps, csv != nullptr, options.every, isatty(STDERR_FILENO) && steps * (free + robots.size()) >= 2'000'000,
      [&](long long k) {
        const double t = static_cast<double>(k - 1) * dt;  // as the node's clock: steps × dt
        controls.loadsFor(state, t, loads.robots);         // the timeline's commands first, as the node gives them
        if (!drives.empty()) drives.loadsFor(state.bodies, t, loads.bodies);
        sensors.before(state);
        core::stepScene(scene, state, loads, ws);
        controls.observe(state, k, static_cast<double>(k) * dt);
        sensors.sample(state, loads, ws, k, static_cast<double>(k) * dt);
        body_sensors.sample(state.bodies, k, static_cast<double>(k) * dt);
        max_penetration = std::max(max_penetration, ws.bodies.deepest_penetration);
        if (!ws.bodies.speed_limited.empty() || !ws.bodies.diverged.empty()) {
          checkStep(model, ws.bodies, k * dt, limited);
        }
        for (std::size_t r = 0; r < robots.size(); ++r) {
          if (ws.robot_diverged[r]) {
            throw Diverged("robot '" + robots[r].name + "': its state stopped being finite at t = " + text(k * dt) +
                           " s (the step's guard put it back at rest; the run stops here)");
          }
          if (ws.robots[r].speed_limited && !robot_limited[r]) {
            robot_limited[r] = 1;
            warnRobotLimited(robots[r].name, model.limits(), k * dt);
          }
        }
      },
      write_rows);

  const double sim_time = static_cast<double>(steps) * dt;
  const double energy_end = sceneEnergy(scene, state);
  const core::Vec3 momentum_end = sceneAngularMomentum(scene, state);
  Json out = {{"steps", steps},
              {"sim_time", num(sim_time)},
              {"wall_s", num(times.wall_s)},
              {"ns_per_step", num(times.ns_per_step)}};
  out["energy"] = {{"start", num(energy_start)}, {"end", num(energy_end)}};
  out["angular_momentum"] = {{"start", vec(momentum_start)}, {"end", vec(momentum_end)}};
  for (std::size_t i = 0; i < free; ++i) {
    max_penetration = std::max(
        max_penetration, -std::min(0.0, core::minSeparation(model, state.bodies.bodies[i], static_cast<int>(i), 0.0)));
  }
  out["max_penetration"] = num(max_penetration);
  // Each entry in the config's order: a body, or a robot with its joints.
  std::vector<Json> entries;
  Json limited_json = Json::array();
  bool all_rest = true;
  int resting = 0;
  for (const int e : setup.entry) {
    Json entry;
    bool rest = false;
    if (e >= 0) {
      const core::BodyState& s = state.bodies.bodies[e];
      rest = core::atRest(model, s);
      entry = {{"name", model.body(e).name}, {"final", finalJson(core::linkState(model.body(e), s))}};
      if (limited[e]) limited_json.push_back(model.body(e).name);
    } else {
      const int r = -1 - e;
      rest = robotAtRest(robots[r].model, state.robots[r], model.sleep());
      Json final = finalJson(core::baseLinkState(state.robots[r]));
      final["joints"] = jointsJson(robots[r].model, state.robots[r]);
      entry = {{"name", robots[r].name}, {"final", final}};
      if (robot_limited[r]) limited_json.push_back(robots[r].name);
    }
    entry["at_rest"] = rest;
    all_rest = all_rest && rest;
    resting += rest;
    entries.push_back(entry);
  }
  if (alone) out["final"] = entries[0]["final"];  // as a body given alone has it
  out["at_rest"] = all_rest;
  out["speed_limited"] = limited_json;
  if (csv) csv->finish();
  controls.finish();
  sensors.finish();
  body_sensors.finish();
  JsonLine line(out, "bodies");
  for (const Json& entry : entries) line.element(entry);
  line.finish();

  if (!options.quiet) {
    std::fprintf(stderr,
                 "rbsim: %zu bodies and %zu robots for %.6g s: %lld steps of %.6g s, %.3g s wall, %.1f ns/step\n", free,
                 robots.size(), sim_time, steps, dt, times.wall_s, times.ns_per_step);
    std::fprintf(stderr, "  at rest           %d of %zu\n", resting, setup.entry.size());
    std::fprintf(stderr, "  energy            %.9g J -> %.9g J\n", energy_start, energy_end);
    std::fprintf(stderr, "  |L| about 0       %.9g -> %.9g kg m^2/s\n", momentum_start.norm(), momentum_end.norm());
    std::fprintf(stderr, "  contacts          deepest penetration %.3g mm, %s at the end\n", 1e3 * max_penetration,
                 all_rest ? "at rest" : "moving");
  }
  return 0;
}

}  // namespace rigid_body_sim::tools
