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
#include "rigid_body_sim/core/articulation_dynamics.h"
#include "rigid_body_sim/core/articulation_step.h"
#include "rigid_body_sim/io/robot.h"

namespace rigid_body_sim::tools {
namespace {

/// The base link's pose and twist in the world (its twist is kept in its own axes).
core::LinkState baseState(const core::ArticulationState& s) {
  const core::Mat3 R = s.X_WB.rotation.toRotationMatrix();
  return {s.X_WB.translation, s.X_WB.rotation, R * s.V_B.tail<3>(), R * s.V_B.head<3>()};
}

double energy(const core::ArticulationModel& model, const core::ArticulationState& s, const core::Vec3& g) {
  const core::ArticulationKinematics kin = core::kinematics(model, s);
  return core::kineticEnergy(model, kin) + core::potentialEnergy(model, kin, g);
}

/// The whole robot's angular momentum about the world origin.
core::Vec3 angularMomentum(const core::ArticulationModel& model, const core::ArticulationState& s) {
  return core::momentum_W(model, core::kinematics(model, s)).head<3>();
}

/// At rest: every joint and the base slower than the sleep speeds (a
/// prismatic joint and the base's v by the linear one).
bool atRest(const core::ArticulationModel& model, const core::ArticulationState& s, const core::SleepSettings& sleep) {
  if (s.V_B.head<3>().norm() >= sleep.angular_velocity || s.V_B.tail<3>().norm() >= sleep.linear_velocity) return false;
  for (int i = 1; i <= model.jointCount(); ++i) {
    const bool slides = model.links[i].type == core::JointType::Prismatic;
    if (std::abs(s.v(i - 1)) >= (slides ? sleep.linear_velocity : sleep.angular_velocity)) return false;
  }
  return true;
}

}  // namespace

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
  std::vector<std::string> joints;
  for (int i = 1; i <= model.jointCount(); ++i) joints.push_back(model.links[i].joint);
  const double energy_start = energy(model, state, g);
  const core::Vec3 momentum_start = angularMomentum(model, state);

  std::unique_ptr<CsvWriter> csv;
  if (!options.csv.empty()) csv = std::make_unique<CsvWriter>(options.csv, false, joints);
  const auto write_row = [&](long long done) { csv->row(done * dt, baseState(state), state.q, state.v); };
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
          std::fprintf(stderr,
                       "rbsim: warning: robot '%s' reached the speed limits at t = %s s (limits.max_linear_speed %s "
                       "m/s, limits.max_angular_speed %s rad/s): its velocities are held to them\n",
                       model.name.c_str(), text(k * dt).c_str(), text(settings.limits().max_linear_speed).c_str(),
                       text(settings.limits().max_angular_speed).c_str());
        }
      },
      write_row);
  const double wall_s = times.wall_s;
  const double ns_per_step = times.ns_per_step;

  const double sim_time = static_cast<double>(steps) * dt;
  const double energy_end = energy(model, state, g);
  const core::Vec3 momentum_end = angularMomentum(model, state);
  const bool rest = atRest(model, state, settings.sleep());
  Json final = finalJson(baseState(state));
  Json joint_json = Json::object();
  for (int i = 1; i <= model.jointCount(); ++i) {
    joint_json[joints[i - 1]] = {{"position", num(state.q(i - 1))}, {"velocity", num(state.v(i - 1))}};
  }
  final["joints"] = joint_json;
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
    const core::LinkState base = baseState(state);
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
