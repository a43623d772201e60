// Contact benchmarks (issue 3), Google Benchmark; run through bench/run.sh.
//  - BM_BoxDrop: the shipped box (half extents 0.2 × 0.1 × 0.05 m, 1 kg)
//    dropped from 1 m, tumbling, onto the ground; 10 s at Δt = 1 ms, with and
//    without sleeping. Counters: ns per step, deepest penetration (mm), time
//    from the first impact until it stops moving (s).
//  - BM_Rolling: a ball (0, for comparison), a cylinder (1) or a capsule
//    (2), radius 0.1 m (length 0.3 m), 2 kg, rolling at 1 m/s on the ground
//    for 5 s without sleeping: ns per step, and the speed kept (%).
//  - BM_MeshDrop: a mesh body of N vertices (a UV sphere written as OBJ and
//    loaded through the URDF loader and assimp) dropped from 0.3 m, 3 s,
//    without sleeping: ns per step against N.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "rigid_body_sim/core/step/step.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/io/world.h"

namespace {

using namespace rigid_body_sim;
using core::Vec3;

const char* kBoxUrdf = R"(<robot name="box"><link name="base_link">
  <inertial><mass value="1"/><inertia ixx="0.004166666666666667" iyy="0.014166666666666668" izz="0.016666666666666666" ixy="0" ixz="0" iyz="0"/></inertial>
  <collision><geometry><box size="0.4 0.2 0.1"/></geometry></collision></link></robot>)";

struct Run {
  double deepest = 0.0, first_impact = -1.0, last_moving = 0.0;
  std::size_t repeated = 0;  ///< steps found to be a fixed point (the fixed-point cache, src/core/step/fixed_point.h)
};

Run simulate(const core::Model& model, core::State s, int steps, bool skip_fixed_points) {
  Run r;
  core::Workspace ws;
  ws.skip_fixed_points = skip_fixed_points;
  for (int n = 0; n < steps; ++n) {
    core::step(model, s, {}, &ws);
    r.deepest = std::max(r.deepest, ws.deepest_penetration);
    if (r.first_impact < 0.0 && !ws.contacts.empty()) r.first_impact = s.time;
    if (s.bodies[0].still_time == 0.0) r.last_moving = s.time;
  }
  r.repeated = ws.skipped_steps;
  return r;
}

/// Runs the scenario once per benchmark iteration and sets the counters:
/// ns per step (the run's time over its steps), deepest penetration (mm),
/// seconds from the first impact until the body stopped moving, and the
/// share of steps that were a fixed point and not computed again.
void measure(benchmark::State& bench, const core::Model& model, const core::State& start, int steps,
             bool skip_fixed_points = true) {
  Run r;
  double ns = 0.0;
  for (auto _ : bench) {
    const auto t0 = std::chrono::steady_clock::now();
    r = simulate(model, start, steps, skip_fixed_points);
    ns += std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
  }
  bench.counters["ns_per_step"] = ns / static_cast<double>(bench.iterations()) / steps;
  bench.counters["deepest_mm"] = 1e3 * r.deepest;
  bench.counters["rest_after_impact_s"] = r.last_moving - r.first_impact;
  bench.counters["repeated_steps"] = static_cast<double>(r.repeated) / steps;
}

void BM_BoxDrop(benchmark::State& bench) {
  const bool sleep = bench.range(0) != 0, skip = bench.range(1) != 0;
  io::SimConfig config =
      io::parseConfig(YAML::Load("initial: {position: [0, 0, 1], rpy: [0.5, 0.2, 0.1], angular_velocity: [1, 2, 3]}"));
  config.model.sleep.enabled = sleep;
  const core::Model model = io::buildModel(config, io::loadUrdfString(kBoxUrdf, "box"));
  const core::State start{0.0, {core::bodyStateFromLink(model.body(0), config.initial)}, {}};
  measure(bench, model, start, 10000, skip);
  bench.SetLabel(std::string(sleep ? "sleep on" : "sleep off") + (skip ? "" : ", every step computed"));
}
// {sleep, skip fixed points}: the issue's figure is {0, 1}; {0, 0} computes
// every step, for the comparison in the same run.
BENCHMARK(BM_BoxDrop)->Args({0, 1})->Args({0, 0})->Args({1, 1})->Unit(benchmark::kMillisecond);

