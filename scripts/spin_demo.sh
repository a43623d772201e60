#!/usr/bin/env bash
# Sets up everything and runs rbsim (no ROS) on the shipped box, spinning
# about its intermediate axis (the Dzhanibekov flip), headless, then prints
# when it flipped beside the closed form. Extra arguments go to rbsim, e.g.
# --set gyroscopic=false (no flip) or --set initial.angular_velocity=[0.3,2,0].
set -euo pipefail
source "$(dirname "$0")/common.sh"
rbs_install_packages
rbs_build
csv="$RBS_WS/spin_demo.csv"
echo "rbsim: the 0.4 x 0.2 x 0.1 m box spinning at 3 rad/s about its middle axis, 20 s (trajectory: ${csv#"$PWD"/}, figures: .ws/spin_demo.json)" >&2
"$RBS_WS/devel/lib/rigid_body_sim/rbsim" --urdf "$RBS_ROOT/urdf/box.urdf" \
  --config "$RBS_ROOT/config/spin.yaml" --duration 20 --csv "$csv" "$@" >"$RBS_WS/spin_demo.json"
python3 "$RBS_ROOT/scripts/flip_times.py" "$csv" "$RBS_ROOT/urdf/box.urdf"
