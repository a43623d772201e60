// How high a box bounces, in this project and in Bullet at its defaults
// (bullet_world.h), against the closed form: one pile box (box_grid.h) held
// flat, broad face down, dropped from rest from a spread of heights onto the
// ground with the pile's settings (restitution 0.5, friction 0.5, Δt = 1 ms).
// A flat landing is one impact of the whole face, so Newton's law gives the
// rebound apex e² × the fall; each drop reports the effective restitution
// sqrt(rebound / fall). Prints, per engine, the median and the spread over
// the drops; with --each, one line per drop.
// Usage: bullet_bounce [drops] [--each]   (default 101 drops, centre
//        heights 0.5–1.5 m as in the pile)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "box_grid.h"
#include "bullet_world.h"

using namespace rigid_body_sim::core;

namespace {

constexpr double kHalfHeight = 0.05;  // m, the pile box lying flat
constexpr double kDt = 1e-3;          // s
constexpr double kRestitution = 0.5, kFriction = 0.5;

/// The highest the centre rises after the first bounce (0 if it never
/// rises), given a function that steps once and returns the centre's
/// (height, vertical velocity).
template <typename Step>
double reboundApex(Step step) {
  bool bounced = false;
  double apex = 0.0;
  for (int k = 0; k < 5000; ++k) {
    const auto [z, vz] = step();
    if (vz > 0.0) {
      bounced = true;
      apex = std::max(apex, z);
    } else if (bounced) {
      break;
    }
  }
  return apex;
}

double ourApex(const rigid_body_sim::bench::BoxGrid& one, const LinkState& drop) {
  State s;
  s.bodies.push_back(bodyStateFromLink(one.model.body(0), drop));
  Workspace ws;
  return reboundApex([&] {
    step(one.model, s, {}, &ws);
    return std::pair{s.bodies[0].p_WB.z(), s.bodies[0].v_WB.z()};
  });
}

double bulletApex(const LinkState& drop) {
  rigid_body_sim::bench::BulletWorld w({drop}, kFriction, kRestitution);
  const btRigidBody& box = *w.bodies[1];
  return reboundApex([&] {
    w.step(kDt);
    return std::pair{box.getWorldTransform().getOrigin().z(), box.getLinearVelocity().z()};
  });
}

void summary(const char* engine, std::vector<double> e) {
  std::sort(e.begin(), e.end());
  const auto at = [&e](double q) {
    return e[static_cast<std::size_t>(std::lround(q * static_cast<double>(e.size() - 1)))];
  };
  std::printf("engine %s drops %zu e_median %.3f e_p10 %.3f e_p90 %.3f e_min %.3f e_max %.3f (closed form %.3f)\n",
              engine, e.size(), at(0.5), at(0.1), at(0.9), e.front(), e.back(), kRestitution);
}

}  // namespace

int main(int argc, char** argv) {
  const int drops = argc > 1 && std::strcmp(argv[1], "--each") != 0 ? std::atoi(argv[1]) : 101;
  const bool each = std::strcmp(argv[argc - 1], "--each") == 0;
  if (drops < 1) {
    std::fprintf(stderr, "usage: bullet_bounce [drops >= 1] [--each]\n");
    return 2;
  }
  ContactSettings contact;
  contact.restitution = kRestitution;
  contact.friction = kFriction;
  const auto one = rigid_body_sim::bench::boxGrid(1, contact);
  std::vector<double> ours, bullet;
  for (int i = 0; i < drops; ++i) {
    LinkState drop;
    drop.p_WL = Vec3(0.0, 0.0, 0.5 + (drops > 1 ? static_cast<double>(i) / (drops - 1) : 0.0));
    const double fall = drop.p_WL.z() - kHalfHeight;
    const auto restitution = [fall](double apex) { return std::sqrt(std::max(apex - kHalfHeight, 0.0) / fall); };
    ours.push_back(restitution(ourApex(one, drop)));
    bullet.push_back(restitution(bulletApex(drop)));
    if (each) std::printf("centre %.4f m: e rbs %.3f bullet %.3f\n", drop.p_WL.z(), ours.back(), bullet.back());
  }
  summary("rbs", ours);
  summary("bullet", bullet);
}
