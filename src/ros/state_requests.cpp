// The requests that read or set the state and run the clock: get_state,
// set_state, reset, pause, unpause and step. Each validates first: a
// refused request changes nothing.
#include <cmath>
#include <sstream>

#include "request_checks.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {

using core::Quat;

bool SimNode::getState(GetState::Request& req, GetState::Response& res) {
  res.success = false;
  const auto target = address_.target(req.body, req.frame, res.message);
  if (!target) return true;
  const auto [body, axes] = *target;
  res.state = bodyState(body, axes);
  res.success = true;
  return true;
}

bool SimNode::setState(SetState::Request& req, SetState::Response& res) {
  res.success = false;
  const auto target = address_.target(req.body.empty() ? req.state.body : req.body, req.state.twist_frame, res.message);
  if (!target) return true;
  const auto [body, axes] = *target;
  const Vec3 p = fromPoint(req.state.pose.position);
  const Vec3 v = fromVector3(req.state.twist.linear), w = fromVector3(req.state.twist.angular);
  const Quat q = fromQuaternion(req.state.pose.orientation);
  res.message = firstProblem(
      {checkVector(p, kMaxPosition, "position", "m"),
       checkSpeed(v, model_.limits().max_linear_speed, "linear velocity", "limits.max_linear_speed", "m/s"),
       checkSpeed(w, model_.limits().max_angular_speed, "angular velocity", "limits.max_angular_speed", "rad/s")});
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
  state_.bodies[body] = core::bodyStateFromLink(model_.body(body), link);
  state_.contact_impulses.clear();            // nothing carries over to a new pose
  ports_.restart(body, state_.bodies[body]);  // the jump is no acceleration
  res.success = true;
  res.message = "state set";
  publish();
  return true;
}

bool SimNode::reset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  // Back to the initial state; sim time keeps increasing (tf listeners never see it go back).
  sim_.reset(simTime());
  ports_.restartAll(state_);  // the IMUs from the initial state, the odometry drift from zero
  rebaseClock();
  publish();
  res.success = true;
  res.message = "reset to the initial state at t = " + now();
  return true;
}

bool SimNode::pause(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  setPaused(true);
  showPhysics();
  res.success = true;
  res.message = "paused at t = " + now();
  return true;
}

bool SimNode::unpause(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  // Do not make up for the paused time; the wall-anchored clock resumes at
  // wall time, or, if steps taken while paused put it ahead, waits for it.
  paused_ = false;
  const double lead = rebaseClock();
  showPhysics();
  res.success = true;
  res.message = "running from t = " + now();
  if (lead > 0.0 && settings_.realtime_factor > 0.0) {
    res.message += " once the wall clock reaches it, in " + std::to_string(lead) +
                   " s (the steps taken while paused put the clock ahead; /use_sim_time has no such wait)";
  }
  return true;
}

bool SimNode::step(Step::Request& req, Step::Response& res) {
  res.success = false;
  if (!paused_) {
    res.message = "the simulation is running: call pause first (step advances a paused simulation)";
    return true;
  }
  if (req.steps < 1 || req.steps > kMaxSteps) {
    res.message = "steps = " + std::to_string(req.steps) + ": must be within 1 ... " + std::to_string(kMaxSteps);
    return true;
  }
  for (int k = 0; k < req.steps; ++k) stepOnce();
  publisher_->clock(stamp());
  publish();
  res.success = true;
  res.message = "stepped " + std::to_string(req.steps) + " steps";
  res.time = stamp();
  for (std::size_t i = 0; i < model_.bodyCount(); ++i) res.states.push_back(bodyState(static_cast<int>(i), Axes{}));
  return true;
}

BodyState SimNode::bodyState(int body, const Axes& axes) const {
  const core::BodyModel& b = model_.body(body);
  const core::LinkState link = core::linkState(b, state_.bodies[body]);
  BodyState msg;
  msg.body = b.name;
  msg.stamp = stamp();
  msg.pose = toPose(link.p_WL, link.q_WL);
  msg.twist_frame = address_.frameOf(axes, body);
  const Quat q = address_.orientationOf(axes, body).conjugate();
  msg.twist.linear = toVector3(q * link.v_WL);
  msg.twist.angular = toVector3(q * link.w_W);
  return msg;
}

}  // namespace rigid_body_sim::node
