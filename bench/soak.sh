#!/usr/bin/env bash
# Soak (issue 13): sim_node on a world of two boxes, one resting on the
# ground 70 m from the other, for SIM_SECONDS of sim time (default 3600) at
# Δt = 1 ms (1 kHz), at ~realtime_factor RTF (default 20: three minutes of
# wall time an hour; as fast as possible would leave the requests too few
# per sim second to mean anything), while bench/soak.py
# sends seeded random valid requests to the other box (wrenches, impulses,
# states, the ~wrench topic, clears, reads). Prints the node's RSS over the
# run, the request count, and whether the resting box stayed bit-identical.
# Usage: bench/soak.sh [SIM_SECONDS] [RTF]
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
SIM_SECONDS=${1:-3600}
RTF=${2:-20}
rbs_bench_node_setup 11498
core=$RBS_MASTER_PID
trap 'kill -INT $core 2>/dev/null; wait $core 2>/dev/null || true' EXIT
rosparam set /sim_node/realtime_factor "$RTF"
rosparam set /sim_node/publish_rate 100
rosparam set /sim_node/bodies "[{name: resting, urdf: package://rigid_body_sim/urdf/box.urdf, initial: {position: [50, 50, 0.05]}},
                                {name: pushed, urdf: package://rigid_body_sim/urdf/box.urdf, initial: {position: [0, 0, 0.5]}}]"
"$RBS_WS/devel/lib/rigid_body_sim/sim_node" >"$ROS_HOME/soak_node.log" 2>&1 &
node=$!
trap 'kill -INT $node 2>/dev/null; wait $node 2>/dev/null || true; kill -INT $core 2>/dev/null; wait $core 2>/dev/null || true' EXIT
/usr/bin/python3 "$RBS_ROOT/bench/soak.py" "$node" "$SIM_SECONDS"
