// A legged robot with mesh feet dropped on the ground (issue 47), against
// MuJoCo 2.2.2 on the same URDF in the same run: ns per step over the drop
// (falling, landing, then standing on its collapsed legs), medians of
// interleaved rounds, and where each base ends on how many contacts.
// This project runs the URDF as rbsim does (the default config: ground
// plane, Δt = 1 ms, its meshes through ROS_PACKAGE_PATH), and again with
// sleep off (MuJoCo has none: a robot at rest still costs its solve). MuJoCo reads the
// same URDF through its own URDF import (its meshes as convex hulls, the
// visuals dropped, links on fixed joints merged), given a free joint, a
// ground plane, Δt = 1 ms and its Euler integrator; package:// paths are
// taken under PACKAGE_DIR.
// Usage: legged_bench URDF PACKAGE_DIR [rounds] [seconds] [height]
//        (default 5 rounds of 3 s from 0.5 m)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "median.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/scene_loader.h"

#ifdef RBS_WITH_MUJOCO
#include <mujoco/mujoco.h>
#endif

namespace {

using rigid_body_sim::bench::median;

using namespace rigid_body_sim;

struct Drop {
  std::function<void()> step;
  std::function<double()> base_height;  // m
  std::function<int()> contacts;        // at the last step; -1: asleep (no solve)
  int steps = 0;
};

struct Args {
  std::string urdf, package_dir;
  double seconds = 3.0, height = 0.5;
};

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "legged_bench: cannot read %s\n", path.c_str());
    std::exit(1);
  }
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Drop ours(const Args& a, bool sleep) {
  YAML::Node tree;
  io::applyOverride(tree, "initial.position=[0,0," + std::to_string(a.height) + "]");
  if (!sleep) io::applyOverride(tree, "sleep.enabled=false");
  const io::SimConfig config = io::parseConfig(tree, ".");
  const std::string xml = readFile(a.urdf);
  const std::string dir = std::filesystem::path(a.urdf).parent_path().string();
  auto setup = std::make_shared<io::SceneSetup>(io::loadScene(config, [&] { return io::UrdfText{xml, a.urdf, dir}; }));
  auto ws = std::make_shared<core::SceneWorkspace>();
  const int steps = static_cast<int>(a.seconds / setup->scene.model().dt() + 0.5);
  return {[setup, ws] { core::stepScene(setup->scene, setup->state, {}, *ws); },
          [setup] { return setup->state.robots[0].X_WB.translation.z(); },
          [setup, ws] { return setup->state.robots[0].asleep ? -1 : static_cast<int>(ws->bodies.contacts.size()); },
          steps};
}

