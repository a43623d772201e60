// Shared fixtures for the gtest suites: the bodies the issues name, and
// helpers that check a thrown message.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "rigid_body_sim/core/model.h"
#include "rigid_body_sim/core/state.h"

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

/// The issues' test box: half extents 0.2 × 0.1 × 0.05 m, 1 kg.
inline core::BodySpec issueBox() {
  core::BodySpec b;
  b.name = "box";
  b.mass = 1.0;
  b.I_C_L = boxInertia(1.0, Vec3(0.2, 0.1, 0.05));
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

/// A one-body state from the link's pose and twist.
inline core::State stateOf(const core::Model& model, const core::LinkState& link) {
  core::State s;
  s.bodies = {core::bodyStateFromLink(model.body(0), link)};
  return s;
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
  }
}

}  // namespace rigid_body_sim::test
