// What rbsim reports of a run besides the states: energies, momenta, rest,
// joints, the steps' warnings, and the devices it does not run. Shared by the world's run
// (rbsim_main.cpp) and a scene's, robots and all (rbsim_scene.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "rbsim_output.h"
#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/step/workspace.h"
#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::tools {

/// A robot's kinetic and potential energy (J) under g.
double robotEnergy(const core::ArticulationModel& model, const core::ArticulationState& s, const core::Vec3& g);

/// A robot's angular momentum about the world origin.
core::Vec3 robotAngularMomentum(const core::ArticulationModel& model, const core::ArticulationState& s);

/// At rest: every joint and the base slower than the sleep speeds (a
/// prismatic joint and the base's v by the linear one).
bool robotAtRest(const core::ArticulationModel& model, const core::ArticulationState& s,
                 const core::SleepSettings& sleep);

/// final.joints: per joint, its position and velocity.
Json jointsJson(const core::ArticulationModel& model, const core::ArticulationState& s);

/// Σ I ω + r × m v of bodies 0 .. count − 1, about the world origin.
core::Vec3 bodiesAngularMomentum(const core::Model& model, const core::State& state, std::size_t count);

/// What a step reports beyond the state: a body held back by the speed
/// limits (a warning, once per body, `limited` remembering) or put back by
/// the guard (Diverged: the end).
void checkStep(const core::Model& model, const core::Workspace& ws, double t, std::vector<char>& limited);

/// A free body's `cmd_vel` (the config's one body's, and each body's of
/// `bodies`: entry i is body `entry[i]`, a robot's < 0, all bodies without
/// `entry`) is the node's to run: named once on stderr, never taken silently.
void noteDevices(const io::SimConfig& config, const std::vector<int>& entry = {});

/// The warning for a robot held back by the speed limits.
void warnRobotLimited(const std::string& name, const core::SpeedLimits& limits, double t);

}  // namespace rigid_body_sim::tools
