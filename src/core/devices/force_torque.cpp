// A force-torque sensor on a joint (docs/physics.md §10.10).
#include "rigid_body_sim/core/devices/force_torque.h"

#include <cmath>
#include <stdexcept>

namespace rigid_body_sim::core {

void checkForceTorque(const ForceTorqueSettings& s) {
  if (!(std::isfinite(s.noise) && s.noise >= 0.0)) {
    throw std::invalid_argument("noise must be finite and >= 0 (a sigma, N and N*m)");
  }
}

std::vector<Vec6> contactWrenches_L(const SceneRobot& robot, const ArticulationKinematics& kin,
                                    const std::vector<BodyState>& bodies, const std::vector<Contact>& contacts,
                                    double h) {
  std::vector<Vec6> out(robot.model.links.size(), Vec6::Zero());
  const int first = robot.first_body, last = first + static_cast<int>(robot.link.size());
  // A contact's force on one of the robot's bodies, at its point, into its link's wrench.
  const auto add = [&](int body, const Vec3& point_W, const Vec3& force_W) {
    if (body < first || body >= last) return;
    const int link = robot.link[static_cast<std::size_t>(body - first)];
    const Placement& X_WL = kin.X_WL[static_cast<std::size_t>(link)];
    const Vec3 f_L = X_WL.R_PC.transpose() * force_W;
    const Vec3 r_L = X_WL.R_PC.transpose() * (point_W - X_WL.p_PC);
    out[static_cast<std::size_t>(link)].head<3>() += r_L.cross(f_L);
    out[static_cast<std::size_t>(link)].tail<3>() += f_L;
  };
  for (const Contact& c : contacts) {
    if (c.normal_impulse <= 0.0 && c.tangent_impulse_W.isZero()) continue;
    const Vec3 force_W = (c.normal_impulse * c.normal_W + c.tangent_impulse_W) / h;  // on `body`
    add(c.body, bodies[static_cast<std::size_t>(c.body)].p_WB + c.r_W, force_W);
    if (c.other >= 0) add(c.other, bodies[static_cast<std::size_t>(c.other)].p_WB + c.r_other_W, -force_W);
  }
  return out;
}

ForceTorqueSensor::ForceTorqueSensor(int link, const ForceTorqueSettings& settings) : link_(link), settings_(settings) {
  checkForceTorque(settings);
  if (link <= 0) throw std::invalid_argument("a force-torque sensor is on a joint: link > 0");
}

Vec6 ForceTorqueSensor::reading(const ArticulationModel& model, const ArticulationKinematics& kin,
                                const Eigen::VectorXd& u, const Eigen::VectorXd& u_before, double h, const Vec3& g_W,
                                const std::vector<Vec6>& wrench_L) {
  const std::uint64_t sample = readings_++;
  const Eigen::VectorXd udot = (u - u_before) / h;
  Vec6 w = jointWrenches(model, kin, udot, g_W, wrench_L)[static_cast<std::size_t>(link_)];
  if (settings_.noise > 0.0) {  // reading k's own stream (sample_seed.h)
    rng_.seed(sampleSeed(settings_.seed, sample));
    normal_.reset();
    for (int k = 0; k < 6; ++k) w(k) += settings_.noise * normal_(rng_);
  }
  return w;
}

}  // namespace rigid_body_sim::core
