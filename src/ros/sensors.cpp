// The bodies' sensors: each IMU (core::Imu, docs/physics.md §10.1) sampled
// at its rate of sim time and published as sensor_msgs/Imu (REP 145).
#include <sensor_msgs/Imu.h>

#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {
namespace {

/// Diagonal covariance σ² (row-major 3×3).
boost::array<double, 9> diagonal(double sigma) {
  boost::array<double, 9> c{};
  c[0] = c[4] = c[8] = sigma * sigma;
  return c;
}

}  // namespace

void SimNode::sampleSensors() {
  for (std::size_t i = 0; i < ports_.size(); ++i) {
    BodyPorts& p = ports_[i];
    if (!p.imu || steps_ % p.imu_every != 0) continue;
    const core::ImuReading r = p.imu->sample(model_.body(i), state_.bodies[i], model_.gravity(),
                                             static_cast<double>(p.imu_every) * model_.dt());
    if (!ros::ok() || !p.imu_pub.listened()) continue;  // sampled all the same: the noise stays seeded
    const core::ImuSettings& s = p.imu->settings();
    sensor_msgs::Imu msg;
    msg.header.stamp = stamp();
    msg.header.frame_id = p.imu_frame;
    msg.orientation = toQuaternion(r.q_WS);
    msg.orientation_covariance = diagonal(s.orientation_noise);
    msg.angular_velocity = toVector3(r.w_S);
    msg.angular_velocity_covariance = diagonal(s.gyro_noise);
    msg.linear_acceleration = toVector3(r.f_S);
    msg.linear_acceleration_covariance = diagonal(s.accel_noise);
    p.imu_pub.publish(msg);
  }
}

}  // namespace rigid_body_sim::node
