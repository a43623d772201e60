#!/usr/bin/env bash
# Benchmarks (Release build). Prints medians of several runs; the figures go
# into bench/README.md with the date. Usage: bench/run.sh [repetitions]
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
REPS=${1:-7}
rbs_install_packages
RBS_BUILD_TYPE=Release rbs_build >/dev/null
BIN="$RBS_WS/devel/lib/rigid_body_sim"

echo "== core step, one body (Google Benchmark, median of $REPS)"
"$BIN/bench_core_step" --benchmark_repetitions="$REPS" --benchmark_report_aggregates_only=true 2>/dev/null |
  grep -E '_median|^Benchmark'

echo "== rbsim whole run: torque-free spin of the shipped box, 20 s at 1 ms, output excluded (median of $REPS)"
for i in $(seq "$REPS"); do
  "$BIN/rbsim" --urdf "$RBS_ROOT/urdf/box.urdf" --config "$RBS_ROOT/config/spin.yaml" --duration 20 --quiet
done | /usr/bin/python3 -c '
import json, statistics, sys
runs = [json.loads(line) for line in sys.stdin]
ns = sorted(r["ns_per_step"] for r in runs)
e0, e1 = runs[0]["energy"]["start"], runs[0]["energy"]["end"]
l0, l1 = runs[0]["angular_momentum"]["start"], runs[0]["angular_momentum"]["end"]
norm = lambda v: sum(x * x for x in v) ** 0.5
print(f"ns_per_step median {statistics.median(ns):.1f} (min {ns[0]:.1f}, max {ns[-1]:.1f}) over {len(ns)} runs")
print(f"energy relative change {(e1 - e0) / e0:.2e}, |L| relative change {(norm(l1) - norm(l0)) / norm(l0):.2e}")
'

echo "== contacts: box drop (10 s) and mesh bodies against their vertex count (median of $REPS)"
"$BIN/bench_contact" --benchmark_repetitions="$REPS" --benchmark_report_aggregates_only=true 2>/dev/null |
  grep -E '_median|^Benchmark'

echo "== many bodies: N boxes dropped on a grid, 2 s (median of 3 runs; one thread, then every core)"
RBS_THREADS=1 "$BIN/world_bench" 3
"$BIN/world_bench" 3

echo "== many bodies: which boxes still move at 2 s, and why (N = 1000, one run)"
"$BIN/rest_census"

echo "== gyroscopic integrator study (one run; ns/step is indicative only)"
"$BIN/gyroscopic_study"
