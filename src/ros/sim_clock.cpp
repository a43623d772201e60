#include "rigid_body_sim/ros/sim_clock.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rigid_body_sim::node {

int64_t SimClock::stampAt(long long steps) const {
  return anchor_ns_ + std::llround(static_cast<double>(steps - anchor_steps_) * dt_ * 1e9);
}

int64_t SimClock::anchor(long long steps, int64_t wall_now_ns) {
  if (!wall_anchored_) return 0;
  const int64_t now = std::max(wall_now_ns, stampAt(steps));
  anchor_steps_ = steps;
  anchor_ns_ = now;
  return now - wall_now_ns;
}

double SimClock::simTimeAt(int64_t stamp_ns) const {
  const long long steps = anchor_steps_ + std::llround(static_cast<double>(stamp_ns - anchor_ns_) / (dt_ * 1e9));
  if (std::llabs(stampAt(steps) - stamp_ns) <= 1) return static_cast<double>(steps) * dt_;
  return static_cast<double>(anchor_steps_) * dt_ + static_cast<double>(stamp_ns - anchor_ns_) * 1e-9;
}

std::string formatStamp(int64_t stamp_ns) {
  char buf[48];
  const char* sign = stamp_ns < 0 ? "-" : "";
  const unsigned long long ns = stamp_ns < 0 ? 0ULL - static_cast<unsigned long long>(stamp_ns) : stamp_ns;
  std::snprintf(buf, sizeof buf, "%s%llu.%09llu", sign, ns / 1000000000ULL, ns % 1000000000ULL);
  return buf;
}

}  // namespace rigid_body_sim::node
