// Rays cast against the world: ray_cast.h, docs/physics.md §10.5.
#include "rigid_body_sim/core/devices/ray_cast.h"

#include <algorithm>
#include <cmath>

namespace rigid_body_sim::core {

namespace {

constexpr double kTraceTolerance = 1e-6;  // m: a sphere trace stops this near the surface
constexpr int kTraceSteps = 1000;

/// The interval [t0, t1] of t where lo ≤ o + t d ≤ hi on one axis (the slab); empty when t0 > t1.
void slab(double o, double d, double lo, double hi, double& t0, double& t1) {
  if (d == 0.0) {  // parallel: inside the slab everywhere or nowhere
    if (o < lo || o > hi) {
      t0 = kNoHit;
      t1 = -kNoHit;
    }
    return;
  }
  double a = (lo - o) / d, b = (hi - o) / d;
  if (a > b) std::swap(a, b);
  t0 = std::max(t0, a);
  t1 = std::min(t1, b);
}

/// The entry of a ray into an interval [t0, t1] of inside: 0 when it starts inside.
double entry(double t0, double t1, double max_range) {
  if (t0 > t1 || t1 < 0.0) return kNoHit;
  const double t = std::max(t0, 0.0);
  return t <= max_range ? t : kNoHit;
}

/// Where |(o + t d)_xy| ≤ r: the interval of t, or false when the ray never is.
bool disk(const Vec3& o, const Vec3& d, double r, double& t0, double& t1) {
  const double a = d.x() * d.x() + d.y() * d.y();
  const double c = o.x() * o.x() + o.y() * o.y() - r * r;
  if (a == 0.0) {  // along the axis
    if (c > 0.0) return false;
    t0 = -kNoHit;
    t1 = kNoHit;
    return true;
  }
  const double b = o.x() * d.x() + o.y() * d.y();  // half of the linear coefficient
  const double disc = b * b - a * c;
  if (disc < 0.0) return false;
  const double s = std::sqrt(disc);
  // The nearer root without cancellation, the other from their product c / a.
  const double q = b > 0.0 ? -(b + s) : -(b - s);
  double r0 = q / a, r1 = q != 0.0 ? c / q : -r0;
  if (r0 > r1) std::swap(r0, r1);
  t0 = r0;
  t1 = r1;
  return true;
}

/// The interval of t where |o + t d − c| ≤ r (a ball), or false.
bool ball(const Vec3& o, const Vec3& d, const Vec3& c, double r, double& t0, double& t1) {
  const Vec3 m = o - c;
  const double b = m.dot(d), cc = m.squaredNorm() - r * r, disc = b * b - cc;
  if (disc < 0.0) return false;
  const double s = std::sqrt(disc);
  const double q = b > 0.0 ? -(b + s) : -(b - s);
  double r0 = q, r1 = q != 0.0 ? cc / q : -q;
  if (r0 > r1) std::swap(r0, r1);
  t0 = r0;
  t1 = r1;
  return true;
}

/// The ray in `shape`'s own frame, from the frame it is posed in.
void toShape(const Sdf& shape, const Vec3& o, const Vec3& d, Vec3& o_S, Vec3& d_S) {
  const Pose& X = shape.pose();
  const Mat3 R_T = X.rotation.toRotationMatrix().transpose();
  o_S = R_T * (o - X.translation);
  d_S = R_T * d;
}

/// Sphere tracing of `shape`'s distance (in its parent frame) from o along d.
double trace(const Sdf& shape, const Vec3& o, const Vec3& d, double max_range) {
  double t = 0.0;
  for (int k = 0; k < kTraceSteps && t <= max_range; ++k) {
    const double phi = shape.eval(o + t * d);
    if (phi < kTraceTolerance) return t;
    t += phi;
  }
  return kNoHit;
}

}  // namespace

double castRay(const Sdf& shape, const Vec3& o, const Vec3& d, double max_range) {
  Vec3 p, v;
  toShape(shape, o, d, p, v);
  double t0 = -kNoHit, t1 = kNoHit;
  switch (shape.kind()) {
    case Sdf::Kind::kPlane: {  // inside where n · x ≤ 0
      const Vec3& n = shape.normal();
      const double h = n.dot(p), s = n.dot(v);
      if (h <= 0.0) return 0.0;
      if (s >= 0.0) return kNoHit;
      return entry(-h / s, kNoHit, max_range);
    }
    case Sdf::Kind::kSphere:
      if (!ball(p, v, Vec3::Zero(), shape.radius(), t0, t1)) return kNoHit;
      return entry(t0, t1, max_range);
    case Sdf::Kind::kBox: {
      const Vec3 h = 0.5 * shape.size();
      for (int a = 0; a < 3; ++a) slab(p(a), v(a), -h(a), h(a), t0, t1);
      return entry(t0, t1, max_range);
    }
    case Sdf::Kind::kCylinder: {
      if (!disk(p, v, shape.radius(), t0, t1)) return kNoHit;
      const double h = 0.5 * shape.length();
      slab(p.z(), v.z(), -h, h, t0, t1);
      return entry(t0, t1, max_range);
    }
    case Sdf::Kind::kCapsule: {  // the union of its side and its two caps
      const double r = shape.radius(), h = 0.5 * shape.length();
      double best = kNoHit;
      if (disk(p, v, r, t0, t1)) {
        slab(p.z(), v.z(), -h, h, t0, t1);
        best = entry(t0, t1, max_range);
      }
      for (const double z : {-h, h}) {
        double a = 0.0, b = 0.0;
        if (ball(p, v, Vec3(0.0, 0.0, z), r, a, b)) best = std::min(best, entry(a, b, max_range));
      }
      return best;
    }
    case Sdf::Kind::kUnion: {  // the nearest part, each in its own pose within the union's frame
      double best = kNoHit;
      for (const Sdf& child : shape.children()) best = std::min(best, castRay(child, p, v, std::min(best, max_range)));
      return best;
    }
    case Sdf::Kind::kGrid:
    case Sdf::Kind::kIntersection:
    case Sdf::Kind::kDifference:
      return trace(shape, o, d, max_range);
  }
  return kNoHit;
}

RayWorld::RayWorld(const Model& model, const State& state, const std::vector<char>& skip) : model_(model) {
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    if (i < skip.size() && skip[i] != 0) continue;
    const BodyModel& body = model.body(i);
    if (body.solid_B.empty()) continue;
    const BodyState& s = state.bodies.at(i);
    const Vec3 centre_B = 0.5 * (body.solid_lo_B + body.solid_hi_B);
    const double radius = 0.5 * (body.solid_hi_B - body.solid_lo_B).norm();
    seen_.push_back({static_cast<int>(i), &body, s.q_WB.toRotationMatrix().transpose(), s.p_WB,
                     s.p_WB + s.q_WB * centre_B, radius});
  }
}

