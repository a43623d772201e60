#include "rigid_body_sim/ros/state_requests.h"

#include <cmath>
#include <sstream>

#include "request_checks.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim::node {

using core::Quat;

bool StateRequests::getState(GetState::Request& req, GetState::Response& res) {
  res.success = false;
  const auto target = address_.target(req.body, req.frame, res.message);
  if (!target) return true;
  const auto [body, axes] = *target;
  res.state = bodyState(body, axes);
  res.success = true;
  return true;
}

bool StateRequests::setState(SetState::Request& req, SetState::Response& res) {
  res.success = false;
  const auto target = address_.target(req.body.empty() ? req.state.body : req.body, req.state.twist_frame, res.message);
  if (!target) return true;
  const auto [body, axes] = *target;
  const Vec3 p = fromPoint(req.state.pose.position);
  const Vec3 v = fromVector3(req.state.twist.linear), w = fromVector3(req.state.twist.angular);
  const Quat q = fromQuaternion(req.state.pose.orientation);
  res.message = firstProblem(
      {checkVector(p, kMaxPosition, "position", "m"),
       checkSpeed(v, sim_.model().limits().max_linear_speed, "linear velocity", "limits.max_linear_speed", "m/s"),
       checkSpeed(w, sim_.model().limits().max_angular_speed, "angular velocity", "limits.max_angular_speed",
                  "rad/s")});
  if (!res.message.empty()) return true;
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-3) {
    std::ostringstream os;
    os << "orientation is not a unit quaternion (norm " << q.norm() << "; the identity is x=0 y=0 z=0 w=1)";
    res.message = os.str();
    return true;
  }
  core::LinkState link;
  link.p_WL = p;
  link.q_WL = q.normalized();
  // The twist's axes: the new pose's own, or another body's as it is now.
  const Quat q_frame = axes.frame == core::Frame::kBody ? link.q_WL : address_.orientationOf(axes, body);
  link.v_WL = q_frame * v;
  link.w_W = q_frame * w;
  sim_.place(body, core::bodyStateFromLink(sim_.model().body(body), link));  // no warm start carries over
  ports_.restart(body, sim_.model().body(body), sim_.state.bodies[body]);    // the jump is no acceleration
  res.success = true;
  res.message = "state set";
  hooks_.changed();
  return true;
}

bool StateRequests::reset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  // Back to the initial state; sim time keeps increasing (tf listeners never see it go back).
  sim_.reset(time_.simTime());
  ports_.restartAll(sim_.model(), sim_.state);  // the IMUs from the initial state, the odometry drift from zero
  hooks_.restarted();
  hooks_.changed();
  res.success = true;
  res.message = "reset to the initial state at t = " + time_.text();
  return true;
}

BodyState StateRequests::bodyState(int body, const Axes& axes) const {
  const core::BodyModel& b = sim_.model().body(body);
  const core::LinkState link = core::linkState(b, sim_.state.bodies[body]);
  BodyState msg;
  msg.body = b.name;
  msg.stamp.fromNSec(time_.stampNs());
  msg.pose = toPose(link.p_WL, link.q_WL);
  msg.twist_frame = address_.frameOf(axes, body);
  const Quat q = address_.orientationOf(axes, body).conjugate();
  msg.twist.linear = toVector3(q * link.v_WL);
  msg.twist.angular = toVector3(q * link.w_W);
  return msg;
}

}  // namespace rigid_body_sim::node
