// External loads: wrenches held over a step, and instantaneous impulses.
#pragma once

#include <vector>

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core {

/// The frame a load is expressed in.
enum class Frame {
  kWorld,  ///< world axes; a point is an offset from the centre of mass along world axes
  kBody,   ///< the URDF root link's axes, turning with the body; a point is body-fixed
};

/// A force and a torque, the force acting at `point`.
struct Wrench {
  Vec3 force = Vec3::Zero();   ///< N
  Vec3 torque = Vec3::Zero();  ///< N·m
  Vec3 point = Vec3::Zero();   ///< point of application relative to the centre of mass (m)
  Frame frame = Frame::kWorld;
};

/// An instantaneous change of momentum: a linear impulse J at `point` and an
/// angular impulse H.
struct Impulse {
  Vec3 linear = Vec3::Zero();   ///< J, N·s
  Vec3 angular = Vec3::Zero();  ///< H, N·m·s
  Vec3 point = Vec3::Zero();    ///< point of application relative to the centre of mass (m)
  Frame frame = Frame::kWorld;
};

/// The net external load on one body about its centre of mass. World parts
/// keep their direction; body parts turn with the body and are rotated into
/// the world at every step (a body-frame push follows the body).
struct BodyLoad {
  Vec3 force_W = Vec3::Zero();   ///< N
  Vec3 torque_W = Vec3::Zero();  ///< N·m
  Vec3 force_B = Vec3::Zero();   ///< N, principal axes B
  Vec3 torque_B = Vec3::Zero();  ///< N·m, principal axes B

  bool isZero() const {
    return force_W.isZero(0.0) && torque_W.isZero(0.0) && force_B.isZero(0.0) && torque_B.isZero(0.0);
  }
};

/// One BodyLoad per body, or empty for no external loads.
using Loads = std::vector<BodyLoad>;

/// The fraction of the step [t, t + h) that the window [start, end) covers,
/// in [0, 1]: what a load given over that window delivers in this step.
/// Ends within a billionth of a step of the step's own are taken as on them,
/// since both are sums of dt formed in different ways ((n − 1)·dt + dt is not
/// always n·dt): a window on the step grid acts on whole steps, exactly.
double stepFraction(double start, double end, double t, double h);

/// Adds a wrench to a body's load: τ = τ₀ + r × F about the centre of mass,
/// kept in the wrench's frame (docs/physics.md §3).
void addWrench(const BodyModel& body, BodyLoad& load, const Wrench& wrench);

/// A wrench (or impulse) whose vectors are given in the axes of a frame F,
/// such as another body's root link, re-expressed in world axes for F's
/// orientation now (q_WF): force, torque and the point's offset from the
/// centre of mass are rotated. A load that turns with F is re-expressed at
/// every step (WrenchSchedule). `wrench.frame` must be kWorld ("F's axes").
Wrench inWorldAxes(const Wrench& wrench, const Quat& q_WF);
Impulse inWorldAxes(const Impulse& impulse, const Quat& q_WF);

/// Applies an impulse now: Δv = J / M, Δω = I⁻¹ (r × J + H), with I and r in
/// the current orientation (docs/physics.md §3). Wakes
/// the body if it was asleep.
void applyImpulse(const BodyModel& body, BodyState& s, const Impulse& impulse);

}  // namespace rigid_body_sim::core
