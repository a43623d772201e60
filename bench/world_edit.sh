#!/usr/bin/env bash
# Spawn and delete latency, and whether a spawn stalls the 1 kHz loop
# (issue 14). For N boxes resting in the world (N = 1, 100, 1000 by
# default): sim_node at ~rate 1000 with ~report_timing, and edit_latency
# timing ROUNDS spawns and deletes of a box, then MESH_ROUNDS of a body whose
# collision is a 1,952-vertex mesh (its distance grid is built at spawn, on
# the spawn thread), one a second. A second run of the same world without
# edits, for as long, gives the loop's timing to compare with.
# Usage: bench/world_edit.sh [ROUNDS] [MESH_ROUNDS] [N...]
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
ROUNDS=${1:-50} MESH_ROUNDS=${2:-5}
shift 2 || true
COUNTS=("$@")
[[ ${#COUNTS[@]} -gt 0 ]] || COUNTS=(1 100 1000)
rbs_bench_node_setup 11496
core=$RBS_MASTER_PID
trap 'kill -INT $core 2>/dev/null; wait $core 2>/dev/null || true' EXIT
lib=$RBS_WS/devel/lib/rigid_body_sim
out=$ROS_HOME/world_edit
mkdir -p "$out"
# A UV sphere of radius 0.1 m: 40 stacks x 50 slices = 1,952 vertices.
/usr/bin/python3 - "$out" <<'PY'
import math, sys
out = sys.argv[1]
stacks, slices, r = 40, 50, 0.1
v = [(0, 0, r)]
for i in range(1, stacks):
    t = math.pi * i / stacks
    v += [(r * math.sin(t) * math.cos(2 * math.pi * j / slices), r * math.sin(t) * math.sin(2 * math.pi * j / slices),
           r * math.cos(t)) for j in range(slices)]
v.append((0, 0, -r))
f = []
ring = lambda i, j: 2 + (i - 1) * slices + j % slices  # 1-based, stack i >= 1
for j in range(slices):
    f.append((1, ring(1, j), ring(1, j + 1)))
    f.append((len(v), ring(stacks - 1, j + 1), ring(stacks - 1, j)))
for i in range(1, stacks - 1):
    for j in range(slices):
        f += [(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)), (ring(i, j), ring(i + 1, j + 1), ring(i, j + 1))]
with open(out + "/sphere.obj", "w") as o:
    o.writelines("v %.9f %.9f %.9f\n" % p for p in v)
    o.writelines("f %d %d %d\n" % t for t in f)
print("mesh: %d vertices, %d triangles" % (len(v), len(f)))
with open(out + "/mesh_ball.urdf", "w") as o:
    o.write("""<robot name="mesh_ball"><link name="mesh_ball">
  <inertial><mass value="1"/><inertia ixx="0.004" iyy="0.004" izz="0.004" ixy="0" ixz="0" iyz="0"/></inertial>
  <collision><geometry><mesh filename="%s/sphere.obj"/></geometry></collision>
</link></robot>
""" % out)
PY
# N boxes resting on the ground, 0.6 m apart (they sleep within a second).
bodies() {
  /usr/bin/python3 -c "
import math, sys
n = int(sys.argv[1]); side = math.ceil(math.sqrt(n))
print('[' + ', '.join('{name: b%d, urdf: package://rigid_body_sim/urdf/box.urdf, initial: {position: [%g, %g, 0.05]}}'
                      % (i, 0.6 * (i % side), 0.6 * (i // side)) for i in range(n)) + ']')" "$1"
}
run_node() {  # N LOG: the node in the background, waited for
  rosparam delete /sim_node >/dev/null 2>&1 || true
  rosparam set /sim_node/report_timing true
  rosparam set /sim_node/bodies "$(bodies "$1")"
  "$lib/sim_node" >"$2" 2>&1 &
  node=$!
  until rosservice list 2>/dev/null | grep -q /sim_node/spawn_body; do sleep 0.2; done
  sleep 2  # past the start, the boxes asleep
}
stop_node() {
  kill -INT "$node"
  wait "$node" || true
}
echo "date: $(date -u +%F), ROUNDS $ROUNDS, MESH_ROUNDS $MESH_ROUNDS"
for n in "${COUNTS[@]}"; do
  echo "== N = $n boxes"
  run_node "$n" "$out/node_edits_$n.log"
  start=$(date +%s.%N)
  "$lib/edit_latency" package://rigid_body_sim/urdf/box.urdf "$ROUNDS" "$out/mesh_ball.urdf" "$MESH_ROUNDS"
  took=$(/usr/bin/python3 -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$start" "$(date +%s.%N)")
  stop_node
  echo "with edits:    $(grep -o 'timing: .*' "$out/node_edits_$n.log")"
  run_node "$n" "$out/node_idle_$n.log"
  sleep "$took"
  stop_node
  echo "without edits: $(grep -o 'timing: .*' "$out/node_idle_$n.log")"
done
