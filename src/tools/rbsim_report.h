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

/// Each of `notes` (a timeline's) not yet in `said` as a warning on stderr,
/// then kept in `said`: each said once in a run.
void warnOnce(const std::vector<std::string>& notes, std::vector<std::string>& said);

/// The warning for a robot held back by the speed limits.
void warnRobotLimited(const std::string& name, const core::SpeedLimits& limits, double t);

}  // namespace rigid_body_sim::tools
