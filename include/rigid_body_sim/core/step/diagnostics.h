// Energy and momentum, the quantities the physics tests check.
#pragma once

#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"

namespace rigid_body_sim::core {

/// ½ M |v|² + ½ ωᵀ I ω (J).
double kineticEnergy(const BodyModel& body, const BodyState& s);

/// −M g · p_WB (J), zero at the world origin.
double potentialEnergy(const BodyModel& body, const BodyState& s, const Vec3& gravity_W);

/// Kinetic plus potential energy of all bodies (J).
double totalEnergy(const Model& model, const State& state);

/// How deep `body` lies inside the static scene in state `s`: the largest
/// r − φ(p) over its contact points (radius r, the scene's signed distance
/// φ at its centre; a rim's or side's at its deepest point, as detection
/// measures it), or 0 when it is clear of it (m). What a start inside the
/// ground is warned with.
double sceneDepth(const Model& model, std::size_t body, const BodyState& s);

/// Angular momentum about the centre of mass, world frame: R_WB I_B w_B (kg·m²/s).
Vec3 angularMomentumWorld(const BodyModel& body, const BodyState& s);

}  // namespace rigid_body_sim::core