/// A UV sphere of radius 0.1 m with `rings` × `segments` + 2 vertices, as OBJ.
std::string writeSphereObj(int rings, int segments) {
  const std::string path = "/tmp/rbs_bench_sphere_" + std::to_string(::getpid()) + "_" + std::to_string(rings) + "x" +
                           std::to_string(segments) + ".obj";
  std::ofstream out(path);
  out << "v 0 0 0.1\n";
  for (int i = 1; i <= rings; ++i) {
    const double theta = M_PI * i / (rings + 1);
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * M_PI * j / segments;
      out << "v " << 0.1 * std::sin(theta) * std::cos(phi) << " " << 0.1 * std::sin(theta) * std::sin(phi) << " "
          << 0.1 * std::cos(theta) << "\n";
    }
  }
  out << "v 0 0 -0.1\n";
  const int last = rings * segments + 2;
  auto at = [&](int i, int j) { return 2 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) out << "f 1 " << at(1, j) << " " << at(1, j + 1) << "\n";
  for (int i = 1; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      out << "f " << at(i, j) << " " << at(i + 1, j) << " " << at(i + 1, j + 1) << " " << at(i, j + 1) << "\n";
    }
  }
  for (int j = 0; j < segments; ++j) out << "f " << last << " " << at(rings, j + 1) << " " << at(rings, j) << "\n";
  return path;
}

void BM_Rolling(benchmark::State& bench) {
  const int shape = static_cast<int>(bench.range(0));
  const std::string geometry = shape == 0 ? "sphere" : shape == 1 ? "cylinder" : "capsule";
  const std::string urdf = R"(<robot name="round"><link name="round">
    <inertial><mass value="2"/><inertia ixx="0.02" iyy="0.02" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><)" +
                           geometry + R"( radius="0.1" length="0.3"/></geometry></collision></link></robot>)";
  const core::BodySpec body = io::loadUrdfString(urdf, "round");
  io::SimConfig config = io::parseConfig(
      YAML::Load("initial: {position: [0, 0, 0.1], rpy: [-1.5707963267948966, 0, 0], linear_velocity: [1, 0, 0], "
                 "angular_velocity: [0, 10, 0]}\nsleep: {enabled: false}"));
  const core::Model model = io::buildModel(config, body);
  const core::State start{0.0, {core::bodyStateFromLink(model.body(0), config.initial)}, {}};
  measure(bench, model, start, 5000);
  core::State s = start;
  for (int n = 0; n < 5000; ++n) core::step(model, s);
  bench.counters["speed_kept_pct"] = 100.0 * s.bodies[0].v_WB.x();
}
BENCHMARK(BM_Rolling)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_MeshDrop(benchmark::State& bench) {
  const int rings = static_cast<int>(bench.range(0)), segments = static_cast<int>(bench.range(1));
  const std::string obj = writeSphereObj(rings, segments);
  const std::string urdf = std::string(R"(<robot name="mesh"><link name="mesh">
    <inertial><mass value="1"/><inertia ixx="0.004" iyy="0.004" izz="0.004" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><mesh filename="file://)") +
                           obj + R"("/></geometry></collision></link></robot>)";
  io::SimConfig config =
      io::parseConfig(YAML::Load("initial: {position: [0, 0, 0.4], rpy: [0.3, 0.2, 0]}\nsleep: {enabled: false}"));
  const core::Model model = io::buildModel(config, io::loadUrdfString(urdf, "mesh"));
  std::filesystem::remove(obj);
  const core::State start{0.0, {core::bodyStateFromLink(model.body(0), config.initial)}, {}};
  measure(bench, model, start, 3000);
  bench.counters["vertices"] = static_cast<double>(model.body(0).contact_points.size());
}
BENCHMARK(BM_MeshDrop)
    ->Args({10, 16})  // 162 vertices
    ->Args({20, 25})  // 502
    ->Args({25, 40})  // 1002
    ->Args({40, 50})  // 2002
    ->Args({50, 80})  // 4002
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
