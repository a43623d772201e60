// The smallest roscpp service server, spun as sim_node spins (spinOnce every
// millisecond): what the transport does without the simulator
// (bench/service_churn.sh).
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <chrono>
#include <thread>

int main(int argc, char** argv) {
  ros::init(argc, argv, "trivial_server");
  ros::NodeHandle nh("~");
  boost::function<bool(std_srvs::Trigger::Request&, std_srvs::Trigger::Response&)> answer =
      [](std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
        res.success = true;
        return true;
      };
  const ros::ServiceServer server = nh.advertiseService("trigger", answer);
  while (ros::ok()) {
    ros::spinOnce();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return 0;
}
