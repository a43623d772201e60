// A range finder from a cone of rays: range_finder.h, docs/physics.md §10.8.
#include "rigid_body_sim/core/devices/range_finder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rigid_body_sim/core/devices/sample_seed.h"

namespace rigid_body_sim::core {

void checkRangeFinder(const RangeFinderSettings& s) {
  if (!(std::isfinite(s.noise) && s.noise >= 0.0)) {
    throw std::invalid_argument("range finder: noise must be finite and >= 0");
  }
}

RangeFinder::RangeFinder(const RangeFinderSettings& settings) : settings_(settings) { checkRangeFinder(settings_); }

double RangeFinder::reading(const std::vector<double>& ranges, double min_range, double max_range) {
  const std::uint64_t k = readings_++;
  const double nearest =
      ranges.empty() ? std::numeric_limits<double>::infinity() : *std::min_element(ranges.begin(), ranges.end());
  if (!std::isfinite(nearest)) return nearest;
  double noisy = nearest;
  if (settings_.noise > 0.0) {  // reading k's own stream, whatever was in sight before
    rng_.seed(sampleSeed(settings_.seed, k));
    normal_.reset();
    noisy += settings_.noise * normal_(rng_);
  }
  return std::clamp(noisy, min_range, max_range);
}

}  // namespace rigid_body_sim::core
