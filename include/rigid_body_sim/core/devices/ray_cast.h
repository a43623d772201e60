// Rays cast against the world (docs/physics.md §10.5): the scene's shapes
// and every body's solid where its state puts it, for the range sensors
// (lidar.h). A primitive is met exactly (its closed form: plane, sphere,
// box, cylinder, capsule), a union at the nearest of its parts, a mesh's
// distance grid and the other compositions by sphere tracing their
// 1-Lipschitz distance to within 1 µm. ROS-free, read-only over a state.
#pragma once

#include <algorithm>
#include <cmath>
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

/// A cone from a sensor's origin holding a group of its rays: RayWorld::cull's.
struct RayCone {
  Vec3 axis = Vec3::UnitX();  ///< unit, in the sensor's frame
  double half_angle = M_PI;   ///< rad: the widest ray off the axis
};

/// The cone about the mean of the unit directions dirs[k] for each k that
/// `each(visit)` visits (it calls visit(k) once per ray), holding them all;
/// half-angle π (every direction) when they spread too wide for a mean.
template <class Each>
RayCone coneOf(const std::vector<Vec3>& dirs, const Each& each) {
  Vec3 sum = Vec3::Zero();
  each([&](std::size_t k) { sum += dirs[k]; });
  RayCone cone;
  if (sum.norm() < 1e-6) return cone;
  cone.axis = sum.normalized();
  cone.half_angle = 0.0;
  each([&](std::size_t k) {
    cone.half_angle = std::max(cone.half_angle, std::acos(std::clamp(cone.axis.dot(dirs[k]), -1.0, 1.0)));
  });
  return cone;
}

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

  /// Into `among`: the seen bodies (indices into them) whose bounding
  /// sphere meets the cone from `o_W` about the unit `axis_W`, of half-angle
  /// `half_angle` (rad), within `max_range`: every body a ray from `o_W`
  /// inside that cone can meet (a sensor's tile of rays culls once for all
  /// of them, docs/physics.md §10.5).
  void cull(const Vec3& o_W, const Vec3& axis_W, double half_angle, double max_range, std::vector<int>& among) const;
  /// cast() of a ray inside such a cone, against the scene and `among`'s bodies: the same hit.
  RayHit cast(const Vec3& o_W, const Vec3& d_W, double max_range, const std::vector<int>& among) const;

 private:
  struct Seen {
    int index;              // the body's
    const BodyModel* body;  //
    Mat3 R_BW;              // W's axes in B
    Vec3 p_WB;              // m
    Vec3 centre_W;          // of its bounding sphere (m)
    double radius;          // m
  };
  /// The scene's shapes into `hit` where one is met within `reach` (m),
  /// which then shrinks to it.
  void castScene(const Vec3& o_W, const Vec3& d_W, double& reach, RayHit& hit) const;
  /// Body `b` likewise.
  static void castBody(const Seen& b, const Vec3& o_W, const Vec3& d_W, double& reach, RayHit& hit);

  const Model& model_;
  std::vector<Seen> seen_;
};

/// The first of the scene's shapes and the bodies' solids (at `state`) a
/// ray from `o_W` along the unit `d_W` meets within `max_range`: one ray
/// through a RayWorld of (model, state, skip).
RayHit castRay(const Model& model, const State& state, const Vec3& o_W, const Vec3& d_W, double max_range,
               const std::vector<char>& skip = {});

}  // namespace rigid_body_sim::core
