#include "rigid_body_sim/ros/load_requests.h"

#include <sstream>

#include "request_checks.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim::node {

bool LoadRequests::applyWrench(ApplyWrench::Request& req, ApplyWrench::Response& res) {
  res.success = false;
  const auto target = address_.target(req.body, req.frame, res.message);
  if (!target) return true;
  const auto [body, axes] = *target;
  const Vec3 force = fromVector3(req.force), torque = fromVector3(req.torque), point = fromPoint(req.point);
  res.message =
      firstProblem({checkVector(force, kMaxForce, "force", "N"), checkVector(torque, kMaxTorque, "torque", "N*m"),
                    checkVector(point, kMaxPosition, "point", "m")});
  if (!res.message.empty()) return true;
  const double duration = req.duration.toSec();
  if (duration == 0.0) {
    res.message =
        "duration 0 applies nothing: give duration > 0 (for that long), < 0 (until clear_wrenches), "
        "or call apply_impulse for an instantaneous push";
    return true;
  }
  std::string when;
  const std::optional<double> starts = startOf(req.start_time, time_, when, res.message);
  if (!starts) return true;
  const double start = *starts;
  const double end = duration > 0.0 ? start + duration : core::WrenchSchedule::kForever;
  if (!sim_.schedule.add(body, {force, torque, point, axes.frame}, start, end, axes.other)) {
    res.message = "body '" + sim_.model().body(body).name + "' already holds " +
                  std::to_string(core::WrenchSchedule::kMaxPerBody) +
                  " wrenches, acting or yet to start (the most per body): wait for some to end, or clear_wrenches";
    return true;
  }
  res.success = true;
  std::ostringstream os;
  os << "wrench on '" << sim_.model().body(body).name << "' " << when << " "
     << (duration > 0.0 ? "for " + std::to_string(duration) + " s" : std::string("until cleared"));
  res.message = os.str();
  return true;
}

bool LoadRequests::applyImpulse(ApplyImpulse::Request& req, ApplyImpulse::Response& res) {
  res.success = false;
  const auto target = address_.target(req.body, req.frame, res.message);
  if (!target) return true;
  const auto [body, axes] = *target;
  const Vec3 linear = fromVector3(req.linear), angular = fromVector3(req.angular), point = fromPoint(req.point);
  res.message = firstProblem({checkVector(linear, kMaxImpulse, "linear", "N*s"),
                              checkVector(angular, kMaxImpulse, "angular", "N*m*s"),
                              checkVector(point, kMaxPosition, "point", "m")});
  if (!res.message.empty()) return true;
  core::BodyState after = sim_.state.bodies[body];
  core::Impulse impulse{linear, angular, point, axes.frame};
  if (axes.other >= 0) impulse = core::inWorldAxes(impulse, address_.orientationOf(axes, body));
  core::applyImpulse(sim_.model().body(body), after, impulse);
  const std::string speed = checkSpeed(after.v_WB, sim_.model().limits().max_linear_speed, "resulting velocity",
                                       "limits.max_linear_speed", "m/s");
  const std::string spin = checkSpeed(after.w_B, sim_.model().limits().max_angular_speed, "resulting angular velocity",
                                      "limits.max_angular_speed", "rad/s");
  if (!speed.empty() || !spin.empty()) {
    res.message = speed.empty() ? spin : speed;
    return true;
  }
  sim_.state.bodies[body] = after;
  res.success = true;
  res.message = "impulse applied to '" + sim_.model().body(body).name + "'";
  return true;
}

bool LoadRequests::clearWrenches(ClearWrenches::Request& req, ClearWrenches::Response& res) {
  int body = -1;
  if (!req.body.empty()) {
    const auto found = address_.body(req.body, res.message);
    if (!found) {
      res.success = false;
      return true;
    }
    body = *found;
  }
  sim_.schedule.clear(body);  // held ones too
  res.success = true;
  res.message = "wrenches cleared";
  return true;
}

void LoadRequests::onWrench(const std::string& name, const geometry_msgs::WrenchStamped::ConstPtr& msg) {
  std::string why;
  const auto found = address_.body(name, why);
  if (!found) return;  // deleted, its message already queued
  const int body = *found;
  const auto axes = address_.axes(msg->header.frame_id, body, why);
  const Vec3 force = fromVector3(msg->wrench.force), torque = fromVector3(msg->wrench.torque);
  if (why.empty()) why = checkVector(force, kMaxForce, "force", "N");
  if (why.empty()) why = checkVector(torque, kMaxTorque, "torque", "N*m");
  if (!why.empty()) {
    ROS_WARN_THROTTLE(kWarnPeriod, "sim_node: wrench for '%s' ignored: %s", sim_.model().body(body).name.c_str(),
                      why.c_str());
    return;
  }
  const double timeout = settings_.wrench_timeout > 0.0 ? settings_.wrench_timeout : core::WrenchSchedule::kForever;
  sim_.schedule.hold(body, {force, torque, Vec3::Zero(), axes->frame}, time_.simTime(), timeout, axes->other);
}

void LoadRequests::onCmdVel(const std::string& name, const geometry_msgs::Twist::ConstPtr& msg) {
  std::string why;
  const auto found = address_.body(name, why);
  if (!found) return;  // deleted, its message already queued
  BodyPorts& p = ports_[*found];
  const Vec3 v = fromVector3(msg->linear), w = fromVector3(msg->angular);
  if (!v.allFinite() || !w.allFinite()) {
    ROS_WARN_THROTTLE(kWarnPeriod, "sim_node: cmd_vel for '%s' ignored: not finite", name.c_str());
    return;
  }
  if (p.driver->command(v, w, time_.simTime()) && !p.clipped) {
    p.clipped = true;
    ROS_WARN(
        "sim_node: cmd_vel for '%s' clipped to cmd_vel.max_linear_speed %g m/s, max_angular_speed %g rad/s "
        "(said once per body)",
        name.c_str(), p.driver->settings().max_linear_speed, p.driver->settings().max_angular_speed);
  }
}

}  // namespace rigid_body_sim::node
