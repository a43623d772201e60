#!/usr/bin/env bash
# What the bodies' devices cost (issue 15): sim_node's CPU at 1 kHz for N
# boxes resting on the ground (N = 1 and 100 by default) bare, with an IMU
# at 1 kHz on every box (all subscribed), and with those plus ~contacts
# subscribed and a planar cmd_vel driving every box (10 Hz commands, 0.2 m/s
# and 0.5 rad/s). ROUNDS rounds, interleaved; each run SECONDS_PER_RUN s.
# Usage: bench/devices.sh [SECONDS_PER_RUN] [ROUNDS] [N...]
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
SECONDS_PER_RUN=${1:-10} ROUNDS=${2:-3}
shift 2 || true
COUNTS=("$@")
[[ ${#COUNTS[@]} -gt 0 ]] || COUNTS=(1 100)
rbs_bench_node_setup 11495
core=$RBS_MASTER_PID
trap 'kill -INT $core 2>/dev/null; wait $core 2>/dev/null || true' EXIT
lib=$RBS_WS/devel/lib/rigid_body_sim
ticks=$(getconf CLK_TCK)
bodies() {  # N DEVICES: boxes 1 m apart on the ground, each with DEVICES
  /usr/bin/python3 -c "
import math, sys
n, devices = int(sys.argv[1]), sys.argv[2]
side = math.ceil(math.sqrt(n))
print('[' + ', '.join('{name: b%d, urdf: package://rigid_body_sim/urdf/box.urdf, initial: {position: [%g, %g, 0.05]}%s}'
                      % (i, 1.0 * (i % side), 1.0 * (i // side), devices) for i in range(n)) + ']')" "$1" "$2"
}
run() {  # N NAME DEVICES LOAD...
  local n=$1 name=$2 devices=$3; shift 3
  rosparam delete /sim_node >/dev/null 2>&1 || true
  rosparam set /sim_node/bodies "$(bodies "$n" "$devices")"
  "$lib/sim_node" >"$ROS_HOME/devices_$name.log" 2>&1 &
  local pid=$!
  until rosservice list 2>/dev/null | grep -q /sim_node/step; do sleep 0.2; done
  "$lib/device_load" "$n" "$@" >/dev/null 2>&1 &
  local load=$!
  sleep 2
  local t0 c0 t1 c1
  t0=$(date +%s.%N); c0=$(awk '{print $14 + $15}' /proc/$pid/stat)
  sleep "$SECONDS_PER_RUN"
  t1=$(date +%s.%N); c1=$(awk '{print $14 + $15}' /proc/$pid/stat)
  kill -INT $load $pid; wait $load $pid || true
  awk -v c0="$c0" -v c1="$c1" -v t0="$t0" -v t1="$t1" -v k="$ticks" -v name="$name" \
    'BEGIN { printf "%-24s CPU %6.1f %% of one core\n", name, 100 * (c1 - c0) / k / (t1 - t0) }'
}
echo "date: $(date -u +%F), $SECONDS_PER_RUN s a run, $ROUNDS rounds"
imu=", imu: {rate: 1000}"
drive=", cmd_vel: {planar: true}"
for round in $(seq "$ROUNDS"); do
  for n in "${COUNTS[@]}"; do
    run "$n" "N=$n bare" ""
    run "$n" "N=$n imu" "$imu" imu
    run "$n" "N=$n imu+contacts+drive" "$imu$drive" imu contacts drive
  done
done
