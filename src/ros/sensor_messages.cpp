// The link sensors' messages: sensor_messages.h.
#include "rigid_body_sim/ros/sensor_messages.h"

#include <cstdint>

#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim::node {
namespace {

/// Diagonal covariance σ² (row-major 3×3).
boost::array<double, 9> diagonal(double sigma) {
  boost::array<double, 9> c{};
  c[0] = c[4] = c[8] = sigma * sigma;
  return c;
}

}  // namespace

sensor_msgs::Imu imuMessage(const core::ImuReading& r, const core::ImuSettings& s, const std::string& frame,
                            const ros::Time& stamp) {
  sensor_msgs::Imu msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.orientation = toQuaternion(r.q_WS);
  msg.orientation_covariance = diagonal(s.orientation_noise);
  msg.angular_velocity = toVector3(r.w_S);
  msg.angular_velocity_covariance = diagonal(s.gyro_noise);
  msg.linear_acceleration = toVector3(r.f_S);
  msg.linear_acceleration_covariance = diagonal(s.accel_noise);
  return msg;
}

sensor_msgs::NavSatFix fixMessage(const core::GnssFix& f, const std_msgs::Header& header, int status, int service) {
  sensor_msgs::NavSatFix m;
  m.header = header;
  m.status.status = static_cast<std::int8_t>(status);
  m.status.service = static_cast<std::uint16_t>(service);
  m.latitude = f.latitude;
  m.longitude = f.longitude;
  m.altitude = f.altitude;
  bool diagonal = true;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      m.position_covariance[3 * i + j] = f.position_covariance_ENU(i, j);
      diagonal = diagonal && (i == j || f.position_covariance_ENU(i, j) == 0.0);
    }
  }
  m.position_covariance_type =
      diagonal ? sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN : sensor_msgs::NavSatFix::COVARIANCE_TYPE_KNOWN;
  return m;
}

geometry_msgs::Vector3Stamped vectorMessage(const core::Vec3& v, const std_msgs::Header& header) {
  geometry_msgs::Vector3Stamped m;
  m.header = header;
  m.vector.x = v.x();
  m.vector.y = v.y();
  m.vector.z = v.z();
  return m;
}

sensor_msgs::MagneticField magneticFieldMessage(const core::Vec3& field, const std_msgs::Header& header) {
  sensor_msgs::MagneticField m;
  m.header = header;
  m.magnetic_field.x = field.x();
  m.magnetic_field.y = field.y();
  m.magnetic_field.z = field.z();
  return m;
}

}  // namespace rigid_body_sim::node
