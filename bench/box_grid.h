// The many-bodies scene of issue 5, shared by world_bench, rest_census and
// the pile bench (pile_bench, bullet_pile): N boxes (half extents
// 0.2 × 0.1 × 0.05 m, 1 kg) on a grid 0.6 m apart, dropped from 0.5–1.5 m
// with random orientations (seed 42 unless given) onto the ground; default
// sleep settings, and default contact settings unless given (the pile of
// issue 16 has restitution 0.5 and friction 0.5). pileSeed() reads the seed
// of the pile benches from RBS_PILE_SEED.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::bench {

struct BoxGrid {
  core::Model model;
  core::State start;
};

inline BoxGrid boxGrid(int n, const core::ContactSettings& contact = {}, unsigned seed = 42) {
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
  spec.contact = contact;
  BoxGrid s{Model(spec), {}};
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> height(0.5, 1.5), angle(-M_PI, M_PI);
  for (int i = 0; i < n; ++i) {
    LinkState link;
    link.p_WL = Vec3(0.6 * (i % side), 0.6 * (i / side), height(rng));
    link.q_WL = Quat(Eigen::AngleAxisd(angle(rng), Vec3(angle(rng), angle(rng), angle(rng)).normalized()));
    s.start.bodies.push_back(bodyStateFromLink(s.model.body(i), link));
  }
  return s;
}

/// The pile benches' seed (pile_bench, bullet_pile): RBS_PILE_SEED, or 42.
/// One seed's census is 1000 draws of a share near 95 %, whose standard
/// error is about 0.7 %: shares compared within that need several seeds.
inline unsigned pileSeed() {
  const char* seed = std::getenv("RBS_PILE_SEED");
  return seed ? static_cast<unsigned>(std::strtoul(seed, nullptr, 10)) : 42u;
}

/// FNV-1a over the bits of every body's motion, sleep flag and still time and
/// of the warm-start impulses: equal hashes mean bit-identical states (for
/// checking that a refactoring changed nothing).
inline std::uint64_t stateHash(const core::State& s) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 1099511628211ull;
  };
  const auto mixDoubles = [&mix](const double* d, int n) { mix(d, sizeof(double) * n); };
  for (const core::BodyState& b : s.bodies) {
    mixDoubles(b.p_WB.data(), 3);
    mixDoubles(b.v_WB.data(), 3);
    mixDoubles(b.q_WB.coeffs().data(), 4);
    mixDoubles(b.w_B.data(), 3);
    mixDoubles(&b.still_time, 1);
    const char asleep = b.asleep;
    mix(&asleep, 1);
  }
  for (const core::ContactImpulse& c : s.contact_impulses) {
    const int key[4] = {c.body, c.other, c.item, c.point};
    mix(key, sizeof key);
    mixDoubles(&c.normal, 1);
    mixDoubles(c.tangent_W.data(), 3);
  }
  return h;
}

}  // namespace rigid_body_sim::bench
