#include "rigid_body_sim/core/bodies/sdf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rigid_body_sim/core/bodies/sdf_grid.h"

namespace rigid_body_sim::core {
namespace {

double signOf(double x) { return x < 0.0 ? -1.0 : 1.0; }

}  // namespace

Sdf Sdf::plane(const Vec3& normal, const Vec3& point) {
  if (!(normal.norm() > 0.0) || !normal.allFinite()) throw std::invalid_argument("plane: normal must be non-zero");
  Sdf s(Kind::kPlane, normal.normalized());
  return s.transformed({Quat::Identity(), point});
}

Sdf Sdf::sphere(double radius) { return Sdf(Kind::kSphere, Vec3(radius, 0.0, 0.0)); }
Sdf Sdf::box(const Vec3& size) { return Sdf(Kind::kBox, size); }
Sdf Sdf::capsule(double radius, double length) { return Sdf(Kind::kCapsule, Vec3(radius, length, 0.0)); }
Sdf Sdf::cylinder(double radius, double length) { return Sdf(Kind::kCylinder, Vec3(radius, length, 0.0)); }

Sdf Sdf::grid(std::shared_ptr<const SdfGrid> grid) {
  Sdf s(Kind::kGrid, Vec3::Zero());
  s.grid_ = std::move(grid);
  return s;
}

Sdf Sdf::unite(std::vector<Sdf> shapes) {
  if (shapes.empty()) throw std::invalid_argument("unite: needs at least one shape");
  Sdf s(Kind::kUnion, Vec3::Zero());
  s.children_ = std::move(shapes);
  return s;
}

Sdf Sdf::intersect(std::vector<Sdf> shapes) {
  if (shapes.empty()) throw std::invalid_argument("intersect: needs at least one shape");
  Sdf s(Kind::kIntersection, Vec3::Zero());
  s.children_ = std::move(shapes);
  return s;
}

Sdf Sdf::subtract(std::vector<Sdf> shapes) {
  if (shapes.empty()) throw std::invalid_argument("subtract: needs at least one shape");
  Sdf s(Kind::kDifference, Vec3::Zero());
  s.children_ = std::move(shapes);
  return s;
}

Sdf Sdf::transformed(const Pose& X) const {
  Sdf s = *this;
  s.X_WS_ = X * X_WS_;
  s.X_WS_.rotation.normalize();
  s.X_SW_ = s.X_WS_.inverse();
  return s;
}

double Sdf::eval(const Vec3& p_W, Vec3* gradient) const {
  const Vec3 p_S = X_SW_ * p_W;
  if (gradient == nullptr) return evalLocal(p_S, nullptr);
  Vec3 g_S;
  const double phi = evalLocal(p_S, &g_S);
  *gradient = X_WS_.rotation * g_S;
  return phi;
}

double Sdf::evalLocal(const Vec3& p, Vec3* g) const {
  switch (kind_) {
    case Kind::kPlane:
      if (g) *g = params_;
      return params_.dot(p);

    case Kind::kSphere: {
      const double n = p.norm();
      if (g) *g = n > 0.0 ? Vec3(p / n) : Vec3::UnitZ();
      return n - params_.x();
    }

    case Kind::kBox: {  // q = |p| − h: outside, the distance to the box; inside, the nearest face
      const Vec3 q = p.cwiseAbs() - 0.5 * params_;
      const Vec3 outside = q.cwiseMax(0.0);
      const double out = outside.norm();
      if (out > 0.0) {
        if (g) *g = Vec3(signOf(p.x()), signOf(p.y()), signOf(p.z())).cwiseProduct(outside) / out;
        return out;
      }
      const double in = q.maxCoeff();
      if (g) {
        // The nearest face's normal; on an edge or a corner (faces equally
        // near, as where two equal boxes stand aligned), their mean, so no
        // face is preferred by the order of the axes.
        const double tie = 1e-9 * params_.maxCoeff();
        *g = Vec3::Zero();
        for (int a = 0; a < 3; ++a) {
          if (q(a) >= in - tie) (*g)(a) = signOf(p(a));
        }
        g->normalize();
      }
      return in;
    }

    case Kind::kCapsule: {  // distance to the segment z ∈ [−L/2, L/2], minus the radius
      const double half = 0.5 * params_.y();
      const Vec3 v(p.x(), p.y(), p.z() - std::clamp(p.z(), -half, half));
      const double n = v.norm();
      if (g) *g = n > 0.0 ? Vec3(v / n) : Vec3::UnitX();
      return n - params_.x();
    }

    case Kind::kCylinder: {
      const double rho = std::hypot(p.x(), p.y());
      const Vec3 radial = rho > 0.0 ? Vec3(p.x() / rho, p.y() / rho, 0.0) : Vec3::UnitX();
      const Vec3 axial(0.0, 0.0, signOf(p.z()));
      const double dr = rho - params_.x();
      const double dz = std::abs(p.z()) - 0.5 * params_.y();
      if (dr > 0.0 && dz > 0.0) {  // beyond the rim: distance to the edge circle
        const double d = std::hypot(dr, dz);
        if (g) *g = (dr * radial + dz * axial) / d;
        return d;
      }
      if (dr > dz) {
        if (g) *g = radial;
        return dr;
      }
      if (g) *g = axial;
      return dz;
    }

    case Kind::kGrid:
      return grid_->eval(p, g);

    case Kind::kUnion:
    case Kind::kIntersection:
    case Kind::kDifference: {
      double best = 0.0;
      Vec3 best_g = Vec3::UnitZ();
      for (std::size_t i = 0; i < children_.size(); ++i) {
        Vec3 gi;
        double phi = children_[i].eval(p, g ? &gi : nullptr);
        if (kind_ == Kind::kDifference && i > 0) {
          phi = -phi;
          gi = -gi;
        }
        const bool take = i == 0 || (kind_ == Kind::kUnion ? phi < best : phi > best);
        if (take) {
          best = phi;
          best_g = gi;
        }
      }
      if (g) *g = best_g;
      return best;
    }
  }
  return 0.0;
}

}  // namespace rigid_body_sim::core
