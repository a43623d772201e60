// What rbsim reports of a run besides the states: rbsim_report.h.
#include "rbsim_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/step/diagnostics.h"

namespace rigid_body_sim::tools {

double robotEnergy(const core::ArticulationModel& model, const core::ArticulationState& s, const core::Vec3& g) {
  const core::ArticulationKinematics kin = core::kinematics(model, s);
  return core::kineticEnergy(model, kin) + core::potentialEnergy(model, kin, g);
}

core::Vec3 robotAngularMomentum(const core::ArticulationModel& model, const core::ArticulationState& s) {
  return core::momentum_W(model, core::kinematics(model, s)).head<3>();
}

bool robotAtRest(const core::ArticulationModel& model, const core::ArticulationState& s,
                 const core::SleepSettings& sleep) {
  if (s.V_B.head<3>().norm() >= sleep.angular_velocity || s.V_B.tail<3>().norm() >= sleep.linear_velocity) return false;
  for (int i = 1; i <= model.jointCount(); ++i) {
    const bool slides = model.links[i].type == core::JointType::Prismatic;
    if (std::abs(s.v(i - 1)) >= (slides ? sleep.linear_velocity : sleep.angular_velocity)) return false;
  }
  return true;
}

Json jointsJson(const core::ArticulationModel& model, const core::ArticulationState& s) {
  Json joints = Json::object();
  for (int i = 1; i <= model.jointCount(); ++i) {
    joints[model.links[i].joint] = {{"position", num(s.q(i - 1))}, {"velocity", num(s.v(i - 1))}};
  }
  return joints;
}

core::Vec3 bodiesAngularMomentum(const core::Model& model, const core::State& state, std::size_t count) {
  core::Vec3 total = core::Vec3::Zero();
  for (std::size_t i = 0; i < count; ++i) {
    const core::BodyState& s = state.bodies[i];
    total += core::angularMomentumWorld(model.body(i), s) + model.body(i).mass * s.p_WB.cross(s.v_WB);
  }
  return total;
}

void checkStep(const core::Model& model, const core::Workspace& ws, double t, std::vector<char>& limited) {
  for (const core::Divergence& d : ws.diverged) {
    throw Diverged("body '" + model.body(d.body).name + "': " + d.what + " stopped being finite at t = " + text(t) +
                   " s (the step's guard put it back at rest; the run stops here)");
  }
  for (const int i : ws.speed_limited) {
    if (limited[i]) continue;
    limited[i] = 1;
    std::fprintf(stderr,
                 "rbsim: warning: body '%s' reached the speed limits at t = %s s (limits.max_linear_speed %s m/s, "
                 "limits.max_angular_speed %s rad/s): its velocity is held to them\n",
                 model.body(i).name.c_str(), text(t).c_str(), text(model.limits().max_linear_speed).c_str(),
                 text(model.limits().max_angular_speed).c_str());
  }
}

void warnRobotLimited(const std::string& name, const core::SpeedLimits& limits, double t) {
  std::fprintf(stderr,
               "rbsim: warning: robot '%s' reached the speed limits at t = %s s (limits.max_linear_speed %s "
               "m/s, limits.max_angular_speed %s rad/s): its velocities are held to them\n",
               name.c_str(), text(t).c_str(), text(limits.max_linear_speed).c_str(),
               text(limits.max_angular_speed).c_str());
}

void warnOnce(const std::vector<std::string>& notes, std::vector<std::string>& said) {
  for (const std::string& s : notes) {
    if (std::find(said.begin(), said.end(), s) != said.end()) continue;
    std::fprintf(stderr, "rbsim: warning: %s (said once)\n", s.c_str());
    said.push_back(s);
  }
}

}  // namespace rigid_body_sim::tools
