// The robots' joint states and floating bases: robot_ports.h.
#include "rigid_body_sim/ros/robot_ports.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim::node {

sensor_msgs::JointState jointStateMessage(const core::ArticulationModel& robot, const core::ArticulationState& state,
                                          const Eigen::VectorXd& effort, const ros::Time& stamp) {
  sensor_msgs::JointState msg;
  msg.header.stamp = stamp;
  const int n = robot.jointCount();
  msg.name.reserve(n);
  for (int i = 1; i <= n; ++i) msg.name.push_back(robot.links[i].joint);
  msg.position.assign(state.q.data(), state.q.data() + n);
  msg.velocity.assign(state.v.data(), state.v.data() + n);
  msg.effort.assign(n, 0.0);
  if (effort.size() == n) msg.effort.assign(effort.data(), effort.data() + n);
  // Joints that move only massless links, held where they started
  // (physics §2.1): robot_state_publisher still needs them for their frames.
  for (const core::HeldJoint& held : robot.held) {
    msg.name.push_back(held.name);
    msg.position.push_back(held.position);
    msg.velocity.push_back(0.0);
    msg.effort.push_back(0.0);
  }
  return msg;
}

std::string placedBase(const core::ArticulationModel& robot) {
  // Every base but the URDF's own `world`, where robot_state_publisher
  // roots the tree (a base fixed because it has no mass is placed where the
  // start put it: nobody else puts it on tf).
  return robot.links[0].name == "world" ? "" : robot.links[0].name;
}

geometry_msgs::TransformStamped baseTransform(const core::ArticulationState& state, const RobotPorts& ports,
                                              const std::string& world_frame, const ros::Time& stamp) {
  geometry_msgs::TransformStamped tf;
  tf.header.stamp = stamp;
  tf.header.frame_id = world_frame;
  tf.child_frame_id = ports.base_frame;
  tf.transform = toTransform(state.X_WB.translation, state.X_WB.rotation);
  return tf;
}

std::string framePrefix(const ros::NodeHandle& nh, const std::string& robot) {
  std::string key, prefix;
  try {
    if (!ros::NodeHandle(nh, robot).searchParam("tf_prefix", key) || !nh.getParam(key, prefix)) return "";
  } catch (const ros::InvalidNameException&) {
    return "";  // a robot named as no namespace can be: robot_state_publisher cannot run in it
  }
  while (!prefix.empty() && prefix.front() == '/') prefix.erase(0, 1);  // as tf::resolve
  return prefix.empty() ? "" : prefix + "/";
}

std::vector<std::string> robotFrames(const core::ArticulationModel& robot, const std::string& frame_prefix) {
  std::vector<std::string> frames;
  for (std::size_t k = 0; k < robot.links.size(); ++k) {
    const std::string& link = robot.links[k].name;
    if (k == 0 && link == "world") continue;  // the root robot_state_publisher starts from
    frames.push_back(frame_prefix + link);
  }
  return frames;
}

void checkRobotFrames(const std::vector<RobotPorts>& robots, const std::string& world_frame,
                      const std::vector<std::string>& body_frames) {
  std::map<std::string, std::string> owner;  // frame -> who has it
  for (const std::string& frame : body_frames) owner.emplace(frame, "a body");
  for (const RobotPorts& robot : robots) {
    for (const std::string& frame : robot.frames) {
      const std::string who = "robot '" + robot.name + "'";
      if (frame == world_frame) {
        throw io::ConfigError(who + ": its link frame '" + frame + "' is named as ~world_frame; tf would publish " +
                              frame + " -> " + frame + " (name the world frame otherwise)");
      }
      const auto [it, added] = owner.emplace(frame, who);
      if (!added) {
        throw io::ConfigError(who + ": its link frame '" + frame + "' is also a frame of " + it->second +
                              "; robot_state_publisher names a robot's frames as its URDF does, after its "
                              "tf_prefix, so tf would mix them up (set the parameter " +
                              robot.name + "/tf_prefix, as for robot_state_publisher in namespace " + robot.name +
                              ", or give each robot's URDF its own link names)");
      }
    }
  }
}

RobotPublisher::RobotPublisher(const ros::NodeHandle& nh, const core::Scene& scene,
                               const std::vector<std::string>& prefixes, std::string world_frame, double dt,
                               double publish_rate, const std::function<double(std::size_t)>& rate)
    : nh_(nh), world_frame_(std::move(world_frame)), dt_(dt) {
  for (const core::SceneRobot& robot : scene.robots()) {
    const double hz = rate(robots_.size()) > 0.0 ? rate(robots_.size()) : publish_rate;
    addRobot(robot, prefixes.at(robots_.size()), hz, framePrefix(nh_, robot.name));
  }
}

std::string robotTopicPrefix(const std::string& robot_namespace, const std::string& otherwise) {
  if (robot_namespace.empty()) return otherwise;
  return robot_namespace.back() == '/' ? robot_namespace : robot_namespace + "/";
}

void RobotPublisher::addRobot(const core::SceneRobot& robot, const std::string& prefix, double hz,
                              const std::string& frame_prefix) {
  RobotPorts p;
  p.name = robot.name;
  p.prefix = prefix;
  p.frame_prefix = frame_prefix;
  p.frames = robotFrames(robot.model, frame_prefix);
  const std::string base = placedBase(robot.model);
  p.base_frame = base.empty() ? "" : frame_prefix + base;
  p.nh = ownHandle(nh_);
  p.joint_states = CountedPublisher::advertise<sensor_msgs::JointState>(*p.nh, p.prefix + "joint_states", kStreamQueue);
  p.every = std::max(1LL, std::llround(1.0 / (hz * dt_)));
  robots_.push_back(std::move(p));
}

void RobotPublisher::leaveBase(std::size_t r, const std::vector<std::string>& frames) {
  RobotPorts& p = robots_.at(r);
  for (const std::string& frame : frames) {
    if (!p.base_frame.empty() && frame == p.base_frame) {
      ROS_INFO(
          "sim_node: robot '%s': its base '%s' is on tf from its odometry (odom -> base), not from %s; "
          "its ground truth is on ~body_states",
          p.name.c_str(), frame.c_str(), world_frame_.c_str());
      p.base_frame.clear();
    } else {
      ROS_WARN(
          "sim_node: robot '%s': a controller puts odom -> '%s' on tf, and '%s' is not its base frame ('%s'): "
          "set its base_frame_id to the base, or tf may see two parents",
          p.name.c_str(), frame.c_str(), frame.c_str(),
          p.base_frame.empty() ? "none, fixed to the world" : p.base_frame.c_str());
    }
  }
}

void RobotPublisher::publish(const core::Simulation& sim, const std::vector<Eigen::VectorXd>& applied,
                             const ros::Time& now, long long steps) {
  if (!ros::ok()) return;
  bases_.clear();
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    const RobotPorts& p = robots_[r];
    if (steps >= 0 && steps % p.every != 0) continue;
    const core::ArticulationState& state = sim.robots[r];
    if (p.joint_states.listened()) {
      p.joint_states.publish(jointStateMessage(sim.scene.robots()[r].model, state, applied[r], now));
    }
    if (!p.base_frame.empty()) bases_.push_back(baseTransform(state, p, world_frame_, now));
  }
  if (!bases_.empty()) tf_.sendTransform(bases_);
}

}  // namespace rigid_body_sim::node
