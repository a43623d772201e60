#!/usr/bin/env bash
# The node's cost (issue 4): sim_node stepping at 1 kHz and publishing tf and
# odometry at 100 Hz and at 1 kHz to a subscriber (CPU share of one core, step-period jitter
# p50/p99 from ~report_timing), and with ~realtime_factor 0 the real-time
# factor reached. Each run lasts SECONDS (default 10) on its own master.
# Two floors, for comparison in the same run: a bare 1 kHz sleep loop
# (jitter) and a roscpp node that only publishes the same two messages at
# 1 kHz (CPU).
# Usage: bench/node_bench.sh [SECONDS]
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
SECONDS_PER_RUN=${1:-10}
rbs_bench_node_setup 11497
core=$RBS_MASTER_PID
trap 'kill -INT $core 2>/dev/null; wait $core 2>/dev/null || true' EXIT
rosparam set --textfile "$RBS_ROOT/urdf/box.urdf" /robot_description
ticks=$(getconf CLK_TCK)
# Someone listening, so the messages are really serialized and sent.
"$RBS_WS/devel/lib/rigid_body_sim/bench_listener" >/dev/null 2>&1 &
listener=$!
trap 'kill $listener 2>/dev/null; kill -INT $core 2>/dev/null; wait $core 2>/dev/null || true' EXIT

run() {  # name, then sim_node private parameters
  local name=$1; shift
  local log=$ROS_HOME/node_bench_$name.log
  rosparam set "/bench_$name/initial" "{position: [0, 0, 1]}"
  "$RBS_WS/devel/lib/rigid_body_sim/sim_node" __name:=bench_$name _report_timing:=true "$@" >"$log" 2>&1 &
  local pid=$!
  sleep 2  # start-up and the drop
  local t0 c0 t1 c1
  t0=$(date +%s.%N); c0=$(awk '{print $14 + $15}' /proc/$pid/stat)
  sleep "$SECONDS_PER_RUN"
  t1=$(date +%s.%N); c1=$(awk '{print $14 + $15}' /proc/$pid/stat)
  kill -INT $pid; wait $pid || true
  local cpu
  cpu=$(awk -v c0="$c0" -v c1="$c1" -v t0="$t0" -v t1="$t1" -v k="$ticks" 'BEGIN { print 100 * (c1 - c0) / k / (t1 - t0) }')
  printf "%-22s CPU %6.2f %% of one core   %s\n" "$name" "$cpu" "$(grep -o 'timing: .*' "$log" | sed 's/timing: //')"
}

printf "%-22s %s\n" "bare 1 kHz sleep loop" "$("$RBS_WS/devel/lib/rigid_body_sim/sleep_baseline" $((SECONDS_PER_RUN * 1000)))"
printf "%-22s %s\n" "roscpp floor, 1 kHz" \
  "$("$RBS_WS/devel/lib/rigid_body_sim/publish_baseline" $((SECONDS_PER_RUN * 1000)) 2>/dev/null | tail -1)"
run rate1k_publish100 _rate:=1000.0 _dt:=0.001 _publish_rate:=100.0
run rate1k_publish1k _rate:=1000.0 _dt:=0.001 _publish_rate:=1000.0
run as_fast_publish100 _rate:=1000.0 _dt:=0.001 _publish_rate:=100.0 _realtime_factor:=0.0
printf "%-22s %s\n" "bare 1 kHz sleep loop" "$("$RBS_WS/devel/lib/rigid_body_sim/sleep_baseline" $((SECONDS_PER_RUN * 1000)))"
echo "(as_fast: real-time factor = sim time / wall time of the whole run, start-up included: $((SECONDS_PER_RUN + 2)) s)"
