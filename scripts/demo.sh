#!/usr/bin/env bash
# The main job: sets up everything, builds, launches the simulation headless
# (launch/sim.launch: a body dropped from 1 m, turning, onto the ground), and
# prints the body's pose a few times a second from t = 0 until Ctrl-C. Extra
# arguments go to roslaunch, e.g. urdf:=$PWD/urdf/bunny.urdf rviz:=true.
set -euo pipefail
source "$(dirname "$0")/common.sh"
rbs_install_packages
rbs_build
set +u
source "$RBS_WS/devel/setup.bash"
set -u
mkdir -p "$ROS_HOME"
log="$ROS_HOME/demo_launch.log"
echo "demo: launching sim.launch${*:+ $*} (log: ${log#"$PWD"/})" >&2
roslaunch rigid_body_sim sim.launch "$@" >"$log" 2>&1 &
launch=$!
trap 'kill -INT $launch 2>/dev/null; wait $launch 2>/dev/null || true' EXIT INT TERM
for _ in $(seq 150); do
  if rosservice list 2>/dev/null | grep -qx /sim_node/get_state; then break; fi
  if ! kill -0 $launch 2>/dev/null; then echo "demo: roslaunch stopped; its log:" >&2; cat "$log" >&2; exit 1; fi
  sleep 0.2
done
echo "demo: the body drops from 1 m, turning, and comes to rest; Ctrl-C stops. Push it from another terminal:" >&2
echo "  source .ws/devel/setup.bash" >&2
echo "  rosservice call /sim_node/apply_impulse \"{frame: world, linear: {x: 0.5, y: 0, z: 4}}\"" >&2
"$RBS_WS/devel/lib/rigid_body_sim/print_pose" _rate:=4 _reset:=true
