# Sourced by the scripts: environment and the workspace layout.
# A pyenv python3 shadows /usr/bin/python3 on these machines and has no ROS
# modules: put /usr/bin first and pass the python flags to catkin.
export PATH=/usr/bin:/bin:$PATH
RBS_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
RBS_WS=${RBS_WS:-$RBS_ROOT/.ws}
RBS_BUILD_TYPE=${RBS_BUILD_TYPE:-Release}
RBS_PYFLAGS="-DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3"
export ROS_HOME=${ROS_HOME:-$RBS_WS/ros_home}
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}

# Debian 12 packages the project needs (ROS 1 from Debian, under /usr).
RBS_APT_PACKAGES=(
  build-essential cmake catkin
  libeigen3-dev liburdfdom-dev libyaml-cpp-dev libassimp-dev
  # libassimp-dev's CMake config links libz.so but the package does not depend on zlib1g-dev
  zlib1g-dev
  libgtest-dev libbenchmark-dev
  # ROS 1 (Debian's packages): build and test
  libroscpp-dev ros-message-generation ros-message-runtime
  libgeometry-msgs-dev ros-geometry-msgs libnav-msgs-dev ros-nav-msgs libstd-srvs-dev ros-std-srvs
  libvisualization-msgs-dev ros-visualization-msgs libros-rosgraph-msgs-dev ros-std-msgs libstd-msgs-dev
  libtf2-ros-dev libtf2-dev librostest-dev python3-rostest python3-roslaunch
  # running and poking at the node (rosrun, roslaunch, rostopic, rosservice, the demo's printer)
  ros-robot-state-publisher rosbash python3-rospy python3-rostopic python3-rosservice python3-rosnode
  python3-nav-msgs python3-geometry-msgs python3-std-srvs python3-tf2-msgs python3-rosgraph-msgs
  python3-visualization-msgs  # rostopic echo of the marker topics
)

rbs_install_packages() {
  local missing=()
  for p in "${RBS_APT_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ] && [ "${RBS_FORCE_APT:-0}" != 1 ]; then return 0; fi
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]:-all packages}" >&2
  DEBIAN_FRONTEND=noninteractive $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${RBS_APT_PACKAGES[@]}"
}

rbs_build() {
  mkdir -p "$RBS_WS/src"
  ln -sfn "$RBS_ROOT" "$RBS_WS/src/rigid_body_sim"
  catkin_make -C "$RBS_WS" -j2 $RBS_PYFLAGS -DCMAKE_BUILD_TYPE="$RBS_BUILD_TYPE" "$@"
}