void RayWorld::castScene(const Vec3& o_W, const Vec3& d_W, double& reach, RayHit& hit) const {
  for (const Sdf& shape : model_.scene()) {
    const double t = castRay(shape, o_W, d_W, reach);
    if (t < hit.range) {
      hit.range = reach = t;
      hit.body = -1;
    }
  }
}

void RayWorld::castBody(const Seen& b, const Vec3& o_W, const Vec3& d_W, double& reach, RayHit& hit) {
  // Its bounding sphere first: most rays pass most bodies by.
  const Vec3 m = b.centre_W - o_W;
  const double along = m.dot(d_W);
  if (along + b.radius < 0.0 || along - b.radius > reach) return;
  if ((m - along * d_W).squaredNorm() > b.radius * b.radius) return;
  const Vec3 o_B = b.R_BW * (o_W - b.p_WB), d_B = b.R_BW * d_W;
  double t0 = -kNoHit, t1 = kNoHit;  // then its box
  for (int a = 0; a < 3; ++a) slab(o_B(a), d_B(a), b.body->solid_lo_B(a), b.body->solid_hi_B(a), t0, t1);
  if (entry(t0, t1, reach) == kNoHit) return;
  for (const Sdf& part : b.body->solid_B) {
    const double t = castRay(part, o_B, d_B, reach);
    if (t < hit.range) {
      hit.range = reach = t;
      hit.body = b.index;
    }
  }
}

RayHit RayWorld::cast(const Vec3& o_W, const Vec3& d_W, double max_range) const {
  RayHit hit;
  double reach = max_range;
  castScene(o_W, d_W, reach, hit);
  for (const Seen& b : seen_) castBody(b, o_W, d_W, reach, hit);
  return hit;
}

RayHit RayWorld::cast(const Vec3& o_W, const Vec3& d_W, double max_range, const std::vector<int>& among) const {
  RayHit hit;
  double reach = max_range;
  castScene(o_W, d_W, reach, hit);
  for (const int k : among) castBody(seen_[static_cast<std::size_t>(k)], o_W, d_W, reach, hit);
  return hit;
}

void RayWorld::cull(const Vec3& o_W, const Vec3& axis_W, double half_angle, double max_range,
                    std::vector<int>& among) const {
  among.clear();
  for (std::size_t k = 0; k < seen_.size(); ++k) {
    const Seen& b = seen_[k];
    const Vec3 m = b.centre_W - o_W;
    const double distance = m.norm();
    if (distance <= b.radius) {  // the origin inside its sphere
      among.push_back(static_cast<int>(k));
      continue;
    }
    if (distance - b.radius > max_range) continue;
    // The sphere subtends asin(r / |m|) about m; a ray within half_angle of
    // the axis can meet it when m is within the sum of the axis (1e-9 rad
    // of margin for the rounding of the angles).
    const double off_axis = std::acos(std::clamp(m.dot(axis_W) / distance, -1.0, 1.0));
    if (off_axis <= half_angle + std::asin(b.radius / distance) + 1e-9) among.push_back(static_cast<int>(k));
  }
}

RayHit castRay(const Model& model, const State& state, const Vec3& o_W, const Vec3& d_W, double max_range,
               const std::vector<char>& skip) {
  return RayWorld(model, state, skip).cast(o_W, d_W, max_range);
}

}  // namespace rigid_body_sim::core
