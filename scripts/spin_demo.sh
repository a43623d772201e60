#!/usr/bin/env bash
# Sets up everything and runs rbsim (no ROS) on the shipped box, spinning
# about its intermediate axis (the Dzhanibekov flip), headless. Extra
# arguments go to rbsim, e.g. --set gyroscopic=false or --csv spin.csv.
set -euo pipefail
source "$(dirname "$0")/common.sh"
rbs_install_packages
rbs_build
echo "rbsim: the 0.4 x 0.2 x 0.1 m box spinning at 3 rad/s about its middle axis, 20 s" >&2
"$RBS_WS/devel/lib/rigid_body_sim/rbsim" --urdf "$RBS_ROOT/urdf/box.urdf" \
  --config "$RBS_ROOT/config/spin.yaml" --duration 20 "$@"
