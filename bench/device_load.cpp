// The load on sim_node's devices for bench/devices.sh: subscribes to every
// body's IMU (and, with `contacts`, to ~contacts) so the node really builds
// and sends them, and sends each body a cmd_vel at 10 Hz (with `drive`).
// Bodies are b0..b{N-1}; one body has the single-body names.
// Usage: device_load N [imu] [contacts] [drive]
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "rigid_body_sim/Contacts.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "device_load", ros::init_options::AnonymousName);
  if (argc < 2) return 2;
  const int n = std::atoi(argv[1]);
  bool imu = false, contacts = false, drive = false;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    imu = imu || a == "imu";
    contacts = contacts || a == "contacts";
    drive = drive || a == "drive";
  }
  ros::NodeHandle nh;
  long count = 0;
  std::vector<ros::Subscriber> subs;
  std::vector<ros::Publisher> pubs;
  for (int i = 0; i < n; ++i) {
    const std::string prefix = n == 1 ? "/" : "/b" + std::to_string(i) + "/";
    if (imu) {
      subs.push_back(
          nh.subscribe<sensor_msgs::Imu>(prefix + "imu", 100, [&](const sensor_msgs::Imu::ConstPtr&) { ++count; }));
    }
    if (drive) pubs.push_back(nh.advertise<geometry_msgs::Twist>(prefix + "cmd_vel", 1));
  }
  if (contacts) {
    subs.push_back(nh.subscribe<rigid_body_sim::Contacts>("/sim_node/contacts", 10,
                                                          [&](const rigid_body_sim::Contacts::ConstPtr&) { ++count; }));
  }
  ros::Rate rate(10.0);
  geometry_msgs::Twist t;
  t.linear.x = 0.2;
  t.angular.z = 0.5;
  while (ros::ok()) {
    for (const ros::Publisher& p : pubs) p.publish(t);
    ros::spinOnce();
    rate.sleep();
  }
  return count < 0;
}