#ifdef RBS_WITH_MUJOCO
mjModel* load(const std::string& path) {
  char error[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  if (m == nullptr) {
    std::fprintf(stderr, "MuJoCo: %s: %s\n", path.c_str(), error);
    std::exit(1);
  }
  return m;
}

/// The link of the URDF that is no joint's child.
std::string rootLink(const std::string& urdf) {
  std::vector<std::string> children;
  const std::regex child("<child\\s+link\\s*=\\s*\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(urdf.begin(), urdf.end(), child); it != std::sregex_iterator(); ++it) {
    children.push_back((*it)[1]);
  }
  const std::regex link("<link\\s+name\\s*=\\s*\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(urdf.begin(), urdf.end(), link); it != std::sregex_iterator(); ++it) {
    if (std::find(children.begin(), children.end(), (*it)[1]) == children.end()) return (*it)[1];
  }
  std::fprintf(stderr, "legged_bench: no root link\n");
  std::exit(1);
}

/// The URDF as MuJoCo imports it, its root link on a floating joint (a
/// free joint: MuJoCo makes a URDF's root the world), saved as MJCF, with a
/// ground plane added.
mjModel* mujocoModel(const Args& a) {
  std::string urdf = std::regex_replace(readFile(a.urdf), std::regex("package://[^/]+/"), a.package_dir + "/");
  const std::size_t robot = urdf.find('>', urdf.find("<robot"));
  urdf.insert(robot + 1,
              "<mujoco><compiler strippath='false' discardvisual='true' balanceinertia='true'/></mujoco>"
              "<link name='rbs_world'/><joint name='rbs_free' type='floating'><parent link='rbs_world'/>"
              "<child link='" +
                  rootLink(urdf) + "'/></joint>");
  const std::string urdf_path = "/tmp/rbs_legged_bench.urdf", mjcf_path = "/tmp/rbs_legged_bench.xml";
  std::ofstream(urdf_path) << urdf;
  char error[1000] = "";
  mj_deleteModel(load(urdf_path));
  if (!mj_saveLastXML(mjcf_path.c_str(), nullptr, error, sizeof error)) {
    std::fprintf(stderr, "MuJoCo: saving %s: %s\n", mjcf_path.c_str(), error);
    std::exit(1);
  }
  std::string mjcf = readFile(mjcf_path);
  const std::size_t world = mjcf.find("<worldbody>");
  if (world == std::string::npos) {
    std::fprintf(stderr, "MuJoCo's model of %s has no worldbody\n", a.urdf.c_str());
    std::exit(1);
  }
  mjcf.insert(world + 11, "<geom type='plane' size='0 0 1'/>");
  std::ofstream(mjcf_path) << mjcf;
  mjModel* m = load(mjcf_path);
  m->opt.timestep = 1e-3;
  m->opt.integrator = mjINT_EULER;
  return m;
}

Drop mujoco(const Args& a) {
  mjModel* m = mujocoModel(a);
  std::shared_ptr<mjModel> model(m, mj_deleteModel);
  std::shared_ptr<mjData> data(mj_makeData(m), mj_deleteData);
  data->qpos[0] = data->qpos[1] = 0.0;
  data->qpos[2] = a.height;
  mj_forward(m, data.get());
  return {[model, data] { mj_step(model.get(), data.get()); }, [data] { return data->qpos[2]; },
          [data] { return data->ncon; }, static_cast<int>(a.seconds / 1e-3 + 0.5)};
}
#endif

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: legged_bench URDF PACKAGE_DIR [rounds] [seconds] [height]\n");
    return 2;
  }
  Args a;
  a.urdf = argv[1];
  a.package_dir = argv[2];
  const int rounds = argc > 3 ? std::atoi(argv[3]) : 5;
  if (argc > 4) a.seconds = std::atof(argv[4]);
  if (argc > 5) a.height = std::atof(argv[5]);
  std::vector<std::pair<const char*, std::function<Drop(const Args&)>>> engines = {
      {"rigid_body_sim", [](const Args& b) { return ours(b, true); }},
      {"  without sleep", [](const Args& b) { return ours(b, false); }}};
#ifdef RBS_WITH_MUJOCO
  engines.push_back({"MuJoCo 2.2.2", mujoco});
#endif
  std::vector<std::vector<double>> times(engines.size());
  std::vector<double> end(engines.size());
  std::vector<int> contacts(engines.size());
  for (int r = 0; r < rounds; ++r) {
    for (std::size_t e = 0; e < engines.size(); ++e) {  // interleaved
      Drop drop = engines[e].second(a);
      const auto t0 = std::chrono::steady_clock::now();
      for (int k = 0; k < drop.steps; ++k) drop.step();
      const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
      times[e].push_back(ns / drop.steps);
      end[e] = drop.base_height();
      contacts[e] = drop.contacts();
    }
  }
  std::printf("%-16s %12s %14s %10s\n", "engine", "ns/step", "base z at end", "contacts");
  for (std::size_t e = 0; e < engines.size(); ++e) {
    const std::string count = contacts[e] < 0 ? "asleep" : std::to_string(contacts[e]);
    std::printf("%-16s %12.0f %14.4f %10s\n", engines[e].first, median(times[e]), end[e], count.c_str());
  }
  return 0;
}
