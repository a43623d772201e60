// rbsim: runs a simulation without ROS and writes the trajectory.
//
//   rbsim --urdf FILE [--config FILE.yaml] [--set KEY=VALUE ...] --duration S
//         [--dt S] [--csv OUT.csv] [--every N] [--quiet]
//
// stdout: one JSON line with the run's figures. stderr: a short readable
// summary (unless --quiet), a progress bar when stderr is a terminal and the
// run is long, and errors: one line, exit code 2.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rbsim_bodies.h"
#include "rbsim_output.h"
#include "rbsim_report.h"
#include "rbsim_scene.h"
#include "rbsim_sensors.h"
#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/input_bounds.h"
#include "rigid_body_sim/io/scene_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/io/world.h"

namespace {

using rigid_body_sim::core::Quat;
namespace core = rigid_body_sim::core;
namespace io = rigid_body_sim::io;

constexpr const char* kUsage =
    "usage: rbsim --urdf FILE [--config FILE.yaml] [--set KEY=VALUE ...] --duration S\n"
    "             [--dt S] [--csv OUT.csv] [--every N] [--out DIR] [--quiet]\n"
    "       rbsim --config WORLD.yaml [--set KEY=VALUE ...] --duration S [...]\n"
    "\n"
    "Simulates the rigid body of a URDF (its root link and every link fixed to it),\n"
    "a robot (a URDF with revolute, continuous or prismatic joints; a root link\n"
    "`world` fixes it to the world), or the bodies listed under `bodies` in the\n"
    "config, and prints one JSON line of results on stdout.\n"
    "\n"
    "  --urdf FILE        the body or robot (URDF with <inertial> on every link)\n"
    "  --config FILE      YAML settings; keys and defaults in config/default.yaml\n"
    "  --set KEY=VALUE    override one config key with a YAML value, repeatable:\n"
    "                     --set gravity=[0,0,0] --set initial.angular_velocity=[0.01,3,0]\n"
    "  --duration S       simulated time, seconds\n"
    "  --dt S             time step, seconds (overrides the config's dt)\n"
    "  --csv OUT.csv      trajectory: t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz (world frame;\n"
    "                     with several bodies a body column follows t; a robot's base\n"
    "                     link, then JOINT.position,JOINT.velocity per joint)\n"
    "  --every N          one CSV row every N steps (default 1), plus the final state\n"
    "  --out DIR          a robot's controllers' outputs: each wheeled-base controller's\n"
    "                     odometry in DIR/ROBOT.CONTROLLER.odom.csv at its publish_rate\n"
    "                     (t,x,y,heading,linear,lateral,angular); the controllers run\n"
    "                     as sim_node runs them, commanded by the config's timeline;\n"
    "                     each IMU's, odometry's, GPS's and magnetometer's samples in\n"
    "                     DIR/ROBOT.TOPIC.csv, as sim_node publishes them; a body's IMU\n"
    "                     and noisy odometry in DIR/BODY.TOPIC.csv (docs/rbsim.md)\n"
    "  --quiet            no summary on stderr\n";

using rigid_body_sim::tools::BodyDevices;
using rigid_body_sim::tools::Diverged;
using rigid_body_sim::tools::UsageError;

struct Args {
  std::string urdf, config, csv, out;
  std::vector<std::string> sets;
  double duration = -1.0;
  std::string dt;  // kept as text: it becomes a --set dt=... override
  long long every = 1;
  bool quiet = false;
};

double parsePositive(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(x) || !(x > 0.0)) {
    throw UsageError(flag + ": expected a number > 0, got '" + text + "'");
  }
  return x;
}

Args parseArgs(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    if (flag == "--quiet") {
      a.quiet = true;
      continue;
    }
    static const std::set<std::string> kTakesValue = {"--urdf", "--config", "--set",   "--duration",
                                                      "--dt",   "--csv",    "--every", "--out"};
    if (kTakesValue.count(flag) == 0) throw UsageError("unknown argument '" + flag + "' (see rbsim --help)");
    if (i + 1 >= argc) throw UsageError(flag + ": missing value (see rbsim --help)");
    const std::string value = argv[++i];
    if (flag == "--urdf")
      a.urdf = value;
    else if (flag == "--config")
      a.config = value;
    else if (flag == "--set")
      a.sets.push_back(value);
    else if (flag == "--duration")
      a.duration = parsePositive(flag, value);
    else if (flag == "--dt")
      parsePositive(flag, value), a.dt = value;
    else if (flag == "--csv")
      a.csv = value;
    else if (flag == "--out")
      a.out = value;
    else if (flag == "--every") {
      const double n = parsePositive(flag, value);
      if (n != std::floor(n)) throw UsageError("--every: expected a whole number > 0, got '" + value + "'");
      // Any whole number: beyond the run's steps it only writes the final state.
      a.every = n < 1e18 ? static_cast<long long>(n) : 1'000'000'000'000'000'000LL;
    }
  }
  if (a.duration < 0.0) throw UsageError("--duration S is required (see rbsim --help)");
  return a;
}

// ---------------------------------------------------------------- output

// ---------------------------------------------------------------- run

/// A world of bodies alone refuses a config's `controllers` (ConfigError
/// naming the key): there is no robot (a URDF with a moving joint) for
/// them. Its timeline may drive the bodies (Timeline refuses the rest).
void refuseControllers(const io::SimConfig& config) {
  const auto refuse = [](const std::string& key) {
    throw io::ConfigError("config key '" + key + "': no robot to control (a URDF with a moving joint)");
  };
  if (!config.controllers.empty()) refuse("controllers");
  for (std::size_t i = 0; i < config.bodies.size(); ++i) {
    if (!config.bodies[i].controllers.empty()) refuse("bodies[" + std::to_string(i) + "].controllers");
  }
}

