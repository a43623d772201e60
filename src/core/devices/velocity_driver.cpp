// The velocity driver (docs/physics.md §10.4).
#include "rigid_body_sim/core/devices/velocity_driver.h"

#include <cmath>

#include "bodies/validate.h"
#include "rigid_body_sim/core/bodies/ranges.h"

namespace rigid_body_sim::core {
namespace {

/// v scaled down to |v| ≤ limit.
Vec3 clipped(const Vec3& v, double limit) {
  const double n = v.norm();
  return n > limit ? Vec3(v * (limit / n)) : v;
}

}  // namespace

void validateDriver(const DriverSettings& s, const std::string& key) {
  detail::requirePositiveAtMost(s.max_force, 1e6, key + ".max_force", "N");
  detail::requirePositiveAtMost(s.max_torque, 1e6, key + ".max_torque", "N*m");
  detail::requireWithin(s.linear_gain, 0.0, 1e4, key + ".linear_gain", "1/s");
  detail::requireWithin(s.linear_integral_gain, 0.0, 1e6, key + ".linear_integral_gain", "1/s^2");
  detail::requireWithin(s.angular_gain, 0.0, 1e4, key + ".angular_gain", "1/s");
  detail::requireWithin(s.angular_integral_gain, 0.0, 1e6, key + ".angular_integral_gain", "1/s^2");
  // The range of limits.*: a driver may ask for any speed the world allows.
  detail::requireWithin(s.max_linear_speed, 0.0, ranges::kMaxSpeedLimit, key + ".max_linear_speed", "m/s");
  detail::requireWithin(s.max_angular_speed, 0.0, ranges::kMaxSpeedLimit, key + ".max_angular_speed", "rad/s");
  detail::requireWithin(s.timeout, 0.0, 1e6, key + ".timeout", "s (0: until replaced)");
}

bool VelocityDriver::command(const Vec3& v_L, const Vec3& w_L, double t) {
  Vec3 v = v_L, w = w_L;
  if (settings_.planar) {
    v.z() = 0.0;
    w.x() = w.y() = 0.0;
  }
  v_cmd_ = clipped(v, settings_.max_linear_speed);
  w_cmd_ = clipped(w, settings_.max_angular_speed);
  commanded_ = true;
  received_ = t;
  return v_cmd_ != v || w_cmd_ != w;
}

bool VelocityDriver::active(double t) const {
  return commanded_ && (settings_.timeout == 0.0 || t - received_ <= settings_.timeout);
}

BodyLoad VelocityDriver::load(const BodyModel& body, const BodyState& s, double t, double h) {
  return load(linkState(body, s), body.mass, body.I_C_L, t, h);
}

void addDriverLoad(VelocityDriver& driver, const Model& model, const State& state, std::size_t i, double t, double h,
                   Loads& loads) {
  const BodyLoad drive = driver.load(model.body(i), state.bodies[i], t, h);
  if (drive.isZero()) return;
  if (loads.empty()) loads.resize(model.bodyCount());
  loads[i].force_W += drive.force_W;
  loads[i].torque_W += drive.torque_W;
}

BodyLoad VelocityDriver::load(const LinkState& link, double mass, const Mat3& I_C_L, double t, double h) {
  BodyLoad out;
  if (!active(t)) {
    v_integral_ = w_integral_ = Vec3::Zero();
    commanded_ = commanded_ && settings_.timeout == 0.0;
    return out;
  }
  // The frame the error is taken in: the link's own, or for a ground robot
  // its heading (the link's yaw about the world z).
  Quat q_WF = link.q_WL;
  if (settings_.planar) {
    const Vec3 x = link.q_WL * Vec3::UnitX();
    q_WF = Quat(Eigen::AngleAxisd(std::atan2(x.y(), x.x()), Vec3::UnitZ()));
  }
  const Vec3 v_F = q_WF.conjugate() * link.v_WL, w_F = q_WF.conjugate() * link.w_W;
  Vec3 ev = v_cmd_ - v_F, ew = w_cmd_ - w_F;
  if (settings_.planar) {
    ev.z() = 0.0;
    ew.x() = ew.y() = 0.0;
  }
  const DriverSettings& k = settings_;
  // PI with conditional integration: the integral grows only while the
  // output is within its limit (no wind-up while saturated).
  const Vec3 f_free = mass * (k.linear_gain * ev + k.linear_integral_gain * (v_integral_ + h * ev));
  if (f_free.norm() <= k.max_force) v_integral_ += h * ev;
  const Vec3 f_F = clipped(mass * (k.linear_gain * ev + k.linear_integral_gain * v_integral_), k.max_force);
  const Mat3 I_F = (q_WF.conjugate() * link.q_WL).toRotationMatrix() * I_C_L *
                   (q_WF.conjugate() * link.q_WL).toRotationMatrix().transpose();
  const Vec3 t_free = I_F * (k.angular_gain * ew + k.angular_integral_gain * (w_integral_ + h * ew));
  if (t_free.norm() <= k.max_torque) w_integral_ += h * ew;
  const Vec3 t_F = clipped(I_F * (k.angular_gain * ew + k.angular_integral_gain * w_integral_), k.max_torque);
  out.force_W = q_WF * f_F;
  out.torque_W = q_WF * t_F;
  return out;
}

SpatialInertia robotInertia_B(const ArticulationModel& model, const ArticulationKinematics& kin) {
  const Placement& X_WB = kin.X_WL[0];
  SpatialInertia all;
  for (std::size_t k = 0; k < model.links.size(); ++k) {
    const Placement& X_WL = kin.X_WL[k];
    const Placement X_BL{X_WB.R_PC.transpose() * X_WL.R_PC, X_WB.R_PC.transpose() * (X_WL.p_PC - X_WB.p_PC)};
    const SpatialInertia I_B = kin.I_L[k].toParent(X_BL);
    all.mass += I_B.mass;
    all.h += I_B.h;
    all.I_O += I_B.I_O;
  }
  return all;
}

Vec6 baseLoad(VelocityDriver& driver, const ArticulationModel& model, const ArticulationKinematics& kin, double t,
              double h) {
  const Placement& X_WB = kin.X_WL[0];
  const SpatialInertia all = robotInertia_B(model, kin);
  const Vec3 c_B = all.h / all.mass;  // the centre of mass
  const Mat3 I_C_B = all.I_O - all.mass * (c_B.squaredNorm() * Mat3::Identity() - c_B * c_B.transpose());
  LinkState base;
  base.p_WL = X_WB.p_PC;
  base.q_WL = Quat(X_WB.R_PC).normalized();
  base.w_W = X_WB.R_PC * kin.V_L[0].head<3>();
  base.v_WL = X_WB.R_PC * kin.V_L[0].tail<3>();
  const BodyLoad load = driver.load(base, all.mass, I_C_B, t, h);
  const Vec3 f_B = X_WB.R_PC.transpose() * load.force_W;
  Vec6 wrench;
  wrench.head<3>() = X_WB.R_PC.transpose() * load.torque_W + c_B.cross(f_B);  // the force acts through c
  wrench.tail<3>() = f_B;
  return wrench;
}

}  // namespace rigid_body_sim::core
