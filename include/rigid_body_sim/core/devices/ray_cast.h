// Rays cast against the world (docs/physics.md §10.5): the scene's shapes
// and every body's solid where its state puts it, for the range sensors
// (lidar.h). A primitive is met exactly (its closed form: plane, sphere,
// box, cylinder, capsule), a union at the nearest of its parts, a mesh's
// distance grid and the other compositions by sphere tracing their
// 1-Lipschitz distance to within 1 µm. ROS-free, read-only over a state.
#pragma once

#include <limits>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/sdf.h"
#include "rigid_body_sim/core/bodies/state.h"

namespace rigid_body_sim::core {

constexpr double kNoHit = std::numeric_limits<double>::infinity();

/// How far (m) along the unit direction `d` from `o` (both in the frame
/// `shape` is posed in) the ray enters `shape`: 0 when `o` is inside it,
/// kNoHit when it does not within `max_range`.
double castRay(const Sdf& shape, const Vec3& o, const Vec3& d, double max_range);

/// What a ray met first.
struct RayHit {
  double range = kNoHit;  ///< m from the ray's origin; kNoHit: nothing within the range
  int body = -1;          ///< the body whose solid it met, −1 for the scene (or nothing)
};

/// The world as rays see it at one state: the scene's shapes and each
/// seen body's solid with its pose and a bounding sphere in W, so that a
/// ray passes a body it misses by a sphere test. Built once per scan.
class RayWorld {
 public:
  /// The bodies `skip` marks (non-zero; it may be shorter than the body
  /// count) are not seen (a sensor's own links); nor is a body without a
  /// solid (a world of one body builds none).
  RayWorld(const Model& model, const State& state, const std::vector<char>& skip = {});
  /// The first thing a ray from `o_W` along the unit `d_W` meets within `max_range`.
  RayHit cast(const Vec3& o_W, const Vec3& d_W, double max_range) const;

 private:
  struct Seen {
    int index;              // the body's
    const BodyModel* body;  //
    Mat3 R_BW;              // W's axes in B
    Vec3 p_WB;              // m
    Vec3 centre_W;          // of its bounding sphere (m)
    double radius;          // m
  };
  const Model& model_;
  std::vector<Seen> seen_;
};

/// The first of the scene's shapes and the bodies' solids (at `state`) a
/// ray from `o_W` along the unit `d_W` meets within `max_range`: one ray
/// through a RayWorld of (model, state, skip).
RayHit castRay(const Model& model, const State& state, const Vec3& o_W, const Vec3& d_W, double max_range,
               const std::vector<char>& skip = {});

}  // namespace rigid_body_sim::core