/// The config file with the command line's overrides; the node's own keys
/// (sim_node's ~rate, ~publish_rate, ...) set aside and named once, so the
/// node's files run unchanged.
io::SimConfig readConfig(const Args& args) {
  std::vector<std::string> overrides = args.sets;
  if (!args.dt.empty()) overrides.push_back("dt=" + args.dt);
  if (args.config.empty()) {
    YAML::Node tree;
    for (const std::string& s : overrides) io::applyOverride(tree, s);
    return io::parseConfig(tree, ".");
  }
  // Absolute: a body's relative URDF is joined to it once, and a relative
  // folder was joined twice ("worlds/worlds/box.urdf").
  const std::string config_dir = std::filesystem::absolute(args.config).parent_path().string();
  std::vector<std::string> node_keys;
  io::SimConfig config = io::loadConfigFile(args.config, overrides, config_dir, &node_keys);
  std::string names;  // publish_rate is read: the rate of odometry with none of its own
  for (const std::string& k : node_keys) {
    if (k != "publish_rate") names += (names.empty() ? "'" : ", '") + k + "'";
  }
  if (!names.empty()) {
    std::fprintf(stderr, "rbsim: note: config keys %s are sim_node's own (its loop and topics): not used here\n",
                 names.c_str());
  }
  return config;
}

/// The world the command line gives: one body from --urdf, or the config's
/// bodies list.
io::World loadWorld(const Args& args, const io::SimConfig& config, bool* world_config) {
  if (config.bodies_listed && config.bodies.empty()) {
    throw UsageError(
        "the config's bodies list is empty: nothing to simulate (an empty world is for sim_node's "
        "~spawn_body to fill)");
  }
  if (config.bodies.empty() && args.urdf.empty()) {
    throw UsageError("--urdf FILE is required (or a --config with a bodies list; see rbsim --help)");
  }
  if (!config.bodies.empty() && !args.urdf.empty()) {
    throw UsageError("--urdf and a config with a bodies list: give one or the other");
  }
  *world_config = !config.bodies.empty();
  std::vector<std::string> notes;
  io::World world = io::loadWorld(config, [&] {
    return io::loadUrdfFile(args.urdf, io::UrdfOptions{config.urdf_repair, &notes});
  });
  world.notes.insert(world.notes.end(), notes.begin(), notes.end());
  return world;
}

/// A --duration shorter than a step is a usage error before anything is
/// loaded or warned of (a dt out of its range is the model's to refuse).
void checkDuration(const Args& args, const io::SimConfig& config) {
  const double dt = config.model.dt;
  if (dt >= rigid_body_sim::core::ranges::kMinDt && dt <= rigid_body_sim::core::ranges::kMaxDt) {
    rigid_body_sim::tools::stepCount(args.duration, dt);
  }
}

int run(const Args& args) {
  rigid_body_sim::tools::RunOptions options{args.duration, args.csv, args.every, args.quiet, args.out};
  if (!args.urdf.empty()) {  // a URDF with moving joints is a robot: a scene of one (rbsim_scene.cpp)
    const std::string xml = io::readInput<io::UrdfError>(args.urdf, io::InputCaps::kUrdfBytes, "URDF");
    if (io::describesRobot(xml, args.urdf)) {
      const std::string dir = std::filesystem::path(args.urdf).parent_path().string();
      const io::SimConfig config = readConfig(args);
      checkDuration(args, config);
      options.publish_rate = config.publish_rate;
      const auto urdf = [&] { return io::UrdfText{xml, args.urdf, dir}; };
      return rigid_body_sim::tools::runScene(io::loadScene(config, urdf), options, config.timeline);
    }
  }
  bool world_config = false;
  std::optional<io::World> world;
  std::vector<BodyDevices> devices;  // per body
  std::vector<io::TimedCommand> timeline;
  {
    const io::SimConfig config = readConfig(args);
    checkDuration(args, config);
    if (args.urdf.empty() && !config.bodies.empty() && io::listsRobots(config)) {  // rbsim_scene.cpp
      options.publish_rate = config.publish_rate;
      io::SceneSetup setup = io::buildScene(config);
      const std::vector<BodyDevices> bodies = rigid_body_sim::tools::bodyDevices(config, setup.entry);
      return rigid_body_sim::tools::runScene(std::move(setup), options, config.timeline, bodies);
    }
    refuseControllers(config);
    devices = rigid_body_sim::tools::bodyDevices(config);
    timeline = config.timeline;
    const auto has = [](const BodyDevices& d) { return d.imu || d.odom_noise; };
    if (!args.out.empty() && std::none_of(devices.begin(), devices.end(), has)) {
      throw UsageError("--out: no body has a device (imu, odom_noise) whose samples it would write");
    }
    options.publish_rate = config.publish_rate;
    world.emplace(loadWorld(args, config, &world_config));  // its notes are runBodies' to say
  }  // the config goes: its bodies list is a tenth of the memory of a world of 10,000 boxes
  return rigid_body_sim::tools::runBodies(std::move(*world), world_config, options, devices, std::move(timeline));
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parseArgs(argc, argv));
  } catch (const Diverged& e) {
    std::fprintf(stderr, "rbsim: error: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    // UsageError, io::ConfigError, io::UrdfError, and the model's
    // std::invalid_argument: all one line, all exit code 2.
    std::string message = e.what();
    for (char& c : message) {
      if (c == '\n') c = ' ';
    }
    std::fprintf(stderr, "rbsim: error: %s\n", message.c_str());
    return 2;
  }
}
