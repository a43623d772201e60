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
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/ros/addressing.h"
#include "rigid_body_sim/ros/body_ports.h"
#include "rigid_body_sim/ros/params.h"
#include "rigid_body_sim/ros/sim_clock.h"

namespace rigid_body_sim::node {

class LoadRequests {
 public:
  /// Reads the node's time from `time`; changes `sim`'s
  /// state and schedule and the ports' drivers.
  LoadRequests(core::Simulation& sim, PortRegistry& ports, const Addressing& address, const NodeSettings& settings,
               const NodeTime& time)
      : sim_(sim), ports_(ports), address_(address), settings_(settings), time_(time) {}

  bool applyWrench(ApplyWrench::Request& req, ApplyWrench::Response& res);
  bool applyImpulse(ApplyImpulse::Request& req, ApplyImpulse::Response& res);
  bool clearWrenches(ClearWrenches::Request& req, ClearWrenches::Response& res);
  /// A ~PREFIXwrench message for the body named `body`: held from now; a
  /// bad one is dropped with a warning (a topic has no answer).
  void onWrench(const std::string& body, const geometry_msgs::WrenchStamped::ConstPtr& msg);
  /// A PREFIXcmd_vel message for the body named `body`, which has a driver.
  void onCmdVel(const std::string& body, const geometry_msgs::Twist::ConstPtr& msg);

 private:
  core::Simulation& sim_;
  PortRegistry& ports_;
  const Addressing& address_;
  const NodeSettings& settings_;
  const NodeTime& time_;
};

}  // namespace rigid_body_sim::node
