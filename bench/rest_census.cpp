// Which boxes of the N = 1000 scene (box_grid.h) are not at rest after 2 s,
// and why: for each, what it stands on, its tilt from that face, its
// contacts, speeds and kinetic energy; then the share at rest (core::atRest)
// as the same run carries on to 4 s, and the share slower than a few speed
// thresholds at 2 s. Also reports the most mechanical energy a body
// touching no other body gained in one step: rocking that lasts must be
// physics, not energy put in by the solver (the solve stops at 1e-7 m/s,
// which lets a resting 1 kg box's centre move about 1e-10 m, 1e-9 J, in a
// step). Not a timing benchmark.
// Usage: rest_census [N]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "box_grid.h"
#include "rigid_body_sim/core/step/diagnostics.h"

using namespace rigid_body_sim::core;

namespace {

double mechanicalEnergy(const Model& model, int i, const BodyState& b) {  // J, potential from the origin
  return kineticEnergy(model.body(i), b) + potentialEnergy(model.body(i), b, model.gravity());
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 1000;
  const auto scene = rigid_body_sim::bench::boxGrid(n);
  const Model& model = scene.model;
  State s = scene.start;
  Workspace ws;
  std::vector<double> energy(n);
  for (int i = 0; i < n; ++i) energy[i] = mechanicalEnergy(model, i, s.bodies[i]);
  long rises = 0;
  double worst_rise = 0.0;
  std::vector<char> touches_body(n);
  std::vector<std::pair<double, double>> shares;  // (s, share at rest)
  for (int k = 1; k <= 4000; ++k) {
    step(model, s, {}, &ws);
    if (k <= 2000) {
      std::fill(touches_body.begin(), touches_body.end(), 0);
      for (const Contact& c : ws.contacts) {
        if (c.other >= 0) touches_body[c.body] = touches_body[c.other] = 1;
      }
      for (int i = 0; i < n; ++i) {
        const double e = mechanicalEnergy(model, i, s.bodies[i]);
        if (!touches_body[i]) {
          rises += e > energy[i] + 1e-9;
          worst_rise = std::max(worst_rise, e - energy[i]);
        }
        energy[i] = e;
      }
    }
    if (k % 500 == 0) {
      int resting = 0;
      for (const BodyState& b : s.bodies) resting += atRest(model, b);
      shares.emplace_back(s.time, 100.0 * resting / n);
    }
    if (k != 2000) continue;
    std::printf("at 2 s, share slower than v and ω:");
    for (const auto& [v, w] : {std::pair{0.01, 0.05}, {0.02, 0.1}, {0.05, 0.2}, {0.1, 0.5}}) {
      int slow = 0;
      for (const BodyState& b : s.bodies) slow += b.v_WB.norm() < v && b.w_B.norm() < w;
      std::printf(" %.2f m/s %.2f rad/s %.1f%%;", v, w, 100.0 * slow / n);
    }
    std::printf(
        "\nin 0-2 s, the most energy a body touching no other body gained in a step: %.2g J (%ld steps above 1e-9 J)\n",
        worst_rise, rises);
    std::vector<int> ground(n, 0), bodies(n, 0);
    for (const Contact& c : ws.contacts) {
      if (c.other < 0) {
        ++ground[c.body];
      } else {
        ++bodies[c.body];
        ++bodies[c.other];
      }
    }
    std::printf("boxes not at rest at 2 s:\n%5s  %-22s %9s %7s %7s %9s %9s %9s %8s\n", "box", "stands on", "tilt (°)",
                "ground", "bodies", "v (m/s)", "ω (rad/s)", "KE (mJ)", "still (s)");
    for (int i = 0; i < n; ++i) {
      const BodyState& b = s.bodies[i];
      if (atRest(model, b)) continue;
      const Mat3 R = b.q_WB.toRotationMatrix();
      int up = 0;
      for (int a = 1; a < 3; ++a) {
        if (std::abs(R(2, a)) > std::abs(R(2, up))) up = a;
      }
      const char* face[] = {"an end, 0.2 x 0.1 m", "a long side, 0.4 x 0.1", "its broad face, 0.4 x 0.2"};
      std::printf("%5d  %-22s %9.2f %7d %7d %9.4f %9.4f %9.3f %8.2f\n", i, bodies[i] ? "touches a box" : face[up],
                  std::acos(std::min(1.0, std::abs(R(2, up)))) * 180.0 / M_PI, ground[i], bodies[i], b.v_WB.norm(),
                  b.w_B.norm(), 1e3 * kineticEnergy(model.body(i), b), b.still_time);
    }
  }
  std::printf("share at rest (core::atRest), the run carried on:");
  for (const auto& [t, share] : shares) std::printf(" %.1f s %.1f%%;", t, share);
  std::printf("\n");
}
