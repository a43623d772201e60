#!/usr/bin/env bash
# Do service calls fail under load, and is it sim_node? (issue 13: 3 of
# 61,226 concurrent calls failed with a transport error.) Calls
# /sim_node/get_state on world.launch and a trivial roscpp server's Trigger,
# from rospy and from roscpp, with one TCP connection per call and with a
# persistent one: CALLS per thread (default 4000) on 8 threads, ROUNDS times
# (default 2). Prints one line per run: calls that succeeded and failed.
# Usage: bench/service_churn.sh [CALLS] [ROUNDS]
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
CALLS=${1:-4000} ROUNDS=${2:-2}
rbs_bench_node_setup 11499
core=$RBS_MASTER_PID
lib=$RBS_WS/devel/lib/rigid_body_sim
roslaunch rigid_body_sim world.launch >"$ROS_HOME/service_churn_world.log" 2>&1 &
world=$!
"$lib/trivial_server" >"$ROS_HOME/service_churn_trivial.log" 2>&1 &
trivial=$!
trap 'kill -INT $world $trivial 2>/dev/null; wait $world $trivial 2>/dev/null; kill -INT $core; wait $core 2>/dev/null || true' EXIT
until rosservice list 2>/dev/null | grep -q /sim_node/get_state; do sleep 0.5; done
until rosservice list 2>/dev/null | grep -q /trivial_server/trigger; do sleep 0.5; done
for round in $(seq "$ROUNDS"); do
  for service in /sim_node/get_state /trivial_server/trigger; do
    for persistent in 0 1; do
      "$lib/service_hammer" "$service" "$CALLS" 8 "$persistent"
      /usr/bin/python3 "$RBS_ROOT/bench/service_hammer.py" "$service" "$CALLS" 8 "$persistent"
    done
  done
done
