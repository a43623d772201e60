# Sourced by the scripts: environment and the workspace layout.
# A pyenv python3 shadows /usr/bin/python3 on these machines and has no ROS
# modules: put /usr/bin first and tell catkin which python to use
# (PYTHON_EXECUTABLE is the one catkin reads; Python3_EXECUTABLE is read by
# nothing this package finds, and CMake warned that it went unused).
export PATH=/usr/bin:/bin:$PATH
RBS_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
RBS_WS=${RBS_WS:-$RBS_ROOT/.ws}
RBS_BUILD_TYPE=${RBS_BUILD_TYPE:-Release}
# Warnings are errors in every build of a workspace (demo, tests, benches):
# a flag that differed between demo.sh and test.sh made the second rebuild
# everything (600 s) in the same workspace. sanitize.sh's own workspaces set OFF.
RBS_WERROR=${RBS_WERROR:-ON}
RBS_PYFLAGS="-DPYTHON_EXECUTABLE=/usr/bin/python3"
export ROS_HOME=${ROS_HOME:-$RBS_WS/ros_home}
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}

# Debian 12 packages the project needs (ROS 1 from Debian, under /usr).
RBS_APT_PACKAGES=(
  build-essential cmake catkin
  libeigen3-dev liburdfdom-dev libtinyxml-dev libyaml-cpp-dev libassimp-dev
  # libassimp-dev's CMake config links libz.so but the package does not depend on zlib1g-dev
  zlib1g-dev
  nlohmann-json3-dev  # rbsim writes its JSON line through it
  libgtest-dev libbenchmark-dev
  liborocos-kdl-dev  # the articulation tests' oracle (KDL), tests only
  # ROS 1 (Debian's packages): build and test
  libroscpp-dev ros-message-generation ros-message-runtime
  libgeometry-msgs-dev ros-geometry-msgs libnav-msgs-dev ros-nav-msgs libstd-srvs-dev ros-std-srvs
  libsensor-msgs-dev ros-sensor-msgs
  libtrajectory-msgs-dev ros-trajectory-msgs  # the trajectory controllers' command
  libvisualization-msgs-dev ros-visualization-msgs libros-rosgraph-msgs-dev ros-std-msgs libstd-msgs-dev
  libtf2-ros-dev libtf2-dev librostest-dev python3-rostest python3-roslaunch
  # the node's live tuning (~physics): the cfg generator and the C++ server
  python3-dynamic-reconfigure libdynamic-reconfigure-config-init-mutex-dev
  # running and poking at the node (rosrun, roslaunch, rostopic, rosservice, the demo's printer)
  rosbash python3-rospy python3-rostopic python3-rosservice python3-rosnode
  python3-nav-msgs python3-geometry-msgs python3-std-srvs python3-tf2-msgs python3-rosgraph-msgs python3-sensor-msgs
  python3-trajectory-msgs  # rostopic pub of a trajectory
  python3-visualization-msgs  # rostopic echo of the marker topics
  ros-robot-state-publisher  # a robot's links on tf, from the node's joint_states (the launch files start it)
)

# What scripts/fuzz.sh and scripts/sanitize.sh add: clang 14 and its
# libFuzzer (the sanitizer runtimes of GCC come with build-essential).
RBS_FUZZ_PACKAGES=(clang-14 libclang-rt-14-dev libfuzzer-14-dev)

# Runs a phase: says what it does, keeps its output in .ws/LOG, says how
# long it took, or shows the end of the log when it fails.
rbs_phase() {
  local what=$1 log=$RBS_WS/$2 start=$SECONDS status=0
  shift 2
  mkdir -p "$RBS_WS"
  echo "setup: $what (log: ${log#"$PWD"/})" >&2
  "$@" >"$log" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    echo "setup: failed ($status) after $((SECONDS - start)) s; the errors and the end of $log:" >&2
    grep -E "error|Error|E: " "$log" | head -n 40 >&2 || true
    echo "..." >&2
    tail -n 40 "$log" >&2
    return "$status"
  fi
  echo "setup: done in $((SECONDS - start)) s" >&2
}

# Installs the packages given.
rbs_apt() {
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get update -q &&
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "$@"
}

