#!/usr/bin/env bash
# Interleaved A/B of two builds of the package: the world bench (N boxes
# dropped on a grid) with one thread and with two, and the one-body core
# step, alternating A and B each round so the machine's drift hits both.
# Prints each round's figures, then the medians over the rounds and whether
# the final states' hashes agree (bit-identical trajectories).
#
#   bench/ab.sh A_DEVEL_LIB B_DEVEL_LIB [rounds]
#
# A_DEVEL_LIB, B_DEVEL_LIB: the devel/lib folders of two Release builds
# (e.g. a `git worktree` of the old commit built with catkin_make, and .ws/devel/lib).
set -euo pipefail
A=$1 B=$2 ROUNDS=${3:-7}
out=$(mktemp -d)
for r in $(seq "$ROUNDS"); do
  for side in A B; do
    lib=${!side}
    for t in 1 2; do
      LD_LIBRARY_PATH="$lib" RBS_THREADS=$t "$lib/rigid_body_sim/world_bench" 3 10 100 1000 |
        awk -v s="$side" -v t="$t" 'NR > 1 {print s, t, $1, $3, $NF}' >>"$out/world"
    done
    LD_LIBRARY_PATH="$lib" "$lib/rigid_body_sim/bench_core_step" --benchmark_filter=BM_TorqueFreeSpin \
      --benchmark_repetitions=5 --benchmark_report_aggregates_only=true 2>/dev/null |
      awk -v s="$side" '/_median/ {print s, $2}' >>"$out/core"
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
    side, ns = line.split()
    core[side].append(float(ns))
a, b = statistics.median(core["A"]), statistics.median(core["B"])
print(f"core step (BM_TorqueFreeSpin), ns, median of the rounds' medians: A {a:.1f}  B {b:.1f}  B/A {b / a:.3f}")
PY
rm -rf "$out"
