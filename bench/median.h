// The median of a bench's interleaved rounds (the upper one of an even count).
#pragma once

#include <algorithm>
#include <vector>

namespace rigid_body_sim::bench {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace rigid_body_sim::bench
