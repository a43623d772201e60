#!/usr/bin/env bash
# The node with a robot (issue 34): sim_node stepping bench/arm7.urdf, a
# 7-joint arm held bent against gravity by seven JointPositionControllers
# (bench/arm7.yaml), at 1 kHz with joint_states at 100 Hz, against the
# one-box node (urdf/box.urdf dropped onto the ground, tf and odometry at
# 100 Hz), in interleaved rounds of SECONDS each on one master, a listener
# subscribed to /odom, /tf and /joint_states. Prints each run's CPU share of
# one core and tick jitter, then the medians and their ratio (target ≤ 1.5).
# Usage: bench/robot_bench.sh [SECONDS] [ROUNDS]   (default 10 s, 3 rounds)
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
SECONDS_PER_RUN=${1:-10}
ROUNDS=${2:-3}
rbs_bench_node_setup 11520
core=$RBS_MASTER_PID
"$RBS_WS/devel/lib/rigid_body_sim/bench_listener" >/dev/null 2>&1 &
listener=$!
trap 'kill $listener 2>/dev/null; kill -INT $core 2>/dev/null; wait $core 2>/dev/null || true' EXIT
ticks=$(getconf CLK_TCK)

run() {  # name, URDF, then sim_node private parameters; prints the CPU %
  local name=$1 urdf=$2; shift 2
  local log=$ROS_HOME/robot_bench_$name.log
  rosparam set --textfile "$urdf" /robot_description
  "$RBS_WS/devel/lib/rigid_body_sim/sim_node" __name:=bench_$name _report_timing:=true "$@" >"$log" 2>&1 &
  local pid=$!
  sleep 2  # start-up (and the box's drop)
  if ! kill -0 $pid 2>/dev/null; then echo "robot_bench: sim_node ($name) stopped; its log:" >&2; tail -5 "$log" >&2; exit 1; fi
  local t0 c0 t1 c1
  t0=$(date +%s.%N); c0=$(awk '{print $14 + $15}' /proc/$pid/stat)
  sleep "$SECONDS_PER_RUN"
  t1=$(date +%s.%N); c1=$(awk '{print $14 + $15}' /proc/$pid/stat)
  if [ "$name" = arm7 ]; then  # where the controllers hold it (the start: 0.3 0.6 -0.4 -1.0 0.5 0.8 0.2)
    echo "arm7 joint_states position: $(timeout 10 rostopic echo -n1 /joint_states/position 2>/dev/null | head -1)" >&2
  fi
  kill -INT $pid; wait $pid || true
  local cpu
  cpu=$(awk -v c0="$c0" -v c1="$c1" -v t0="$t0" -v t1="$t1" -v k="$ticks" 'BEGIN { print 100 * (c1 - c0) / k / (t1 - t0) }')
  printf "%-8s CPU %6.2f %% of one core   %s\n" "$name" "$cpu" "$(grep -o 'timing: .*' "$log" | tail -1 | sed 's/timing: //')" >&2
  echo "$cpu"
}

rosparam set /bench_box/initial "{position: [0, 0, 1]}"
rosparam load "$RBS_ROOT/bench/arm7.yaml" /bench_arm7
box=() arm=()
for round in $(seq "$ROUNDS"); do
  echo "round $round of $ROUNDS" >&2
  box+=("$(run box "$RBS_ROOT/urdf/box.urdf" _rate:=1000.0 _dt:=0.001 _publish_rate:=100.0)")
  arm+=("$(run arm7 "$RBS_ROOT/bench/arm7.urdf")")
done
median() { printf "%s\n" "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
mb=$(median "${box[@]}") ma=$(median "${arm[@]}")
printf "medians of %s rounds: one-box node %.2f %%, 7-joint arm node %.2f %%, ratio %.2f (target <= 1.5)\n" \
  "$ROUNDS" "$mb" "$ma" "$(awk -v a="$ma" -v b="$mb" 'BEGIN { print a / b }')"
