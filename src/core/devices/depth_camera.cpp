// A depth camera: depth_camera.h, docs/physics.md §10.7.
#include "rigid_body_sim/core/devices/depth_camera.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::core {

void checkDepthCamera(const DepthCameraSettings& s) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("depth camera: " + what); };
  if (s.width < 1 || s.height < 1) fail("width and height must be >= 1");
  if (static_cast<double>(s.width) * s.height > ranges::kMaxPixels) fail("width x height must be <= 4e6 pixels");
  // Narrower, the focal length overflows: 1e-320 rad gave CameraInfo's K and P as inf.
  if (!(s.hfov >= ranges::kMinFieldOfView && s.hfov < M_PI)) fail("hfov must be within [0.001, pi) rad");
  if (!(std::isfinite(s.max_depth) && s.min_depth >= 0.0 && s.min_depth < s.max_depth)) {
    fail("depths must be 0 <= min_depth < max_depth, finite");
  }
  if (!(s.max_depth <= ranges::kMaxSensorRange)) fail("max_depth must be <= 1e5 m");
  if (!(std::isfinite(s.noise) && s.noise >= 0.0)) fail("noise must be finite and >= 0");
}

std::uintmax_t depthCameraBytes(const DepthCameraSettings& s) {
  // A ray (3 doubles), its range per unit depth and its depth (doubles), and
  // the image (4 bytes) and cloud (16) messages twice (built, then serialized).
  const std::uintmax_t pixels =
      static_cast<std::uintmax_t>(std::max(s.width, 0)) * static_cast<std::uintmax_t>(std::max(s.height, 0));
  return pixels * (sizeof(Vec3) + 2 * sizeof(double) + 2 * (4 + 16));
}

DepthCamera::DepthCamera(const DepthCameraSettings& settings) : settings_(settings) {
  checkDepthCamera(settings_);
  focal_ = 0.5 * settings_.width / std::tan(0.5 * settings_.hfov);
  const std::size_t pixels = static_cast<std::size_t>(settings_.width) * static_cast<std::size_t>(settings_.height);
  rays_.reserve(pixels);
  per_depth_.reserve(pixels);
  for (int v = 0; v < settings_.height; ++v) {
    for (int u = 0; u < settings_.width; ++u) {
      const Vec3 ray(1.0, -(u - cx()) / focal_, -(v - cy()) / focal_);  // x = 1: one unit of depth
      per_depth_.push_back(ray.norm());
      rays_.push_back(ray / per_depth_.back());
    }
  }
  // Tiles of kTile × kTile pixels, each with the cone that holds its rays.
  constexpr int kTile = 16;
  for (int v0 = 0; v0 < settings_.height; v0 += kTile) {
    for (int u0 = 0; u0 < settings_.width; u0 += kTile) {
      Tile t{u0, v0, std::min(u0 + kTile, settings_.width), std::min(v0 + kTile, settings_.height), {}, 0.0};
      const auto each = [&](const auto& visit) {
        for (int v = t.v0; v < t.v1; ++v) {
          for (int u = t.u0; u < t.u1; ++u) {
            visit(static_cast<std::size_t>(v) * static_cast<std::size_t>(settings_.width) +
                  static_cast<std::size_t>(u));
          }
        }
      };
      t.cone = coneOf(rays_, each);
      each([&](std::size_t k) { t.reach = std::max(t.reach, per_depth_[k]); });
      tiles_.push_back(t);
    }
  }
}

void DepthCamera::capture(const Model& model, const State& state, const Pose& X_WS, const std::vector<char>& skip,
                          std::vector<double>& depth) {
  const DepthCameraSettings& s = settings_;
  const Mat3 R_WS = X_WS.rotation.toRotationMatrix();
  const RayWorld world(model, state, skip);
  depth.resize(rays_.size());
  // Each tile's rays against the bodies its cone can meet: the ranges a
  // cast against every body gives, in far fewer sphere tests.
  const Vec3& o_W = X_WS.translation;
  for (const Tile& tile : tiles_) {
    world.cull(o_W, R_WS * tile.cone.axis, tile.cone.half_angle, s.max_depth * tile.reach, among_);
    for (int v = tile.v0; v < tile.v1; ++v) {
      for (int u = tile.u0; u < tile.u1; ++u) {
        const std::size_t k =
            static_cast<std::size_t>(v) * static_cast<std::size_t>(s.width) + static_cast<std::size_t>(u);
        depth[k] = world.cast(o_W, R_WS * rays_[k], s.max_depth * per_depth_[k], among_).range;
      }
    }
  }
  // Then row by row, so that the noise is drawn in the pixels' order.
  rng_.seed(sampleSeed(s.seed, images_++));
  normal_.reset();  // no value of the last stream's held over
  for (std::size_t k = 0; k < rays_.size(); ++k) {
    const double length = per_depth_[k];
    const double t = depth[k];
    const double z = t / length;
    if (t == kNoHit) {
      depth[k] = kNoHit;
    } else if (z < s.min_depth) {
      depth[k] = -kNoHit;
    } else {
      depth[k] = std::clamp(s.noise > 0.0 ? z + s.noise * normal_(rng_) : z, s.min_depth, s.max_depth);
    }
  }
}

}  // namespace rigid_body_sim::core
