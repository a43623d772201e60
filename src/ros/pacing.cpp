// The loop: sim time follows the wall clock × ~realtime_factor, in ticks
// of ~rate, and the node's one clock (SimClock) is anchored to it; and the
// services that run it: pause, unpause and step.
#include <sys/prctl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "request_checks.h"
#include "rigid_body_sim/ros/interrupt.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {

void SimNode::stepOnce() {
  const double t = simTime(), h = model_.dt();
  commands_->giveTimed(t, sim_.joint_efforts);       // the config's timeline, before the step it is due at
  schedule_.loadsFor(model_, state_, t, h, loads_);  // timed wrenches, and those ~wrench holds
  for (std::size_t i = 0; i < ports_.size(); ++i) {  // the velocity drivers' forces
    if (ports_[i].driver) core::addDriverLoad(*ports_[i].driver, model_, state_, i, t, h, loads_);
  }
  commands_->loadsFor(sim_, t, robot_loads_);  // the robots' controllers, from the state before the step
  link_sensors_->before(sim_);                 // the force-torque sensors' velocities before the step
  sim_.step(loads_, robot_loads_);
  commands_->observe(sim_);  // the drives' odometry, from where the step left the wheels
  reportStep();
  ++steps_;
  state_.time = simTime();  // the node's clock: exact multiples of Δt, never reset
  sampleSensors();
  sim_.contacts.update(state_, workspace_.contacts);
  link_sensors_->publish(sim_, robot_loads_, steps_, simTime(), stamp());
  schedule_.dropFinished(simTime());
  sim_.joint_efforts.dropFinished(simTime());
  if (steps_ % publish_every_ == 0) {
    publisher_->clock(stamp());
    publishBodies();
    publisher_->contacts(sim_, stamp());
  }
  robot_publisher_->publish(sim_, commands_->applied(), stamp(), steps_);  // each at its rate
  commands_->publishDrives(stamp(), steps_);
  if (steps_ % body_states_every_ == 0) publisher_->bodyStates(sim_, ports_, stamp());
}

void SimNode::publish() {
  publishBodies();
  robot_publisher_->publish(sim_, commands_->applied(), stamp());
  commands_->publishDrives(stamp());
}

void SimNode::publishBodies() {
  if (publisher_->state(sim_, ports_, stamp(), simTime(), steps_ % publish_every_ == 0)) markers_->afterTf();
}

void SimNode::reportStep() {
  // Robots, as bodies (physics §11.7): a runaway held by the limits, a step
  // the guard undid.
  const core::SceneWorkspace& scene = sim_.workspace;
  for (std::size_t r = 0; r < scene.robot_diverged.size() && r < sim_.scene.robots().size(); ++r) {
    const std::string& name = sim_.scene.robots()[r].name;
    if (scene.robot_diverged[r]) {
      sim_.joint_efforts.clear(r, -1);
      ROS_WARN(
          "sim_node: robot '%s' stopped being finite at t = %s; it is back where the step began, at rest, and its "
          "timed joint efforts are cleared",
          name.c_str(), now().c_str());
    }
    if (r < scene.robots.size() && scene.robots[r].speed_limited && robots_speed_limited_.insert(name).second) {
      ROS_WARN(
          "sim_node: robot '%s' reached the speed limits at t = %s (limits.max_linear_speed %g m/s, "
          "limits.max_angular_speed %g rad/s): its joints and base are held to them (said once per robot)",
          name.c_str(), now().c_str(), model_.limits().max_linear_speed, model_.limits().max_angular_speed);
    }
  }
  if (workspace_.speed_limited.empty() && workspace_.diverged.empty()) return;
  for (const core::Divergence& d : workspace_.diverged) {
    // Its loads made it diverge, or will again: they go with it.
    schedule_.clear(d.body);
    ROS_WARN(
        "sim_node: body '%s': %s stopped being finite at t = %s; it is back at its last finite pose, at rest, "
        "and its wrenches are cleared",
        model_.body(d.body).name.c_str(), d.what.c_str(), now().c_str());
  }
  for (const int i : workspace_.speed_limited) {
    if (ports_[i].speed_limited) continue;
    ports_[i].speed_limited = true;
    ROS_WARN(
        "sim_node: body '%s' reached the speed limits at t = %s (limits.max_linear_speed %g m/s, "
        "limits.max_angular_speed %g rad/s): its velocity is held to them (said once per body)",
        model_.body(i).name.c_str(), now().c_str(), model_.limits().max_linear_speed,
        model_.limits().max_angular_speed);
  }
}

double SimNode::rebaseClock() {
  const int64_t lead = paused_ ? 0 : clock_.anchor(steps_, static_cast<int64_t>(ros::WallTime::now().toNSec()));
  pacer_.rebase(Pacer::Clock::now() + std::chrono::nanoseconds(lead), simTime());
  return 1e-9 * static_cast<double>(lead);
}

// The services that run the loop: pause, unpause and step.
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
  for (std::size_t i = 0; i < ports_.size(); ++i)
    res.states.push_back(state_requests_.bodyState(static_cast<int>(i), Axes{}));
  return true;
}

void SimNode::run() {
  using Clock = Pacer::Clock;
  // Linux lets a sleeping thread wake up to 50 us late by default (timer
  // slack); at 1 kHz that is the step-period jitter. Ask for 1 us.
  prctl(PR_SET_TIMERSLACK, 1000UL, 0UL, 0UL, 0UL);
  const auto tick = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / settings_.rate));
  rebaseClock();
  auto next_tick = Clock::now();
  while (ros::ok() && !interrupted()) {
    const auto tick_start = Clock::now();
    const double rtf = settings_.realtime_factor;  // ~physics may change it between ticks
    if (settings_.report_timing) pacer_.recordTick(tick_start);
    if (!paused_ && rtf > 0.0) {
      // Step until sim time reaches wall time × realtime factor, a slice at
      // a time (Pacer::kCallbackPeriod), serving the callbacks between.
      for (int n = pacer_.stepsDue(tick_start, steps_, model_.dt(), rtf); n > 0; --n) stepOnce();
      if (pacer_.behind()) {
        ROS_WARN_THROTTLE(5.0, "sim_node: cannot keep up with realtime_factor %g; slowing down", rtf);
        rebaseClock();
      }
    } else if (!paused_) {
      // As fast as possible: steps in slices of about a millisecond, then callbacks.
      const auto slice_end = tick_start + std::chrono::milliseconds(1);
      do {
        for (int k = 0; k < 64; ++k) stepOnce();
      } while (Clock::now() < slice_end);
    }
    ros::spinOnce();
    world_edits_.insertQueued(spawns_);
    if (rtf > 0.0 && !paused_ && pacer_.more()) continue;  // the rest of the steps due, at once
    if (rtf > 0.0 || paused_) {
      next_tick += tick;
      const auto now = Clock::now();
      if (next_tick < now) next_tick = now;  // late: do not try to make up ticks
      std::this_thread::sleep_until(next_tick);
    }
  }
  if (settings_.report_timing) {
    // Plain stdout: ROS logging is already shut down once ros::ok() is false.
    for (const std::string& line : pacer_.report(1.0 / settings_.rate, simTime())) {
      std::printf("sim_node: timing: %s\n", line.c_str());
    }
    std::fflush(stdout);
  }
}

}  // namespace rigid_body_sim::node
