#!/usr/bin/env bash
# What spawning and deleting a robot with its controllers leaves behind
# (issue 45): sim_node at ~rate 1000 with an empty world, a controller
# loaded under /r as a Gazebo user loads it; spawn_many cycles
# urdf/arm2.urdf (spawned as r, its controllers from /r, then deleted)
# WARM times, then CYCLES times twice. Prints the node's resident memory
# (VmRSS, MB) after each batch and the calls' latency.
# Usage: bench/robot_cycles.sh [CYCLES] [WARM]
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
CYCLES=${1:-100}
WARM=${2:-10}
rbs_bench_node_setup 11514
core=$RBS_MASTER_PID
node=
trap 'if [ -n "$node" ]; then kill -INT $node; wait $node; fi 2>/dev/null; kill -INT $core; wait $core 2>/dev/null || true' EXIT
lib=$RBS_WS/devel/lib/rigid_body_sim
rss() { awk '/VmRSS/ {printf "%.1f", $2 / 1024}' "/proc/$node/status"; }
rosparam delete /sim_node >/dev/null 2>&1 || true
rosparam set /sim_node/bodies "[]"
rosparam set /r "{joint_state_controller: {type: joint_state_controller/JointStateController, publish_rate: 50},
  arm_controller: {type: effort_controllers/JointGroupPositionController, joints: [shoulder, elbow],
                   gains: {shoulder: {p: 100, d: 5}, elbow: {p: 50, d: 2}}}}"
"$lib/sim_node" >"$ROS_HOME/robot_cycles.log" 2>&1 &
node=$!
until rosservice list 2>/dev/null | grep -q /sim_node/spawn_body; do sleep 0.2; done
echo "date: $(date -u +%F)"
echo "empty world: $(rss) MB"
"$lib/spawn_many" cycle "$WARM" "$RBS_ROOT/urdf/arm2.urdf"
first=$(rss)
echo "after $WARM cycles: $first MB"
"$lib/spawn_many" cycle "$CYCLES" "$RBS_ROOT/urdf/arm2.urdf"
second=$(rss)
echo "after $((WARM + CYCLES)) cycles: $second MB"
"$lib/spawn_many" cycle "$CYCLES" "$RBS_ROOT/urdf/arm2.urdf"
third=$(rss)
echo "after $((WARM + 2 * CYCLES)) cycles: $third MB"
/usr/bin/python3 -c "import sys; a, b, c = map(float, sys.argv[1:4]); print(f'growth over the last {sys.argv[4]} cycles: {100 * (c - b) / a:+.1f} % of the warm {a:.1f} MB')" \
  "$first" "$second" "$third" "$CYCLES"
