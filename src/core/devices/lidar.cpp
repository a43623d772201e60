// A scanning range sensor: lidar.h, docs/physics.md §10.6.
#include "rigid_body_sim/core/devices/lidar.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::core {

void checkLidar(const LidarSettings& s) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("lidar: " + what); };
  if (s.samples < 1) fail("samples must be >= 1");
  if (s.vertical_samples < 1) fail("vertical_samples must be >= 1");
  if (static_cast<double>(s.samples) * s.vertical_samples > ranges::kMaxRays) {
    fail("samples x vertical_samples must be <= 1e6");
  }
  for (const auto& [lo, hi, what] :
       {std::tuple{s.min_angle, s.max_angle, "min_angle and max_angle"},
        std::tuple{s.vertical_min_angle, s.vertical_max_angle, "vertical_min_angle and vertical_max_angle"}}) {
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi)) fail(std::string(what) + " must be finite, min <= max");
  }
  // LaserScan's angles are float32: a finite 1e39 or 1e308 was published as inf.
  if (!(s.min_angle >= -ranges::kMaxScanAngle && s.max_angle <= ranges::kMaxScanAngle)) {
    fail("min_angle and max_angle must be within [-4 pi, 4 pi] rad");
  }
  if (!(s.vertical_min_angle >= -M_PI / 2 && s.vertical_max_angle <= M_PI / 2)) {
    fail("vertical angles must be within [-pi/2, pi/2]");
  }
  if (!(std::isfinite(s.max_range) && s.min_range >= 0.0 && s.min_range < s.max_range)) {
    fail("ranges must be 0 <= min_range < max_range, finite");
  }
  if (!(s.max_range <= ranges::kMaxSensorRange)) fail("max_range must be <= 1e5 m");
  if (!(std::isfinite(s.noise) && s.noise >= 0.0)) fail("noise must be finite and >= 0");
}

std::uintmax_t lidarBytes(const LidarSettings& s) {
  // A direction (3 doubles), a range (a double), a group's cone per 16 rays,
  // and the message twice (built, then serialized by roscpp).
  const std::uintmax_t rays = static_cast<std::uintmax_t>(std::max(s.samples, 0)) *
                              static_cast<std::uintmax_t>(std::max(s.vertical_samples, 0));
  const std::uintmax_t message = s.vertical_samples > 1 ? 22 : 4;  // a Velodyne point, or a float
  return rays * (sizeof(Vec3) + sizeof(double) + sizeof(RayCone) / 16 + 1 + 2 * message);
}

Lidar::Lidar(const LidarSettings& settings) : settings_(settings) {
  checkLidar(settings_);
  const LidarSettings& s = settings_;
  increment_ = s.samples > 1 ? (s.max_angle - s.min_angle) / (s.samples - 1) : 0.0;
  vertical_increment_ =
      s.vertical_samples > 1 ? (s.vertical_max_angle - s.vertical_min_angle) / (s.vertical_samples - 1) : 0.0;
  directions_.reserve(static_cast<std::size_t>(s.samples) * static_cast<std::size_t>(s.vertical_samples));
  for (int f = 0; f < s.vertical_samples; ++f) {
    const double elevation = s.vertical_min_angle + f * vertical_increment_;
    for (int k = 0; k < s.samples; ++k) {
      const double azimuth = s.min_angle + k * increment_;
      directions_.emplace_back(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                               std::sin(elevation));
    }
  }
  for (std::size_t first = 0; first < directions_.size(); first += kGroup) {
    const std::size_t end = std::min(first + kGroup, directions_.size());
    cones_.push_back(coneOf(directions_, [&](const auto& visit) {
      for (std::size_t k = first; k < end; ++k) visit(k);
    }));
  }
}

void Lidar::scan(const Model& model, const State& state, const Pose& X_WS, const std::vector<char>& skip,
                 std::vector<double>& ranges) {
  const LidarSettings& s = settings_;
  const Mat3 R_WS = X_WS.rotation.toRotationMatrix();
  const RayWorld world(model, state, skip);
  rng_.seed(sampleSeed(s.seed, scans_++));
  normal_.reset();  // no value of the last stream's held over
  ranges.resize(directions_.size());
  for (std::size_t k = 0; k < directions_.size(); ++k) {
    if (k % kGroup == 0) {  // the next group's bodies, culled once for its rays
      const RayCone& cone = cones_[k / kGroup];
      world.cull(X_WS.translation, R_WS * cone.axis, cone.half_angle, s.max_range, among_);
    }
    const double t = world.cast(X_WS.translation, R_WS * directions_[k], s.max_range, among_).range;
    if (t == kNoHit) {
      ranges[k] = kNoHit;
    } else if (t < s.min_range) {
      ranges[k] = -kNoHit;
    } else {
      const double noisy = s.noise > 0.0 ? t + s.noise * normal_(rng_) : t;
      ranges[k] = std::clamp(noisy, s.min_range, s.max_range);
    }
  }
}

}  // namespace rigid_body_sim::core
