// The requests that read or set the state: get_state, set_state and reset.
// Each checks first: a refused request changes nothing. A state set or
// reset is published at once (the hook the node gives). pause, unpause and
// step run the loop and stay with it (pacing.cpp).
#pragma once

#include <std_srvs/Trigger.h>

#include <functional>
#include <string>

#include "rigid_body_sim/BodyState.h"
#include "rigid_body_sim/GetState.h"
#include "rigid_body_sim/SetState.h"
#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/ros/addressing.h"
#include "rigid_body_sim/ros/body_ports.h"
#include "rigid_body_sim/ros/sim_clock.h"

namespace rigid_body_sim::node {

class StateRequests {
 public:
  /// What a change of state asks of the node: `changed` after set_state
  /// and reset (publish the new state), `restarted` after reset before it
  /// (the pacing starts again from now).
  struct Hooks {
    std::function<void()> changed;
    std::function<void()> restarted;
  };

  /// Reads the node's time from `time`.
  StateRequests(core::Simulation& sim, PortRegistry& ports, const Addressing& address, const NodeTime& time,
                Hooks hooks)
      : sim_(sim), ports_(ports), address_(address), time_(time), hooks_(std::move(hooks)) {}

  bool getState(GetState::Request& req, GetState::Response& res);
  bool setState(SetState::Request& req, SetState::Response& res);
  /// Back to the initial state; sim time goes on (tf listeners never see it go back).
  bool reset(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);

  /// `body`'s state now for a message, its twist in `axes`, stamped on the node's clock.
  BodyState bodyState(int body, const Axes& axes) const;

 private:
  core::Simulation& sim_;
  PortRegistry& ports_;
  const Addressing& address_;
  const NodeTime& time_;
  Hooks hooks_;
};

}  // namespace rigid_body_sim::node
