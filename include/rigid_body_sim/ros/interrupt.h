// SIGINT (Ctrl-C, roslaunch, rostest) for sim_node, in place of roscpp's
// handler, which shuts ROS down from its own thread up to 0.1 s later, so a
// publish could race the shutdown. Here, while the world loads (a big mesh
// takes seconds, and nothing is advertised yet), SIGINT ends the process at
// once with code 130; once the node runs, it only raises a flag: the step
// loop stops at its next tick and main shuts ROS down from its own thread.
#pragma once

namespace rigid_body_sim::node {

/// Installs the handler; call right after ros::init(…, ros::init_options::NoSigintHandler).
void installInterruptHandler();

/// The world is loaded: from now on SIGINT only sets interrupted().
void markRunning();

/// Whether SIGINT came since markRunning().
bool interrupted();

}  // namespace rigid_body_sim::node
