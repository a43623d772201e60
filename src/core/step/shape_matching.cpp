#include "rigid_body_sim/core/step/shape_matching.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

#include "guard.h"
#include "integration.h"
#include "scratch.h"
#include "sleep.h"

namespace rigid_body_sim::core {

Mat3 polarRotation(const Mat3& A) {
  const Eigen::JacobiSVD<Mat3> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 U = svd.matrixU();
  const Mat3& V = svd.matrixV();
  // Singular values come sorted, largest first: flipping the last column
  // changes the fit least when A holds a reflection.
  if ((U * V.transpose()).determinant() < 0.0) U.col(2) = -U.col(2);
  return U * V.transpose();
}

namespace {

/// The particle response at a vertex inside the scene (docs/physics.md §7.3): reflect the
/// normal velocity (restitution above the threshold) and scale the
/// tangential one by a = max(1 − μ_T(1+μ_N)|v_N|/|v_T|, 0).
Vec3 respond(const Vec3& v, const Vec3& n, double restitution, double friction, double threshold) {
  const double vn = v.dot(n);
  if (vn >= 0.0) return v;
  const Vec3 v_n = vn * n;
  const Vec3 v_t = v - v_n;
  const double e = -vn > threshold ? restitution : 0.0;
  const double speed_t = v_t.norm();
  const double a = speed_t > 0.0 ? std::max(1.0 - friction * (1.0 + e) * (-vn) / speed_t, 0.0) : 0.0;
  return -e * v_n + a * v_t;
}

/// φ of the scene at p (the smallest over the items) and its gradient.
double scenePhi(const std::vector<Sdf>& scene, const Vec3& p, Vec3& n) {
  double best = std::numeric_limits<double>::infinity();
  for (const Sdf& sdf : scene) {
    Vec3 g;
    const double phi = sdf.eval(p, &g);
    if (phi < best) {
      best = phi;
      n = g;
    }
  }
  return best;
}

}  // namespace

void stepShapeMatching(const Model& model, State& state, const Loads& loads, double h, Workspace& ws) {
  ws.contacts.clear();
  ws.deepest_penetration = 0.0;
  detail::StepScratch& sc = *ws.scratch;
  sc.in_contact.assign(model.bodyCount(), 0);
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    BodyState& s = state.bodies[i];
    if (s.asleep) continue;
    const BodyModel& b = model.body(i);
    const double friction = model.friction(static_cast<int>(i), -1),
                 restitution = model.restitution(static_cast<int>(i), -1);
    const double deepest = minSeparation(model, s, static_cast<int>(i), 0.0);
    if (deepest < 0.0) ws.deepest_penetration = std::max(ws.deepest_penetration, -deepest);

    // The rigid step first, with the integration stage's own functions:
    // forces (external, drag), velocities, damping, then the rotation with
    // the gyroscopic term (§5.2–5.4, §5.6). Without contact every vertex
    // moves rigidly, so that rigid step is the answer.
    const BodyLoad* load = loads.empty() ? nullptr : &loads[i];
    integrateVelocity(model, b, accumulateForces(model, state, load, ws, static_cast<int>(i)), h, s);
    applyDamping(model, h, s);
    limitSpeeds(model, static_cast<int>(i), s, ws);
    if (!finiteState(s)) {  // the guard (§5.9): the pose is still the last finite one
      putBack(static_cast<int>(i), s, ws);
      continue;
    }
    const bool near = !model.scene().empty() && minSeparation(model, s, static_cast<int>(i),
                                                              (s.v_WB.norm() + s.w_B.norm() * b.bound_radius) * h) <
                                                    std::numeric_limits<double>::infinity();
    if (!near) {
      integrateBody(model, b, h, s);
      updateSleep(model, false, h, s);
      continue;
    }
    // Near the scene: each vertex moves with the step's rigid velocity, the
    // rotation being the one the gyroscopic stage found (its angle over h),
    // and collides on its own.
    const Mat3 R = s.q_WB.toRotationMatrix();
    const Vec3 v = s.v_WB;
    BodyState turned = s;
    const Eigen::AngleAxisd turn_B(gyroscopicRotation(model, b, h, turned).normalized());
    const Vec3 w = R * ((turn_B.angle() / h) * turn_B.axis());

    Vec3 centroid;
    std::vector<Vec3>& y = sc.positions;
    y.clear();
    y.reserve(b.contact_points.size());
    for (const ContactPoint& p : b.contact_points) {
      const Vec3 r_W = R * p.r_B;
      const Vec3 x_i = s.p_WB + r_W;
      Vec3 v_i = v + w.cross(r_W);
      Vec3 y_i = x_i + h * v_i;
      Vec3 n;
      if (near && scenePhi(model.scene(), y_i, n) < 0.0) {
        sc.in_contact[i] = 1;
        v_i = respond(v_i, n, restitution, friction, model.restitutionThreshold());
        y_i = x_i + h * v_i;
        const double phi = scenePhi(model.scene(), y_i, n);
        if (phi < 0.0) y_i -= phi * n;  // onto the surface
      }
      y.push_back(y_i);
    }

    // Rigidify: c = mean yᵢ, A = (Σ (yᵢ − c) r̄ᵢᵀ)(Σ r̄ᵢ r̄ᵢᵀ)⁻¹, R = Polar(A).
    // The fit is a compromise: a vertex pushed out alone can end up inside
    // again, so the penetrating vertices of the fitted pose are projected
    // out and the fit repeated, a few times (as position-based dynamics
    // iterates its constraint projection).
    Mat3 R_new;
    const auto fit = [&] {
      centroid = Vec3::Zero();
      for (const Vec3& yk : y) centroid += yk;
      centroid /= static_cast<double>(y.size());
      Mat3 A = Mat3::Zero();
      for (std::size_t k = 0; k < y.size(); ++k) {
        A += (y[k] - centroid) * (b.contact_points[k].r_B - b.points_centroid_B).transpose();
      }
      R_new = polarRotation(A * b.points_inv_spread);
    };
    fit();
    for (int pass = 0; near && pass < model.solver().shape_matching_passes; ++pass) {
      bool projected = false;
      for (std::size_t k = 0; k < y.size(); ++k) {
        y[k] = centroid + R_new * (b.contact_points[k].r_B - b.points_centroid_B);
        Vec3 n;
        const double phi = scenePhi(model.scene(), y[k], n);
        if (phi < 0.0) {
          y[k] -= phi * n;
          projected = true;
        }
      }
      if (!projected) break;
      fit();
    }
    const Vec3 p_new = centroid - R_new * b.points_centroid_B;  // the centre of mass
    s.v_WB = (p_new - s.p_WB) / h;
    const Eigen::AngleAxisd turn(R_new * R.transpose());
    const Vec3 w_new = (turn.angle() / h) * turn.axis();
    s.p_WB = p_new;
    s.q_WB = Quat(R_new).normalized();
    s.w_B = s.q_WB.conjugate() * w_new;
    limitSpeeds(model, static_cast<int>(i), s, ws);  // a contact's push, as the impulse method's
    updateSleep(model, sc.in_contact[i] != 0, h, s);
  }
}

}  // namespace rigid_body_sim::core
