// Shared fixtures for the gtest suites: the bodies the issues name, and
// helpers that check a thrown message.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"

namespace rigid_body_sim::test {

using core::Mat3;
using core::Quat;
using core::Vec3;

/// Inertia of a solid box about its centre: I = m/3 (b² + c², a² + c², a² + b²)
/// for half extents (a, b, c).
inline Mat3 boxInertia(double mass, const Vec3& half) {
  const Vec3 h2 = half.cwiseProduct(half);
  return (mass / 3.0 * Vec3(h2.y() + h2.z(), h2.x() + h2.z(), h2.x() + h2.y())).asDiagonal();
}

/// The shipped box (urdf/box.urdf): half extents 0.2 × 0.1 × 0.05 m, 1 kg.
inline core::BodySpec shippedBox() {
  core::BodySpec b;
  b.name = "box";
  b.mass = 1.0;
  b.I_C_L = boxInertia(1.0, Vec3(0.2, 0.1, 0.05));
  return b;
}

/// A solid box body with a box <collision>: half extents `half` (m).
inline core::BodySpec boxBody(const Vec3& half, double mass = 1.0) {
  core::BodySpec b;
  b.name = "box";
  b.mass = mass;
  b.I_C_L = boxInertia(mass, half);
  core::CollisionShape shape;
  shape.kind = core::CollisionShape::Kind::kBox;
  shape.size = 2.0 * half;
  b.collision = {shape};
  return b;
}

/// A solid ball with a sphere <collision>: I = 2/5 m r².
inline core::BodySpec ballBody(double radius, double mass = 1.0) {
  core::BodySpec b;
  b.name = "ball";
  b.mass = mass;
  b.I_C_L = (0.4 * mass * radius * radius) * Mat3::Identity();
  core::CollisionShape shape;
  shape.kind = core::CollisionShape::Kind::kSphere;
  shape.radius = radius;
  b.collision = {shape};
  return b;
}

inline core::ModelSpec spec(const core::BodySpec& body, double dt, const Vec3& gravity, bool gyroscopic = true) {
  core::ModelSpec s;
  s.bodies = {body};
  s.dt = dt;
  s.gravity_W = gravity;
  s.gyroscopic = gyroscopic;
  return s;
}

/// A model on the ground plane z = 0 with the given contact settings.
inline core::ModelSpec onGround(const core::BodySpec& body, const core::ContactSettings& contact, double dt = 1e-3) {
  core::ModelSpec s = spec(body, dt, Vec3(0.0, 0.0, -9.81));
  s.scene = {core::Sdf::plane(Vec3::UnitZ())};
  s.contact = contact;
  return s;
}

/// Impulse-method contact settings with this restitution and friction.
inline core::ContactSettings impulse(double restitution, double friction) {
  core::ContactSettings c;
  c.restitution = restitution;
  c.friction = friction;
  return c;
}

/// A room as one SDF: floor z = 0, walls x = ±1 and y = ±1, open on top.
inline core::Sdf room() {
  return core::Sdf::subtract({core::Sdf::box(Vec3(2.2, 2.2, 1.2)).transformed({Quat::Identity(), Vec3(0, 0, 0.5)}),
                              core::Sdf::box(Vec3(2.0, 2.0, 1.5)).transformed({Quat::Identity(), Vec3(0, 0, 0.75)})});
}

/// A one-body state from the link's pose and twist.
inline core::State stateOf(const core::Model& model, const core::LinkState& link) {
  core::State s;
  s.bodies = {core::bodyStateFromLink(model.body(0), link)};
  return s;
}

/// A one-body state with the link at p, turned by q, moving at v and ω (world axes).
inline core::State stateAt(const core::Model& model, const Vec3& p, const Quat& q = Quat::Identity(),
                           const Vec3& v = Vec3::Zero(), const Vec3& w = Vec3::Zero()) {
  core::LinkState link;
  link.p_WL = p;
  link.q_WL = q;
  link.v_WL = v;
  link.w_W = w;
  return stateOf(model, link);
}

/// Mean and sample standard deviation of `x` (noise statistics).
inline std::pair<double, double> meanAndSigma(const std::vector<double>& x) {
  double mean = 0.0, sq = 0.0;
  for (const double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  for (const double v : x) sq += (v - mean) * (v - mean);
  return {mean, std::sqrt(sq / static_cast<double>(x.size() - 1))};
}

/// Bit-for-bit equality of two states, the warm-start impulses included
/// (== would call −0 equal to +0).
inline bool bitIdentical(const core::State& a, const core::State& b) {
  auto same = [](const double* x, const double* y, int n) { return std::memcmp(x, y, n * sizeof(double)) == 0; };
  if (a.bodies.size() != b.bodies.size() || !same(&a.time, &b.time, 1)) return false;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const core::BodyState &x = a.bodies[i], &y = b.bodies[i];
    if (!same(x.p_WB.data(), y.p_WB.data(), 3) || !same(x.v_WB.data(), y.v_WB.data(), 3) ||
        !same(x.q_WB.coeffs().data(), y.q_WB.coeffs().data(), 4) || !same(x.w_B.data(), y.w_B.data(), 3) ||
        x.asleep != y.asleep || !same(&x.still_time, &y.still_time, 1)) {
      return false;
    }
  }
  if (a.contact_impulses.size() != b.contact_impulses.size()) return false;
  for (std::size_t i = 0; i < a.contact_impulses.size(); ++i) {
    const core::ContactImpulse &x = a.contact_impulses[i], &y = b.contact_impulses[i];
    if (x.body != y.body || x.other != y.other || x.item != y.item || x.point != y.point ||
        !same(&x.normal, &y.normal, 1) || !same(x.tangent_W.data(), y.tangent_W.data(), 3)) {
      return false;
    }
  }
  return true;
}

/// Expects `fn` to throw E with a message containing every one of `parts`.
template <class E = std::exception>
void expectThrowsWith(const std::function<void()>& fn, std::initializer_list<std::string> parts) {
  try {
    fn();
    ADD_FAILURE() << "expected an exception";
  } catch (const E& e) {
    const std::string what = e.what();
    for (const std::string& p : parts) EXPECT_NE(what.find(p), std::string::npos) << "'" << p << "' not in: " << what;
    // Read in plain terminals and rosconsole, which show other bytes as '?'.
    for (const unsigned char c : what) ASSERT_TRUE(c >= 0x20 && c < 0x7f) << "not plain ASCII: " << what;
  }
}

/// Expects `text` (a message for users: a warning, a note) to contain every
/// one of `parts`, in plain ASCII.
inline void expectContains(const std::string& text, std::initializer_list<std::string> parts) {
  for (const std::string& p : parts) EXPECT_NE(text.find(p), std::string::npos) << "'" << p << "' not in: " << text;
  for (const unsigned char c : text) ASSERT_TRUE(c >= 0x20 && c < 0x7f) << "not plain ASCII: " << text;
}

}  // namespace rigid_body_sim::test
