#!/usr/bin/env bash
# The node against rbsim on the same world, in the same run (issue 32): the
# seed-42 pile of N boxes (pile_bench --yaml, the pile of issue 16), stepped
# for DURATION s of sim time as fast as each goes. rbsim steps it headless
# (its JSON gives sim time over stepping wall time); sim_node free-runs it
# (~realtime_factor 0) on sim time, started paused and unpaused once
# clock_rtf listens, which reads /clock from the first update until DURATION. Peak resident memory of each: rbsim by
# /usr/bin/time, the node by VmHWM. ROUNDS rounds, the two interleaved;
# medians (VERBOSE=1 prints each run). No one subscribes to the node's
# topics but /clock.
# Usage: bench/node_rtf.sh [ROUNDS] [N ...]   (default 3 rounds, N = 1000 10000; DURATION=2)
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
ROUNDS=${1:-3}
shift || true
SIZES=("$@")
[ ${#SIZES[@]} -eq 0 ] && SIZES=(1000 10000)
DURATION=${DURATION:-2}
rbs_bench_node_setup 11519
core=$RBS_MASTER_PID
node=
dir=$(mktemp -d)
trap 'if [ -n "$node" ]; then kill -INT $node; wait $node; fi 2>/dev/null; kill -INT $core; wait $core 2>/dev/null; rm -rf "$dir"' EXIT
lib=$RBS_WS/devel/lib/rigid_body_sim
rosparam set /use_sim_time true
echo "date: $(date -u +%F), DURATION $DURATION s, ROUNDS $ROUNDS"
for n in "${SIZES[@]}"; do
  "$lib/pile_bench" --yaml "$n" "$RBS_ROOT/urdf/box.urdf" >"$dir/pile_$n.yaml"
done
for round in $(seq "$ROUNDS"); do
  for n in "${SIZES[@]}"; do
    /usr/bin/time -f %M -o "$dir/rss" "$lib/rbsim" --config "$dir/pile_$n.yaml" --duration "$DURATION" --quiet >"$dir/out.json"
    /usr/bin/python3 -c 'import json, sys
j = json.load(open(sys.argv[1]))
print("rbsim N", sys.argv[2], "rtf", j["sim_time"] / j["wall_s"], "peak_kb", open(sys.argv[3]).read().split()[-1])' \
      "$dir/out.json" "$n" "$dir/rss" >>"$dir/rows"
    rosparam delete /sim_node >/dev/null 2>&1 || true
    rosparam load "$dir/pile_$n.yaml" /sim_node
    rosparam set /sim_node/realtime_factor 0
    rosparam set /sim_node/paused true
    "$lib/clock_rtf" "$DURATION" >"$dir/clock" &
    reader=$!
    "$lib/sim_node" >"$dir/node.log" 2>&1 &
    node=$!
    until rosservice list 2>/dev/null | grep -q /sim_node/unpause; do sleep 0.2; done
    sleep 1  # the reader connected to /clock
    rosservice call /sim_node/unpause >/dev/null
    wait $reader || { echo "no /clock reached $DURATION s (node log: $dir/node.log)" >&2; exit 1; }
    hwm=$(awk '/VmHWM/ {print $2}' "/proc/$node/status")
    kill -INT $node
    wait $node 2>/dev/null || true
    node=
    echo "node N $n rtf $(awk '{print $6}' "$dir/clock") peak_kb $hwm" >>"$dir/rows"
  done
  echo "round $round of $ROUNDS done" >&2
done
[ -n "${VERBOSE:-}" ] && cat "$dir/rows"
/usr/bin/python3 - "$dir/rows" <<'PY'
import collections, statistics, sys
rows = collections.defaultdict(list)
for line in open(sys.argv[1]):
    f = line.split()
    rows[(int(f[2]), f[0])].append((float(f[4]), float(f[6])))
print(f"{'N':>6} {'rbsim RTF':>10} {'node RTF':>9} {'node/rbsim':>10} {'rbsim KB/body':>13} {'node KB/body':>12} {'ratio':>6}")
for n in sorted({k[0] for k in rows}):
    r, s = rows[(n, "rbsim")], rows[(n, "node")]
    rr, nr = statistics.median(x[0] for x in r), statistics.median(x[0] for x in s)
    rk, nk = statistics.median(x[1] for x in r) / n, statistics.median(x[1] for x in s) / n
    print(f"{n:>6} {rr:>10.3f} {nr:>9.3f} {nr / rr:>10.2f} {rk:>13.1f} {nk:>12.1f} {nk / rk:>6.2f}")
PY
