// The many-bodies scene of issue 5, shared by world_bench and rest_census:
// N boxes (half extents 0.2 × 0.1 × 0.05 m, 1 kg) on a grid 0.6 m apart,
// dropped from 0.5–1.5 m with random orientations (seed 42) onto the
// ground; default contact and sleep settings.
#pragma once

#include <cmath>
#include <random>
#include <string>

#include "rigid_body_sim/core/step.h"

namespace rigid_body_sim::bench {

struct BoxGrid {
  core::Model model;
  core::State start;
};

inline BoxGrid boxGrid(int n) {
  using namespace core;
  ModelSpec spec;
  BodySpec box;
  box.mass = 1.0;
  box.I_C_L = Vec3(0.0125 / 3.0, 0.0425 / 3.0, 0.05 / 3.0).asDiagonal();
  CollisionShape shape;
  shape.kind = CollisionShape::Kind::kBox;
  shape.size = Vec3(0.4, 0.2, 0.1);
  box.collision = {shape};
  for (int i = 0; i < n; ++i) {
    box.name = "box" + std::to_string(i);
    spec.bodies.push_back(box);
  }
  spec.scene = {Sdf::plane(Vec3::UnitZ())};
  BoxGrid s{Model(spec), {}};
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> height(0.5, 1.5), angle(-M_PI, M_PI);
  for (int i = 0; i < n; ++i) {
    LinkState link;
    link.p_WL = Vec3(0.6 * (i % side), 0.6 * (i / side), height(rng));
    link.q_WL = Quat(Eigen::AngleAxisd(angle(rng), Vec3(angle(rng), angle(rng), angle(rng)).normalized()));
    s.start.bodies.push_back(bodyStateFromLink(s.model.body(i), link));
  }
  return s;
}

}  // namespace rigid_body_sim::bench
