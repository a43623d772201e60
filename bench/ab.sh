#!/usr/bin/env bash
# Interleaved A/B of two builds of the package: the world bench (N boxes
# dropped on a grid) with one thread and with two, the one-body core steps,
# the box drop of the contacts bench and rbsim's torque-free spin,
# alternating A and B each round so the machine's drift hits both.
# Prints each round's figures, then the medians over the rounds and whether
# the final states' hashes agree (bit-identical trajectories).
#
#   bench/ab.sh A_DEVEL_LIB B_DEVEL_LIB [rounds]
#
# A_DEVEL_LIB, B_DEVEL_LIB: the devel/lib folders of two Release builds
# (e.g. a `git worktree` of the old commit built with catkin_make, and .ws/devel/lib).
set -euo pipefail
A=$1 B=$2 ROUNDS=${3:-7}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
for r in $(seq "$ROUNDS"); do
  for side in A B; do
    lib=${!side}
    for t in 1 2; do
      LD_LIBRARY_PATH="$lib" RBS_THREADS=$t "$lib/rigid_body_sim/world_bench" 3 10 100 1000 |
        awk -v s="$side" -v t="$t" 'NR > 1 {print s, t, $1, $3, $NF}' >>"$out/world"
    done
    LD_LIBRARY_PATH="$lib" "$lib/rigid_body_sim/bench_core_step" \
      --benchmark_repetitions=5 --benchmark_report_aggregates_only=true 2>/dev/null |
      awk -v s="$side" '/_median/ {print s, $1, $2}' >>"$out/core"
    LD_LIBRARY_PATH="$lib" "$lib/rigid_body_sim/bench_contact" --benchmark_filter='BM_BoxDrop/0/1' \
      --benchmark_repetitions=3 --benchmark_report_aggregates_only=true 2>/dev/null |
      awk -v s="$side" '/_median/ {print s, "BM_BoxDrop_ms", $2}' >>"$out/core"
    LD_LIBRARY_PATH="$lib" "$lib/rigid_body_sim/rbsim" --urdf "$ROOT/urdf/box.urdf" --config "$ROOT/config/spin.yaml" \
      --duration 20 --quiet | /usr/bin/python3 -c 'import json,sys; print(sys.argv[1], "rbsim_spin", json.load(sys.stdin)["ns_per_step"])' "$side" >>"$out/core"
  done
done
/usr/bin/python3 - "$out" <<'PY'
import collections, statistics, sys
d = sys.argv[1]
world = collections.defaultdict(list)
hashes = collections.defaultdict(set)
for line in open(f"{d}/world"):
    side, threads, n, ns_body, h = line.split()
    world[(threads, n, side)].append(float(ns_body))
    hashes[(threads, n, side)].add(h)
print("world bench, ns per body-step, median of the rounds (each round a median of 3 runs):")
print(f"{'threads':>7} {'N':>5} {'A':>9} {'B':>9} {'B/A':>6}  hashes")
for threads in ("1", "2"):
    for n in ("10", "100", "1000"):
        a, b = statistics.median(world[(threads, n, "A")]), statistics.median(world[(threads, n, "B")])
        same = "equal" if hashes[(threads, n, "A")] == hashes[(threads, n, "B")] and len(hashes[(threads, n, "A")]) == 1 else "DIFFER"
        print(f"{threads:>7} {n:>5} {a:9.1f} {b:9.1f} {b / a:6.3f}  {same} ({' '.join(sorted(hashes[(threads, n, 'B')]))})")
core = collections.defaultdict(list)
for line in open(f"{d}/core"):
    side, name, value = line.split()
    core[(name, side)].append(float(value))
print("one body, median of the rounds (each a median of its repetitions):")
for name in sorted({n for n, _ in core}):
    a, b = statistics.median(core[(name, "A")]), statistics.median(core[(name, "B")])
    unit = "ms" if name.endswith("_ms") else "ns"
    print(f"  {name:<50} A {a:8.1f}  B {b:8.1f} {unit}  B/A {b / a:.3f}")
PY
rm -rf "$out"