# Installs the packages given (default: RBS_APT_PACKAGES) that are missing.
rbs_install_packages() {
  local missing=() wanted=("$@")
  [ ${#wanted[@]} -gt 0 ] || wanted=("${RBS_APT_PACKAGES[@]}")
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -gt 0 ] || return 0
  # The phase's output goes to a log: ask for sudo's password here, where it shows.
  [ "$(id -u)" -eq 0 ] || sudo -v
  rbs_phase "installing the Debian packages it needs (${#missing[@]} missing; apt-get, a few minutes on a fresh machine)" apt.log rbs_apt "${missing[@]}"
}

# The workspace's source space: .ws/src/rigid_body_sim holds a link to every
# top-level entry of the checkout but .ws and .git. (A link to the checkout
# itself would loop, .ws/src/rigid_body_sim/.ws/src/..., and rosrun's
# `find -L` would warn "File system loop detected" at every call.)
rbs_link_sources() {
  local dir="$RBS_WS/src/rigid_body_sim" entry name
  [ ! -L "$dir" ] || rm "$dir"
  mkdir -p "$dir"
  find "$dir" -mindepth 1 -maxdepth 1 -type l -delete
  for entry in "$RBS_ROOT"/* "$RBS_ROOT"/.[!.]*; do
    name=${entry##*/}
    case "$name" in .ws | .git | ".[!.]*") continue ;; esac
    [ -e "$entry" ] && ln -s "$entry" "$dir/$name"
  done
}

# Builds into .ws/ (catkin_make, $RBS_BUILD_TYPE); extra arguments are
# catkin_make targets, e.g. `tests`. The array RBS_CMAKE_ARGS: more CMake
# arguments (scripts/sanitize.sh passes its flags through it). RBS_WERROR (ON
# unless set, see above) makes the project's warnings errors; compile_commands.json
# is kept for clang-tidy.
rbs_build() {
  rbs_link_sources
  # catkin writes the devel space's Python folder into the environment
  # (PYTHONPATH) only if it exists when CMake first runs; without it a tests-only
  # build (sanitize.sh) ran the spawn_body script unable to import its messages.
  mkdir -p "$RBS_WS/devel/lib/python3/dist-packages"
  # First-time figures of CI's fresh root at 5eae2fe: the package 312 s, its
  # tests 215 s more; under ASan (clang) the package and tests 427 s, under
  # TSan the core's threaded suites 77 s.
  local minutes
  case "$RBS_BUILD_TYPE:${1:-}" in
    Sanitize:tests) minutes=8 ;;
    Sanitize:*) minutes=2 ;;
    *:tests) minutes=4 ;;
    *) minutes=6 ;;
  esac
  local what="building ${*:-the package} into ${RBS_WS#"$PWD"/} ($RBS_BUILD_TYPE; about $minutes minutes the first time on 2 cores)"
  local probe=sim_node  # built already: only what changed is built again
  [ "${1:-}" != tests ] || probe=node_test
  [ ! -f "$RBS_WS/devel/lib/rigid_body_sim/$probe" ] || what="building ${*:-the package} (only what changed)"
  rbs_phase "$what" "build${1:+_$1}.log" \
    catkin_make -C "$RBS_WS" -j2 $RBS_PYFLAGS -DCMAKE_BUILD_TYPE="$RBS_BUILD_TYPE" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
    ${RBS_WERROR:+-DRBS_WERROR="$RBS_WERROR"} ${RBS_CMAKE_ARGS[@]+"${RBS_CMAKE_ARGS[@]}"} "$@"
}

# For the benches that run the node: a ROS master of their own on port $1
# (ROS_MASTER_URI set), waited for; RBS_MASTER_PID is its process, for the
# caller's trap to stop.
rbs_start_master() {
  export ROS_MASTER_URI=http://localhost:$1
  roscore -p "$1" >/dev/null 2>&1 &
  RBS_MASTER_PID=$!
  until rosparam list >/dev/null 2>&1; do sleep 0.2; done
}

# The start of every bench that runs the node: packages, a Release build,
# its environment, and a master of its own on port $1 (each bench has its
# own port, so two can run at once).
rbs_bench_node_setup() {
  rbs_install_packages
  RBS_BUILD_TYPE=Release rbs_build >/dev/null
  set +u
  source "$RBS_WS/devel/setup.bash"
  set -u
  rbs_start_master "$1"
}
