// Articulations the articulation suites share: random trees with skew axes,
// offset centres of mass and full inertia tensors, planar pendulums, and a
// link on one joint to the world.
#pragma once

#include <random>
#include <string>

#include "rigid_body_sim/core/articulations/articulation.h"

namespace rigid_body_sim::test {

using core::ArticulatedLink;
using core::ArticulationModel;
using core::JointType;
using core::Mat3;
using core::Quat;
using core::Vec3;

inline Vec3 randomVec(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

inline Quat randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
}

/// A mass with a full (non-diagonal) inertia tensor about an offset centre.
inline core::MassProperties randomMass(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.2, 2.0);
  core::MassProperties mp;
  mp.mass = u(rng);
  mp.p_FC = randomVec(rng, 0.3);
  const Mat3 R = randomRotation(rng).toRotationMatrix();
  const Vec3 moments(u(rng) * 0.1, u(rng) * 0.1, u(rng) * 0.1);
  // Principal moments that meet the triangle inequality: a box's.
  const Vec3 sides = moments.cwiseSqrt();
  const Vec3 box(sides.y() * sides.y() + sides.z() * sides.z(), sides.x() * sides.x() + sides.z() * sides.z(),
                 sides.x() * sides.x() + sides.y() * sides.y());
  mp.I_C_F = R * (mp.mass / 12.0 * box).asDiagonal() * R.transpose();
  return mp;
}

/// A solid box's shape, `size` its full extents (m), centred at `centre` in its link.
inline core::CollisionShape boxShape(const Vec3& size, const Vec3& centre = Vec3::Zero()) {
  core::CollisionShape s;
  s.kind = core::CollisionShape::Kind::kBox;
  s.size = size;
  s.X_LS.translation = centre;
  return s;
}

/// A solid box's mass properties: mass m (kg), extents `size`, centred at `centre`.
inline core::MassProperties boxMass(double m, const Vec3& size, const Vec3& centre = Vec3::Zero()) {
  core::MassProperties p;
  p.mass = m;
  p.p_FC = centre;
  const Vec3 s2 = size.cwiseProduct(size);
  p.I_C_F = (m / 12.0 * Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y())).asDiagonal();
  return p;
}

/// Two 0.4 × 0.1 × 0.1 m, 1 kg bars joined end to end by a hinge about z
/// (±2 rad), the first the floating base, both solid.
inline ArticulationModel twoBars() {
  ArticulationModel model;
  model.fixed_base = false;
  model.links.resize(2);
  const Vec3 size(0.4, 0.1, 0.1);
  model.links[0].name = "upper";
  model.links[0].mass = boxMass(1.0, size);
  model.links[0].collision = {boxShape(size)};
  ArticulatedLink& fore = model.links[1];
  fore.name = "fore";
  fore.joint = "elbow";
  fore.parent = 0;
  fore.type = JointType::Revolute;
  fore.limits.lower = -2.0;
  fore.limits.upper = 2.0;
  fore.X_PJ.translation = Vec3(0.2, 0.0, 0.0);
  fore.axis_J = Vec3::UnitZ();
  fore.mass = boxMass(1.0, size, Vec3(0.2, 0.0, 0.0));
  fore.collision = {boxShape(size, Vec3(0.2, 0.0, 0.0))};
  core::checkArticulation(model);
  return model;
}

/// A robot fixed to the world with one moving link, `link`, on a joint of
/// `type` named `joint` at `origin` (in the world) about or along `axis`;
/// its mass, limits and shapes are the caller's to set.
inline ArticulationModel oneJoint(JointType type, const std::string& link, const std::string& joint, const Vec3& origin,
                                  const Vec3& axis) {
  ArticulationModel model;
  model.fixed_base = true;
  model.links.resize(2);
  model.links[0].name = "world";
  ArticulatedLink& l = model.links[1];
  l.name = link;
  l.joint = joint;
  l.parent = 0;
  l.type = type;
  l.X_PJ.translation = origin;
  l.axis_J = axis;
  return model;
}

/// n moving links; link i's parent is i − 1 (serial) or any earlier link.
inline ArticulationModel randomTree(std::mt19937& rng, int n, bool fixed_base, bool serial) {
  ArticulationModel model;
  model.fixed_base = fixed_base;
  ArticulatedLink base;
  base.name = "base";
  base.mass = randomMass(rng);
  model.links.push_back(base);
  for (int i = 1; i <= n; ++i) {
    ArticulatedLink link;
    link.name = "link" + std::to_string(i);
    link.joint = "joint" + std::to_string(i);
    link.parent = serial ? i - 1 : std::uniform_int_distribution<int>(0, i - 1)(rng);
    link.type = static_cast<JointType>(std::uniform_int_distribution<int>(0, 2)(rng));
    link.X_PJ = {randomRotation(rng), randomVec(rng, 0.5)};
    link.axis_J = randomVec(rng, 1.0).normalized();
    link.mass = randomMass(rng);
    model.links.push_back(link);
  }
  return model;
}

/// A planar chain hanging along −z, every joint about y: link i a rod of
/// length lengths[i−1] with its centre of mass at centres[i−1] below its
/// joint and inertia inertias[i−1] about it around y.
inline ArticulationModel planarChain(const std::vector<double>& masses, const std::vector<double>& lengths,
                                     const std::vector<double>& centres, const std::vector<double>& inertias) {
  ArticulationModel model;
  model.fixed_base = true;
  ArticulatedLink base;
  base.name = "world";
  model.links.push_back(base);
  for (std::size_t i = 0; i < masses.size(); ++i) {
    ArticulatedLink link;
    link.name = "link" + std::to_string(i + 1);
    link.joint = "joint" + std::to_string(i + 1);
    link.parent = static_cast<int>(i);
    link.type = JointType::Continuous;
    link.axis_J = Vec3::UnitY();
    if (i > 0) link.X_PJ.translation = Vec3(0.0, 0.0, -lengths[i - 1]);
    link.mass.mass = masses[i];
    link.mass.p_FC = Vec3(0.0, 0.0, -centres[i]);
    // About the rod's own axis it is thin; about x and y it has `inertia`.
    link.mass.I_C_F = Vec3(inertias[i], inertias[i], 1e-3 * inertias[i]).asDiagonal();
    model.links.push_back(link);
  }
  return model;
}

}  // namespace rigid_body_sim::test
