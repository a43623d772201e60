// The loop's pacing and timing (pacer.h).
#include "rigid_body_sim/ros/pacer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rigid_body_sim::node {
namespace {

/// "N what on the loop, p50 … ms, p90 … ms, max … ms", or "" for none.
std::string editLine(const char* what, std::vector<double> d) {
  if (d.empty()) return "";
  std::sort(d.begin(), d.end());
  char line[200];
  std::snprintf(line, sizeof line, "%zu %s on the loop, p50 %.3f ms, p90 %.3f ms, max %.3f ms", d.size(), what,
                1e3 * d[d.size() / 2], 1e3 * d[d.size() * 9 / 10], 1e3 * d.back());
  return line;
}

}  // namespace

void Pacer::rebase(Clock::time_point wall, double sim_time) {
  ref_wall_ = wall;
  ref_sim_ = sim_time;
}

int Pacer::stepsDue(Clock::time_point now, long long steps, double dt, double realtime_factor) {
  const double target = ref_sim_ + std::chrono::duration<double>(now - ref_wall_).count() * realtime_factor;
  // A step is due while sim time is at least half a step short of the target
  // (sim time as the node reads it: the step count × dt).
  int due = 0;
  while (static_cast<double>(steps + due) * dt + 0.5 * dt <= target && due < kMaxStepsBehind) ++due;
  behind_ = due == kMaxStepsBehind;
  const int slice = std::max(1, static_cast<int>(std::floor(kCallbackPeriod / dt + 1e-9)));
  more_ = due > slice && !behind_;
  return std::min(due, slice);
}

void Pacer::recordTick(Clock::time_point now) {
  if (ticked_) periods_.push_back(std::chrono::duration<double>(now - last_tick_).count());
  if (periods_.capacity() == 0) periods_.reserve(1 << 20);
  ticked_ = true;
  last_tick_ = now;
}

std::vector<std::string> Pacer::report(double period, double sim_time) const {
  std::vector<std::string> lines;
  if (periods_.size() >= 10) {
    std::vector<double> d = periods_;
    for (double& x : d) x = std::abs(x - period);
    std::sort(d.begin(), d.end());
    char line[200];
    std::snprintf(line, sizeof line,
                  "%zu ticks, |period - %.6g s| p50 %.1f us, p99 %.1f us, max %.1f us; sim time %.3f s", d.size(),
                  period, 1e6 * d[d.size() / 2], 1e6 * d[d.size() * 99 / 100], 1e6 * d.back(), sim_time);
    lines.emplace_back(line);
  }
  for (const std::string& l : {editLine("spawns", spawns_), editLine("deletes", deletes_)}) {
    if (!l.empty()) lines.push_back(l);
  }
  return lines;
}

}  // namespace rigid_body_sim::node
