// The bodies' sensors (core::BodySensors, docs/physics.md §10.1): each IMU
// sampled at its rate of sim time and published as sensor_msgs/Imu (REP 145).
#include "rigid_body_sim/ros/sensor_messages.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {

void SimNode::sampleSensors() {
  for (std::size_t i = 0; i < ports_.size(); ++i) {
    BodyPorts& p = ports_[i];
    if (!p.sensors) continue;
    p.sensors->sample(model_.body(i), state_.bodies[i], model_.gravity(), steps_);
    // Sampled all the same: the noise stays seeded.
    if (!p.sensors->imuFresh() || !ros::ok() || !p.imu_pub.listened()) continue;
    p.imu_pub.publish(imuMessage(p.sensors->imuReading(), p.sensors->imu()->settings(), p.imu_frame, stamp()));
  }
}

}  // namespace rigid_body_sim::node
