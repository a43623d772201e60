#!/usr/bin/env bash
# The main job: sets up everything, builds, launches the simulation headless
# (launch/sim.launch: the box dropped from 1 m onto the ground), and prints
# the body's pose a few times a second until Ctrl-C. Extra arguments go to
# roslaunch, e.g. urdf:=$PWD/urdf/bunny.urdf rviz:=true.
set -euo pipefail
source "$(dirname "$0")/common.sh"
rbs_install_packages
rbs_build >/dev/null
set +u
source "$RBS_WS/devel/setup.bash"
set -u
mkdir -p "$ROS_HOME"
log="$ROS_HOME/demo_launch.log"
roslaunch rigid_body_sim sim.launch "$@" >"$log" 2>&1 &
launch=$!
trap 'kill -INT $launch 2>/dev/null; wait $launch 2>/dev/null || true' EXIT INT TERM
for _ in $(seq 100); do
  if rostopic list 2>/dev/null | grep -qx /odom; then break; fi
  if ! kill -0 $launch 2>/dev/null; then echo "demo: roslaunch stopped; its log:" >&2; cat "$log" >&2; exit 1; fi
  sleep 0.2
done
echo "demo: the box drops from 1 m (log: $log). Push it from another terminal (source .ws/devel/setup.bash):" >&2
echo "  rosservice call /sim_node/apply_impulse \"{frame: world, linear: {x: 0.5, y: 0, z: 4}}\"" >&2
"$RBS_WS/devel/lib/rigid_body_sim/print_pose" _rate:=4 _reset:=true
