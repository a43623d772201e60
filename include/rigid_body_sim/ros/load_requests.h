// The requests that push bodies: apply_wrench (timed, in any body's axes,
// from a start_time on the node's clock), apply_impulse, clear_wrenches, a
// body's ~wrench topic (held until ~wrench_timeout) and its cmd_vel (the
// velocity driver's command). Each checks first: a refused request changes
// nothing. They run on the loop's thread, between steps.
#pragma once

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/WrenchStamped.h>

#include <string>

#include "rigid_body_sim/ApplyImpulse.h"
#include "rigid_body_sim/ApplyWrench.h"
#include "rigid_body_sim/ClearWrenches.h"
#include "rigid_body_sim/core/simulation.h"
#include "rigid_body_sim/ros/addressing.h"
#include "rigid_body_sim/ros/body_ports.h"
#include "rigid_body_sim/ros/params.h"
#include "rigid_body_sim/ros/sim_clock.h"

namespace rigid_body_sim::node {

class LoadRequests {
 public:
  /// Reads the node's time as `steps` taken on `clock`; changes `sim`'s
  /// state and schedule and the ports' drivers.
  LoadRequests(core::Simulation& sim, PortRegistry& ports, const Addressing& address, const NodeSettings& settings,
               const SimClock& clock, const long long& steps)
      : sim_(sim), ports_(ports), address_(address), settings_(settings), clock_(clock), steps_(steps) {}

  bool applyWrench(ApplyWrench::Request& req, ApplyWrench::Response& res);
  bool applyImpulse(ApplyImpulse::Request& req, ApplyImpulse::Response& res);
  bool clearWrenches(ClearWrenches::Request& req, ClearWrenches::Response& res);
  /// A ~PREFIXwrench message for the body named `body`: held from now; a
  /// bad one is dropped with a warning (a topic has no answer).
  void onWrench(const std::string& body, const geometry_msgs::WrenchStamped::ConstPtr& msg);
  /// A PREFIXcmd_vel message for the body named `body`, which has a driver.
  void onCmdVel(const std::string& body, const geometry_msgs::Twist::ConstPtr& msg);

 private:
  double simTime() const { return static_cast<double>(steps_) * sim_.model.dt(); }
  std::string now() const { return formatStamp(clock_.stampAt(steps_)) + " s"; }

  core::Simulation& sim_;
  PortRegistry& ports_;
  const Addressing& address_;
  const NodeSettings& settings_;
  const SimClock& clock_;
  const long long& steps_;
};

}  // namespace rigid_body_sim::node
