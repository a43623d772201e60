// sim_node: load the body, build the simulation, step and publish until
// SIGINT (interrupt.h) or shutdown.
#include <ros/ros.h>

#include "rigid_body_sim/ros/interrupt.h"
#include "rigid_body_sim/ros/sim_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "sim_node", ros::init_options::NoSigintHandler);
  rigid_body_sim::node::installInterruptHandler();
  // The handles outlive the try: when the last one goes, ROS (and its
  // logging) shuts down, and the fatal message would be lost.
  ros::NodeHandle nh, private_nh("~");
  try {
    rigid_body_sim::node::SimNode node(nh, private_nh);
    rigid_body_sim::node::markRunning();
    node.run();
  } catch (const std::exception& e) {
    ROS_FATAL("sim_node: %s", e.what());
    return 1;
  }
  ros::shutdown();  // from this thread, after the last publish
  return 0;
}
