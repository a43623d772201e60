// A steered base's geometry: steering.h, docs/physics.md §11.14.
#include "rigid_body_sim/core/controllers/steering.h"

#include <algorithm>
#include <cmath>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/controllers/diff_drive.h"

namespace rigid_body_sim::core {

double steerAngle(double delta, double wheelbase, double x, double y) {
  return std::atan2(x * std::sin(delta), wheelbase * std::cos(delta) - y * std::sin(delta));
}

double steerable(const SteeringSpec& s, double delta) {
  const double most = s.speed_at_steered_wheel ? 0.5 * M_PI : 80.0 * M_PI / 180.0;
  return std::clamp(delta, -most, most);
}

PlanarMotion motionPerSpeed(const SteeringSpec& s, double delta) {
  if (s.speed_at_steered_wheel) return {std::cos(delta), std::sin(delta) / s.wheelbase};
  return {1.0, std::tan(delta) / s.wheelbase};
}

double rimSpeed(const PlanarMotion& m, double x, double y, double a) {
  return (m.v - m.w * y) * std::cos(a) + m.w * x * std::sin(a);
}

PlanarMotion allowedDirection(double x, double y, double a) {
  const PlanarMotion d{x * std::cos(a) + y * std::sin(a), std::sin(a)};
  const double n = std::copysign(std::hypot(d.v, d.w), d.v);  // the line's direction with v >= 0
  if (!(std::abs(n) > 0.0)) return {1.0, 0.0};
  return {d.v / n, d.w / n};
}

PidGains defaultSteeringGains(const ArticulationModel& model, int joint) {
  const double response = jointResponse(model, kinematics(model, restState(model)), joint);
  return servoGains(1.0 / response, model.links.at(joint).limits.effort);
}

}  // namespace rigid_body_sim::core
