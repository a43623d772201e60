#include "rigid_body_sim/ros/body_ports.h"

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>

#include <algorithm>
#include <boost/make_shared.hpp>
#include <utility>

#include "rigid_body_sim/io/sensor_mount.h"

namespace rigid_body_sim::node {
namespace {

/// Lets what it holds go when the queue calls it, on the queue's thread.
class Release : public ros::CallbackInterface {
 public:
  explicit Release(std::shared_ptr<void> what) : what_(std::move(what)) {}
  CallResult call() override {
    what_.reset();
    return Success;
  }

 private:
  std::shared_ptr<void> what_;
};

}  // namespace

BodyPorts openPorts(const PortContext& context, const core::BodyModel& body, const std::string& prefix,
                    const BodyDevices& devices, bool topics) {
  const auto& [imu, odom_noise, cmd_vel] = devices;
  BodyPorts ports;
  ports.prefix = prefix;
  ports.frame = prefix + body.link;
  // Checked before anything is advertised: a spawn's IMU on no such link is
  // refused with nothing changed (it ended the node once).
  if (imu || odom_noise) {
    ports.sensors = std::make_unique<core::BodySensors>(io::bodySensors(body, imu, odom_noise, context.dt));
  }
  if (imu) {
    const std::string own = imu->frame_id.empty() ? "imu_link" : imu->frame_id;
    ports.imu_frame = prefix + own;
    bool taken = own == body.link;
    for (const core::FixedLink& link : body.fixed_links) taken = taken || own == link.name;
    if (taken || ports.imu_frame == context.world_frame) {
      throw io::ConfigError(imu->key + ".frame_id '" + own + "' of body '" + body.name +
                            "': is already a frame (of the body, or the world); name the sensor's own frame");
    }
  }
  const std::string name = body.name;  // by name: a deletion moves the later bodies' indices
  ros::NodeHandle& nh = ports.nh.emplace(context.nh);
  ros::NodeHandle& pnh = ports.pnh.emplace(context.pnh);
  if (cmd_vel) {
    ports.driver.emplace(*cmd_vel);
    const auto& on_cmd_vel = context.on_cmd_vel;
    ports.cmd_vel = nh.subscribe<geometry_msgs::Twist>(
        prefix + "cmd_vel", 10, [on_cmd_vel, name](const geometry_msgs::Twist::ConstPtr& m) { on_cmd_vel(name, m); });
  }
  if (odom_noise) {
    ports.ground_truth = CountedPublisher::advertise<nav_msgs::Odometry>(nh, prefix + "ground_truth", kStreamQueue);
  }
  if (imu) {
    const std::string& topic = imu->topic;
    ports.imu_pub =
        CountedPublisher::advertise<sensor_msgs::Imu>(nh, topic.front() == '/' ? topic : prefix + topic, kStreamQueue);
  }
  if (!topics && !cmd_vel && !odom_noise && !imu) return ports;
  ports.odom = CountedPublisher::advertise<nav_msgs::Odometry>(nh, prefix + "odom", kStreamQueue);
  const auto& on_wrench = context.on_wrench;
  ports.wrench = pnh.subscribe<geometry_msgs::WrenchStamped>(
      prefix + "wrench", 10,
      [on_wrench, name](const geometry_msgs::WrenchStamped::ConstPtr& m) { on_wrench(name, m); });
  return ports;
}

BodyPorts& PortRegistry::add(BodyPorts ports, const core::BodyModel& body, const core::BodyState& start, double t) {
  if (ports.sensors) ports.sensors->start(body, start, t);
  ports.colour = entered_++;
  BodyDirectory::Entry entry{body.name, ports.frame, {}};
  for (const core::FixedLink& link : body.fixed_links) entry.other_frames.push_back(ports.prefix + link.name);
  if (ports.sensors && ports.sensors->imu()) entry.other_frames.push_back(ports.imu_frame);
  directory_.add(std::move(entry));
  ports_.push_back(std::move(ports));
  return ports_.back();
}

void PortRegistry::erase(std::size_t i) {
  directory_.erase(i);
  auto gone = std::make_shared<BodyPorts>(std::move(ports_.at(i)));
  ports_.erase(ports_.begin() + static_cast<std::ptrdiff_t>(i));
  closer_->addCallback(boost::make_shared<Release>(std::move(gone)));
}

void PortRegistry::restart(std::size_t i, const core::BodyModel& body, const core::BodyState& now) {
  if (ports_[i].sensors) ports_[i].sensors->restart(body, now);
}

void PortRegistry::restartAll(const core::Model& model, const core::State& state) {
  for (std::size_t i = 0; i < ports_.size(); ++i) {
    if (ports_[i].sensors) ports_[i].sensors->restartAll(model.body(i), state.bodies[i]);  // the drift too
  }
}

std::vector<std::string> PortRegistry::frames() const {
  std::vector<std::string> frames;
  frames.reserve(ports_.size());
  for (const BodyPorts& p : ports_) frames.push_back(p.frame);
  return frames;
}

std::vector<std::size_t> PortRegistry::colours() const {
  std::vector<std::size_t> colours;
  colours.reserve(ports_.size());
  for (const BodyPorts& p : ports_) colours.push_back(p.colour);
  return colours;
}

}  // namespace rigid_body_sim::node
