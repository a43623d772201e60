#!/usr/bin/env bash
# What N bodies spawned one at a time cost the node against the same N
# loaded at start (issue 32): for each N (default 1000), sim_node at
# ~rate 1000 with ~report_timing, first with N balls listed in ~bodies
# (its resident memory once they rest), then with an empty world into which
# spawn_many spawns the same N balls at the same places one call at a time,
# then deletes them all (its memory after each). The node's timing report
# gives what each spawn and delete cost the loop. Memory is VmRSS, in MB.
# Usage: bench/spawn_memory.sh [N ...]
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
COUNTS=("$@")
[[ ${#COUNTS[@]} -gt 0 ]] || COUNTS=(1000)
rbs_bench_node_setup 11512
core=$RBS_MASTER_PID
node=
trap 'if [ -n "$node" ]; then kill -INT $node; wait $node; fi 2>/dev/null; kill -INT $core; wait $core 2>/dev/null || true' EXIT
lib=$RBS_WS/devel/lib/rigid_body_sim
out=$ROS_HOME/spawn_memory
mkdir -p "$out"
ball=$RBS_ROOT/urdf/ball.urdf
bodies() {  # the grid spawn_many uses, as ~bodies
  /usr/bin/python3 -c "
import math, sys
n = int(sys.argv[1]); side = math.ceil(math.sqrt(n))
print('[' + ', '.join('{name: b%d, urdf: %s, initial: {position: [%g, %g, 0.5]}}'
                      % (i, sys.argv[2], 0.6 * (i % side), 0.6 * (i // side)) for i in range(n)) + ']')" "$1" "$ball"
}
rss() { awk '/VmRSS/ {printf "%.1f", $2 / 1024}' "/proc/$node/status"; }
run_node() {  # BODIES LOG
  rosparam delete /sim_node >/dev/null 2>&1 || true
  rosparam set /sim_node/report_timing true
  rosparam set /sim_node/bodies "$1"
  "$lib/sim_node" >"$2" 2>&1 &
  node=$!
  until rosservice list 2>/dev/null | grep -q /sim_node/spawn_body; do sleep 0.2; done
}
stop_node() {
  kill -INT "$node"
  wait "$node" || true
  node=
}
echo "date: $(date -u +%F)"
for n in "${COUNTS[@]}"; do
  run_node "$(bodies "$n")" "$out/loaded_$n.log"
  sleep 5
  loaded=$(rss)
  stop_node
  run_node "[]" "$out/spawned_$n.log"
  sleep 2
  empty=$(rss)
  "$lib/spawn_many" spawn "$n" "$ball"
  sleep 5
  spawned=$(rss)
  "$lib/spawn_many" delete "$n" "$ball"
  sleep 2
  deleted=$(rss)
  stop_node
  echo "N $n: loaded at start ${loaded} MB; empty ${empty} MB, ${n} spawned ${spawned} MB, all deleted ${deleted} MB"
  /usr/bin/python3 -c "import sys; l, e, s, d = map(float, sys.argv[1:]); print(f'  spawned / loaded {s / l:.2f}, deleted - empty {d - e:+.1f} MB')" \
    "$loaded" "$empty" "$spawned" "$deleted"
  grep -o 'timing: [0-9]* \(spawns\|deletes\).*' "$out/spawned_$n.log" | sed 's/^/  /'
done
