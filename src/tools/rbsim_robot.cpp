// rbsim's run of a robot: rbsim_robot.h.
#include "rbsim_robot.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>

#include "rbsim_loop.h"
#include "rbsim_output.h"
#include "rbsim_report.h"
#include "rigid_body_sim/core/articulation_dynamics.h"
#include "rigid_body_sim/core/articulation_step.h"
#include "rigid_body_sim/io/robot.h"
#include "rigid_body_sim/io/world.h"

namespace rigid_body_sim::tools {
int runRobot(const io::SimConfig& config, core::ArticulationModel articulation, const RunOptions& options) {
  io::Robot robot = io::buildRobot(config, std::move(articulation));
  const core::ArticulationModel& model = robot.model;
  core::ArticulationState& state = robot.state;
  const core::Model& settings = robot.colliders.bodies;  // dt, gravity, scene, contact, limits
  const double dt = settings.dt();
  const core::Vec3 g = settings.gravity();
  const long long steps = stepCount(options.duration, dt);
  if (!settings.scene().empty() && settings.bodyCount() == 0) {
    std::fprintf(stderr,
                 "rbsim: warning: robot '%s' has no <collision> geometry on a moving link: it touches nothing, as in "
                 "Gazebo\n",
                 model.name.c_str());
  }
  const std::string inside = io::insideSceneNote(settings, core::linkStates(robot.colliders, model, state), 0,
                                                 settings.bodyCount(), "robot '" + model.name + "'");
  if (!inside.empty()) std::fprintf(stderr, "rbsim: warning: %s\n", inside.c_str());
  std::vector<std::string> joints;
  for (int i = 1; i <= model.jointCount(); ++i) joints.push_back(model.links[i].joint);
  const double energy_start = robotEnergy(model, state, g);
  const core::Vec3 momentum_start = robotAngularMomentum(model, state);

  std::unique_ptr<CsvWriter> csv;
  if (!options.csv.empty()) csv = std::make_unique<CsvWriter>(options.csv, false, joints);
  const auto write_row = [&](long long done) { csv->row(done * dt, core::baseLinkState(state), state.q, state.v); };
  core::ArticulationWorkspace ws;
  const core::ArticulationLoads loads;
  bool limited = false;
  double max_penetration = 0.0;  // m, over the states at the start of every step
  const LoopTimes times = runLoop(
      steps, csv != nullptr, options.every, isatty(STDERR_FILENO) && steps >= 200'000,
      [&](long long k) {
        if (!core::stepArticulation(model, state, loads, g, dt, settings.limits(), &ws, &robot.colliders)) {
          throw Diverged("robot '" + model.name + "': its state stopped being finite at t = " + text(k * dt) +
                         " s (the step's guard put it back at rest; the run stops here)");
        }
        max_penetration = std::max(max_penetration, ws.detection.deepest_penetration);
        if (ws.speed_limited && !limited) {
          limited = true;
          warnRobotLimited(model.name, settings.limits(), k * dt);
        }
      },
      write_row);
  const double wall_s = times.wall_s;
  const double ns_per_step = times.ns_per_step;

  const double sim_time = static_cast<double>(steps) * dt;
  const double energy_end = robotEnergy(model, state, g);
  const core::Vec3 momentum_end = robotAngularMomentum(model, state);
  const bool rest = robotAtRest(model, state, settings.sleep());
  Json final = finalJson(core::baseLinkState(state));
  final["joints"] = jointsJson(model, state);
  Json out = {
      {"steps", steps}, {"sim_time", num(sim_time)}, {"wall_s", num(wall_s)}, {"ns_per_step", num(ns_per_step)}};
  out["final"] = final;
  out["energy"] = {{"start", num(energy_start)}, {"end", num(energy_end)}};
  out["angular_momentum"] = {{"start", vec(momentum_start)}, {"end", vec(momentum_end)}};
  out["max_penetration"] = num(max_penetration);
  out["at_rest"] = rest;
  out["speed_limited"] = limited ? Json::array({model.name}) : Json::array();
  if (csv) csv->finish();
  JsonLine line(out, "bodies");
  line.element({{"name", model.name}, {"final", final}, {"at_rest", rest}});
  line.finish();

  if (!options.quiet) {
    const core::LinkState base = core::baseLinkState(state);
    std::fprintf(stderr,
                 "rbsim: robot '%s' (%.6g kg, %d joints, base %s) for %.6g s: %lld steps of %.6g s, %.3g s wall, "
                 "%.1f ns/step\n",
                 model.name.c_str(), core::totalMass(model), model.jointCount(),
                 model.fixed_base ? "fixed to the world" : "floating", sim_time, steps, dt, wall_s, ns_per_step);
    std::fprintf(stderr, "  final base        [%.6g, %.6g, %.6g] m, velocity [%.6g, %.6g, %.6g] m/s\n", base.p_WL.x(),
                 base.p_WL.y(), base.p_WL.z(), base.v_WL.x(), base.v_WL.y(), base.v_WL.z());
    for (int i = 1; i <= model.jointCount(); ++i) {
      std::fprintf(stderr, "  joint %-11s %.6g, velocity %.6g\n", joints[i - 1].c_str(), state.q(i - 1),
                   state.v(i - 1));
    }
    std::fprintf(stderr, "  energy            %.9g J -> %.9g J\n", energy_start, energy_end);
    std::fprintf(stderr, "  contacts          deepest penetration %.3g mm, %s at the end\n", 1e3 * max_penetration,
                 rest ? "at rest" : "moving");
  }
  return 0;
}

}  // namespace rigid_body_sim::tools
