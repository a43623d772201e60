// Bullet 3.24 (double precision, Debian's libbullet-dev) set up as a user
// gets it, for the benches that measure this project against Bullet in the
// same run (bullet_pile, bullet_bounce): btDiscreteDynamicsWorld, sequential
// impulse, 10 iterations, split impulse, restitution threshold 0.2 m/s, the
// pair's coefficients multiplied (so each body and the ground get the square
// root of the pair's), deactivation off; the ground is the plane z = 0 and
// every body is the pile's box (half extents 0.2 × 0.1 × 0.05 m, 1 kg).
#pragma once

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <vector>

#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::bench {

struct BulletWorld {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  btStaticPlaneShape ground_shape{btVector3(0, 0, 1), 0};
  btBoxShape box_shape{btVector3(0.2, 0.1, 0.05)};
  std::vector<std::unique_ptr<btDefaultMotionState>> motion;
  std::vector<std::unique_ptr<btRigidBody>> bodies;  // [0] is the ground

  /// Boxes at the given poses; friction and restitution are the pair's.
  BulletWorld(const std::vector<core::LinkState>& start, double friction, double restitution) {
    world.setGravity(btVector3(0, 0, -9.81));
    const auto add = [&](btCollisionShape* shape, double mass, const btTransform& pose) {
      btVector3 inertia(0, 0, 0);
      if (mass > 0) shape->calculateLocalInertia(mass, inertia);
      motion.push_back(std::make_unique<btDefaultMotionState>(pose));
      bodies.push_back(std::make_unique<btRigidBody>(
          btRigidBody::btRigidBodyConstructionInfo(mass, motion.back().get(), shape, inertia)));
      btRigidBody* b = bodies.back().get();
      b->setFriction(std::sqrt(friction));  // Bullet multiplies the two bodies' values
      b->setRestitution(std::sqrt(restitution));
      b->setActivationState(DISABLE_DEACTIVATION);
      world.addRigidBody(b);
    };
    add(&ground_shape, 0.0, btTransform::getIdentity());
    for (const core::LinkState& l : start) {
      add(&box_shape, 1.0,
          btTransform(btQuaternion(l.q_WL.x(), l.q_WL.y(), l.q_WL.z(), l.q_WL.w()),
                      btVector3(l.p_WL.x(), l.p_WL.y(), l.p_WL.z())));
    }
  }

  void step(double dt) { world.stepSimulation(dt, 1, dt); }
};

}  // namespace rigid_body_sim::bench
