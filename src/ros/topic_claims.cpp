// One topic, one publisher: topic_claims.h.
#include "rigid_body_sim/ros/topic_claims.h"

#include <set>
#include <stdexcept>
#include <utility>

namespace rigid_body_sim::node {

std::string deviceTopic(const std::string& prefix, const std::string& topic) {
  return !topic.empty() && topic.front() == '/' ? topic : prefix + topic;
}

std::array<std::string, 3> cameraTopics(const std::string& prefix, const io::DepthCameraEntry& camera) {
  const std::string ns = deviceTopic(prefix, camera.topic) + "/";
  // A topic from the root stays there, as in Gazebo's camera plugins.
  const auto under = [&ns](const std::string& topic) { return deviceTopic(ns, topic); };
  return {under(camera.image_topic), under(camera.info_topic), under(camera.points_topic)};
}

std::string driveNamespace(const std::string& prefix, const std::string& controller, const io::DriveTopics& topics) {
  return topics.under_controller ? prefix + controller + "/" : prefix;
}

std::string TopicClaims::problem(const std::vector<Claim>& claims) const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::map<std::string, const Claim*> own;
  for (const Claim& c : claims) {
    std::string topic;
    try {
      topic = resolve_(c.topic);
    } catch (const std::exception& e) {
      return c.what + ": topic '" + c.topic + "' is no ROS name (" + e.what() + ")";
    }
    if (const auto it = taken_.find(topic); it != taken_.end()) {
      return c.what + ": topic '" + topic + "' is taken by '" + it->second.owner + "' " + it->second.what +
             " (one topic, one publisher: name another topic)";
    }
    if (const auto [it, added] = own.emplace(topic, &c); !added) {
      return c.what + ": topic '" + topic + "' is also its " + it->second->what +
             "'s (one topic, one publisher: name another topic)";
    }
  }
  return {};
}

void TopicClaims::take(const std::string& owner, const std::vector<Claim>& claims) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const Claim& c : claims) taken_[resolve_(c.topic)] = Holder{owner, c.what};
}

void TopicClaims::release(const std::string& owner) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = taken_.begin(); it != taken_.end();) it = it->second.owner == owner ? taken_.erase(it) : std::next(it);
}

std::vector<TopicClaims::Claim> robotTopics(const std::string& prefix, const std::string& control_prefix,
                                            const io::RobotSensors& sensors, const io::RobotControls& controls) {
  std::vector<TopicClaims::Claim> out{{control_prefix + "joint_states", "joint_states"}};
  for (std::size_t d = 0; d < controls.drives.size(); ++d) {
    const io::DriveTopics& t = controls.drive_topics.at(d);
    const std::string& name = controls.drives[d].spec().name;
    const std::string ns = driveNamespace(control_prefix, name, t);
    out.push_back({deviceTopic(ns, t.odom_topic), "controller '" + name + "''s odometry"});
    if (t.publish_cmd) out.push_back({ns + "cmd_vel_out", "controller '" + name + "''s cmd_vel_out"});
  }
  for (const io::RobotLidar& l : sensors.lidars) out.push_back({deviceTopic(prefix, l.entry.topic), l.entry.key});
  for (const io::RobotCamera& c : sensors.cameras) {
    const std::array<std::string, 3> topics = cameraTopics(prefix, c.entry);
    for (const std::string& t : topics) out.push_back({t, c.entry.key});
  }
  for (const io::RobotImu& m : sensors.imus) out.push_back({deviceTopic(prefix, m.entry.topic), m.entry.key});
  for (const io::RobotGnss& g : sensors.gnss) {
    out.push_back({deviceTopic(prefix, g.entry.topic), g.entry.key});
    out.push_back({deviceTopic(prefix, g.entry.velocity_topic), g.entry.key + "'s velocity"});
  }
  for (const io::RobotContactSensor& c : sensors.contact_sensors) {
    out.push_back({deviceTopic(prefix, c.entry.topic), c.entry.key});
  }
  for (const io::RobotForceTorque& f : sensors.force_torques) {
    out.push_back({deviceTopic(prefix, f.entry.topic), f.entry.key});
  }
  for (const io::RobotMagnetometer& m : sensors.magnetometers) {
    out.push_back({deviceTopic(prefix, m.entry.topic), m.entry.key});
  }
  for (const io::RobotOdometry& o : sensors.odometry) {
    out.push_back({deviceTopic(prefix, o.entry.topic), o.entry.key});
    if (!o.entry.ground_truth.empty()) {
      out.push_back({deviceTopic(prefix, o.entry.ground_truth), o.entry.key + "'s ground truth"});
    }
  }
  return out;
}

}  // namespace rigid_body_sim::node
