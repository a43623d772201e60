// The bodies' sensors: each IMU (core::Imu, docs/physics.md §10.1) sampled
// at its rate of sim time and published as sensor_msgs/Imu (REP 145).
#include "rigid_body_sim/ros/sensor_messages.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {

void SimNode::sampleSensors() {
  for (std::size_t i = 0; i < ports_.size(); ++i) {
    BodyPorts& p = ports_[i];
    if (!p.imu || steps_ % p.imu_every != 0) continue;
    const core::ImuReading r = p.imu->sample(model_.body(i), state_.bodies[i], model_.gravity(),
                                             static_cast<double>(p.imu_every) * model_.dt());
    if (!ros::ok() || !p.imu_pub.listened()) continue;  // sampled all the same: the noise stays seeded
    p.imu_pub.publish(imuMessage(r, p.imu->settings(), p.imu_frame, stamp()));
  }
}

}  // namespace rigid_body_sim::node
