// A world for the tests of the node's parts that need no master: boxes of
// 1 kg named as given, root link "base", body i at x = i m turned i quarter
// turns about z, with ports as openPorts names them (no topics).
#pragma once

#include <ros/callback_queue.h>

#include <string>
#include <vector>

#include "../test_util.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/ros/addressing.h"
#include "rigid_body_sim/ros/body_ports.h"

namespace rigid_body_sim::node::test {

using rigid_body_sim::test::Quat;
using rigid_body_sim::test::Vec3;

inline constexpr double kPi = 3.14159265358979323846;

struct PartsWorld {
  explicit PartsWorld(const std::vector<std::string>& names) : sim(model(names), core::State{}), ports(closer) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      core::LinkState link;
      link.p_WL = Vec3(static_cast<double>(i), 0, 0);
      link.q_WL = Quat(Eigen::AngleAxisd(static_cast<double>(i) * kPi / 2, Vec3::UnitZ()));
      sim.state.bodies.push_back(core::bodyStateFromLink(sim.model().body(i), link));
      BodyPorts p;
      p.prefix = names.size() > 1 ? names[i] + "/" : "";
      p.frame = p.prefix + "base";
      ports.add(std::move(p), sim.model().body(i), sim.state.bodies[i], 0.0);
    }
    sim.initial = sim.state;
  }
  static core::Model model(const std::vector<std::string>& names) {
    core::ModelSpec spec =
        rigid_body_sim::test::spec(rigid_body_sim::test::boxBody(Vec3(0.1, 0.1, 0.1)), 1e-3, Vec3(0, 0, -9.81));
    spec.bodies.clear();
    for (const std::string& name : names) {
      core::BodySpec b = rigid_body_sim::test::boxBody(Vec3(0.1, 0.1, 0.1));
      b.name = name;
      b.link = "base";
      spec.bodies.push_back(b);
    }
    return core::Model(spec);
  }

  core::Simulation sim;
  ros::CallbackQueue closer;
  PortRegistry ports;
  std::string world_frame = "map";
  Addressing address{sim, ports, world_frame};
};

}  // namespace rigid_body_sim::node::test
