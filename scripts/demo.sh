#!/usr/bin/env bash
# The main job: sets up everything, builds, launches the simulation headless
# (launch/sim.launch: a body dropped from 1 m, turning, onto the ground), and
# prints the body's pose a few times a second from t = 0 until Ctrl-C. Extra
# arguments go to roslaunch, e.g. urdf:=$PWD/urdf/bunny.urdf rviz:=true.
# robot:=arm2 (the two-link arm under a trajectory controller),
# robot:=diff_drive (the wheeled base under wheel velocity controllers) or
# robot:=rover (the wheeled base with a laser, under a DiffDriveController,
# in a room of boxes) launches that robot instead and drives it
# (scripts/drive_robot), printing its joints, or its base's pose (the
# rover's odometry against the ground truth, and the nearest obstacle its
# scan sees), a few times a second. rviz:=true shows it (and the scan).
set -euo pipefail
source "$(dirname "$0")/common.sh"
rbs_install_packages
rbs_build
set +u
source "$RBS_WS/devel/setup.bash"
set -u
robot="" config_given=""
args=()
for a in "$@"; do
  case "$a" in
    robot:=arm2) robot=arm2 args+=("urdf:=$RBS_ROOT/urdf/arm2.urdf" "config:=$RBS_ROOT/config/arm2_trajectory.yaml") ;;
    robot:=diff_drive) robot=diff_drive args+=("urdf:=$RBS_ROOT/urdf/diff_drive.urdf" "config:=$RBS_ROOT/config/diff_drive.yaml") ;;
    robot:=rover) robot=rover args+=("urdf:=$RBS_ROOT/urdf/diff_drive_lidar.urdf" "config:=$RBS_ROOT/config/rover.yaml") ;;
    robot:=*) echo "demo: ${a}: the shipped robots are robot:=arm2, robot:=diff_drive and robot:=rover" >&2; exit 2 ;;
    config:=*) config_given=1 args+=("$a") ;;
    *) args+=("$a") ;;
  esac
done
# The body demo drops whatever URDF it is given from 1 m (sim.launch gives
# that start to its own box only: any other URDF starts where it says).
[ -n "$robot" ] || [ -n "${config_given:-}" ] || args+=("config:=$RBS_ROOT/config/demo.yaml")
set -- "${args[@]+"${args[@]}"}"
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
if [ -n "$robot" ]; then
  echo "demo: driving $robot through its controllers' topics; Ctrl-C stops" >&2
  "$RBS_WS/devel/lib/rigid_body_sim/drive_robot" _robot:=$robot
  exit
fi
echo "demo: the body drops from 1 m, turning, and comes to rest; Ctrl-C stops. Push it from another terminal:" >&2
echo "  source .ws/devel/setup.bash" >&2
echo "  rosservice call /sim_node/apply_impulse \"{frame: world, linear: {x: 0.5, y: 0, z: 4}}\"" >&2
"$RBS_WS/devel/lib/rigid_body_sim/print_pose" _rate:=4 _reset:=true
