// One core step of one body (Google Benchmark). Run through bench/run.sh.
#include <benchmark/benchmark.h>

#include "rigid_body_sim/core/step/step.h"

namespace {

using namespace rigid_body_sim::core;

/// The issues' box: half extents 0.2 × 0.1 × 0.05 m, 1 kg, Δt = 1 ms.
ModelSpec shippedBox(bool gyroscopic, const Vec3& gravity) {
  BodySpec b;
  b.mass = 1.0;
  b.I_C_L = Vec3(0.0125 / 3.0, 0.0425 / 3.0, 0.05 / 3.0).asDiagonal();
  ModelSpec s;
  s.bodies = {b};
  s.dt = 1e-3;
  s.gravity_W = gravity;
  s.gyroscopic = gyroscopic;
  return s;
}

/// Steps the 20 s scenario of issue 2 over and over (20 000 steps, then restart).
void runSpin(benchmark::State& bench, const Model& model, const Loads& loads) {
  LinkState start;
  start.w_W = Vec3(0.01, 3.0, 0.0);
  const State initial{0.0, {bodyStateFromLink(model.body(0), start)}};
  State s = initial;
  Workspace ws;
  int n = 0;
  for (auto _ : bench) {
    step(model, s, loads, &ws);
    if (++n == 20000) {
      s = initial;
      n = 0;
    }
    benchmark::DoNotOptimize(s.bodies[0]);
  }
}

void BM_TorqueFreeSpin(benchmark::State& bench) {
  const Model model(shippedBox(true, Vec3::Zero()));
  runSpin(bench, model, {});
}
BENCHMARK(BM_TorqueFreeSpin);

void BM_TorqueFreeSpin_GyroscopeOff(benchmark::State& bench) {
  const Model model(shippedBox(false, Vec3::Zero()));
  runSpin(bench, model, {});
}
BENCHMARK(BM_TorqueFreeSpin_GyroscopeOff);

void BM_SpinWithGravityAndBodyWrench(benchmark::State& bench) {
  const Model model(shippedBox(true, Vec3(0, 0, -9.81)));
  Loads loads(1);
  addWrench(model.body(0), loads[0], {Vec3(0.1, 0, 0), Vec3(0, 0, 0.001), Vec3(0.1, 0, 0), Frame::kBody});
  runSpin(bench, model, loads);
}
BENCHMARK(BM_SpinWithGravityAndBodyWrench);

}  // namespace

BENCHMARK_MAIN();
