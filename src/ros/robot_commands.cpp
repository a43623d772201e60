// The robots' controllers in the node: robot_commands.h.
#include "rigid_body_sim/ros/robot_commands.h"

#include <std_msgs/Float64.h>
#include <std_msgs/Float64MultiArray.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "request_checks.h"
#include "rigid_body_sim/ros/robot_ports.h"
#include "rigid_body_sim/ros/topic_claims.h"

namespace rigid_body_sim::node {

RobotCommands::RobotCommands(const ros::NodeHandle& nh, std::vector<io::RobotControls> controls,
                             const core::Simulation& sim, const NodeTime& time,
                             const std::vector<std::string>& prefixes)
    : sim_(sim), time_(time), nh_(nh) {
  const std::vector<core::SceneRobot>& robots = sim.scene.robots();
  controls.resize(robots.size());
  for (std::size_t r = 0; r < robots.size(); ++r) {
    addRobot(sim, r, prefixes.at(r), framePrefix(nh_, robots[r].name), std::move(controls[r]));
  }
}

void RobotCommands::addRobot(const core::Simulation& sim, std::size_t r, const std::string& prefix,
                             const std::string& frame_prefix, io::RobotControls controls) {
  const core::SceneRobot& robot = sim.scene.robots().at(r);
  robot_names_.push_back(robot.name);
  std::vector<std::string> joints;
  for (const core::ArticulatedLink& link : robot.model.links) joints.push_back(link.joint);
  joint_names_.push_back(std::move(joints));
  controls_.push_back(std::move(controls));
  applied_.emplace_back();
  handles_.push_back(ownHandle(nh_));
  subscribers_.push_back(subscribe(r, prefix));
  drives_.push_back(openDrives(r, prefix, frame_prefix));
  restart(sim, r, true);
}

std::vector<std::unique_ptr<DrivePorts>> RobotCommands::openDrives(std::size_t r, const std::string& prefix,
                                                                   const std::string& frame_prefix) {
  const std::string& name = robot_names_[r];
  std::vector<std::unique_ptr<DrivePorts>> out;
  const io::RobotControls& controls = controls_[r];
  for (std::size_t d = 0; d < controls.drives.size(); ++d) {
    const io::DriveTopics& topics = controls.drive_topics[d];
    const DriveFrames frames{frame_prefix + topics.odom_frame_id, frame_prefix + topics.base_frame_id};
    const long long every = std::llround(1.0 / (topics.publish_rate * sim_.model().dt()));
    // The callback finds its robot by name: a robot deleted before moves the later ones down.
    auto command = [this, name, d](double v, double w, double vy) {
      const auto it = std::find(robot_names_.begin(), robot_names_.end(), name);
      if (it == robot_names_.end()) return;
      core::DiffDrive& drive = controls_[static_cast<std::size_t>(it - robot_names_.begin())].drives[d];
      if (!drive.command(v, w, time_.simTime(), vy)) {
        ROS_WARN_THROTTLE(
            kWarnPeriod,
            "sim_node: robot '%s': controller '%s': a cmd_vel not finite or beyond 1e4 m/s or rad/s: dropped",
            name.c_str(), drive.spec().name.c_str());
      }
    };
    out.push_back(std::make_unique<DrivePorts>(*handles_.at(r), prefix, controls.drives[d].spec().name, topics, frames,
                                               every, command));
  }
  return out;
}

std::vector<std::string> RobotCommands::odometryFrames(std::size_t r) const {
  std::vector<std::string> frames;
  for (const auto& d : drives_.at(r)) {
    if (d->onTf()) frames.push_back(d->frames().base);
  }
  return frames;
}

void RobotCommands::observe(const core::Simulation& sim) {
  for (std::size_t r = 0; r < controls_.size(); ++r) controls_[r].observe(sim.robots[r], sim.model().dt());
}

void RobotCommands::publishDrives(const ros::Time& stamp, long long steps) {
  if (!ros::ok()) return;
  odom_tf_.clear();
  for (std::size_t r = 0; r < drives_.size(); ++r) {
    for (std::size_t d = 0; d < drives_[r].size(); ++d)
      drives_[r][d]->publish(controls_[r].drives[d], stamp, steps, odom_tf_);
  }
  if (!odom_tf_.empty()) tf_.sendTransform(odom_tf_);
}

std::vector<ros::Subscriber> RobotCommands::subscribe(std::size_t r, const std::string& prefix) {
  // The callbacks find their robot by name: a robot deleted before moves the later ones down.
  const std::string& name = robot_names_[r];
  const auto at = [this, name](const auto& then) {
    const auto it = std::find(robot_names_.begin(), robot_names_.end(), name);
    if (it != robot_names_.end()) then(static_cast<std::size_t>(it - robot_names_.begin()));
  };
  std::vector<ros::Subscriber> subscribers;
  ros::NodeHandle& nh = *handles_.at(r);
  if (controls_[r].base_driver) {  // cmd_vel on the robot: its base driven as a body's
    const std::string topic = deviceTopic(prefix, controls_[r].base_driver_topic);
    subscribers.push_back(nh.subscribe<geometry_msgs::Twist>(
        topic, 10,
        [this, at](const geometry_msgs::Twist::ConstPtr& m) { at([&](std::size_t k) { baseCommand(k, *m); }); }));
    ROS_INFO("sim_node: robot '%s': its base driven by %s", name.c_str(), nh_.resolveName(topic).c_str());
  }
  const std::vector<core::JointControllerSpec>& specs = controls_[r].controllers.specs();
  for (std::size_t c = 0; c < specs.size(); ++c) {
    const std::string topic = prefix + specs[c].name + "/command";
    if (specs[c].mode == core::ControlMode::kTrajectory) {
      subscribers.push_back(nh.subscribe<trajectory_msgs::JointTrajectory>(
          topic, 10, [this, at, c](const trajectory_msgs::JointTrajectory::ConstPtr& m) {
            at([&](std::size_t k) { trajectory(k, c, *m); });
          }));
    } else if (controls_[r].group[c] != 0) {
      subscribers.push_back(nh.subscribe<std_msgs::Float64MultiArray>(
          topic, 10, [this, at, c](const std_msgs::Float64MultiArray::ConstPtr& m) {
            at([&](std::size_t k) { command(k, c, m->data); });
          }));
    } else {
      subscribers.push_back(
          nh.subscribe<std_msgs::Float64>(topic, 10, [this, at, c](const std_msgs::Float64::ConstPtr& m) {
            at([&](std::size_t k) { command(k, c, {m->data}); });
          }));
    }
    ROS_INFO("sim_node: robot '%s': controller '%s' on %s", name.c_str(), specs[c].name.c_str(),
             nh_.resolveName(topic).c_str());
  }
  if (!specs.empty()) {
    subscribers.push_back(nh.subscribe<sensor_msgs::JointState>(
        prefix + "joint_command", 10,
        [this, at](const sensor_msgs::JointState::ConstPtr& m) { at([&](std::size_t k) { jointCommand(k, *m); }); }));
  }
  return subscribers;
}

void RobotCommands::removeRobot(std::size_t r) {
  const std::string name = robot_names_.at(r);
  const auto erase = [r](auto& per_robot) { per_robot.erase(per_robot.begin() + static_cast<std::ptrdiff_t>(r)); };
  erase(subscribers_);  // its topics unsubscribed
  erase(drives_);
  erase(handles_);  // after what it opened
  erase(controls_);
  erase(robot_names_);
  erase(joint_names_);
  erase(applied_);
  watch_.removeRobot(r);
  for (auto it = warned_.begin(); it != warned_.end();) {
    it = it->first.rfind(name + "/", 0) == 0 ? warned_.erase(it) : std::next(it);
  }
}

void RobotCommands::command(std::size_t r, std::size_t c, const std::vector<double>& values) {
  core::JointControllers& controllers = controls_[r].controllers;
  const core::JointControllerSpec& spec = controllers.specs()[c];
  std::vector<core::Clipped> clipped;
  if (!controllers.command(c, values, clipped)) {
    ROS_WARN_THROTTLE(kWarnPeriod,
                      "sim_node: robot '%s': controller '%s': a command of %zu values, %zu expected and each finite "
                      "and not absurd (core/bodies/ranges.h): dropped",
                      robot_names_[r].c_str(), spec.name.c_str(), values.size(), spec.joints.size());
    return;
  }
  warnClipped(r, "controller '" + spec.name + "'", clipped);
}

void RobotCommands::jointCommand(std::size_t r, const sensor_msgs::JointState& msg) {
  core::JointControllers& controllers = controls_[r].controllers;
  const std::size_t n = msg.name.size();
  const auto drop = [&](const std::string& why) {
    ROS_WARN_THROTTLE(kWarnPeriod, "sim_node: robot '%s': joint_command dropped: %s", robot_names_[r].c_str(),
                      why.c_str());
  };
  for (const auto& [field, values] : {std::pair<const char*, const std::vector<double>*>{"position", &msg.position},
                                      {"velocity", &msg.velocity},
                                      {"effort", &msg.effort}}) {
    if (!values->empty() && values->size() != n) {
      return drop(std::string(field) + " has " + std::to_string(values->size()) + " values for " + std::to_string(n) +
                  " names");
    }
  }
  // Checked whole first: each joint, its controller's field, its value.
  struct Target {
    int joint;
    core::ControlMode mode;
    double value;
  };
  std::vector<Target> targets;
  for (std::size_t k = 0; k < n; ++k) {
    const std::vector<std::string>& names = joint_names_[r];
    int j = 1;
    while (j < static_cast<int>(names.size()) && names[j] != msg.name[k]) ++j;
    if (j == static_cast<int>(names.size()))
      return drop("name[" + std::to_string(k) + "]: no joint '" + msg.name[k] + "'");
    const int c = controllers.ownerOf(j);
    if (c < 0) return drop("joint '" + msg.name[k] + "': no controller owns it");
    const core::ControlMode mode = controllers.specs()[c].mode;
    if (mode == core::ControlMode::kTrajectory) {
      return drop("joint '" + msg.name[k] + "': its controller '" + controllers.specs()[c].name +
                  "' takes trajectories, on its command topic");
    }
    const std::vector<double>& values = mode == core::ControlMode::kPosition   ? msg.position
                                        : mode == core::ControlMode::kVelocity ? msg.velocity
                                                                               : msg.effort;
    const char* field = mode == core::ControlMode::kPosition   ? "position"
                        : mode == core::ControlMode::kVelocity ? "velocity"
                                                               : "effort";
    if (values.empty()) {
      return drop("joint '" + msg.name[k] + "': its controller '" + controllers.specs()[c].name + "' takes " + field +
                  ", and the message has none");
    }
    if (!std::isfinite(values[k])) return drop(std::string(field) + "[" + std::to_string(k) + "] is not finite");
    targets.push_back({j, mode, values[k]});
  }
  std::vector<core::Clipped> clipped;
  for (const Target& t : targets) controllers.commandJoint(t.joint, t.mode, t.value, clipped);
  warnClipped(r, "joint_command", clipped);
}

void RobotCommands::trajectory(std::size_t r, std::size_t c, const trajectory_msgs::JointTrajectory& msg) {
  core::JointControllers& controllers = controls_[r].controllers;
  const core::JointControllerSpec& spec = controllers.specs()[c];
  const auto drop = [&](const std::string& why) {
    ROS_WARN_THROTTLE(kWarnPeriod, "sim_node: robot '%s': controller '%s': trajectory dropped: %s",
                      robot_names_[r].c_str(), spec.name.c_str(), why.c_str());
  };
  std::vector<core::TrajectoryPoint> points;
  for (const trajectory_msgs::JointTrajectoryPoint& p : msg.points) {
    points.push_back({p.time_from_start.toSec(), p.positions, p.velocities, p.accelerations});
  }
  // Each of the controller's joints named once, the points put in its order.
  std::vector<std::string> joints;
  for (const int j : spec.joints) joints.push_back(joint_names_[r][j]);
  if (const std::string problem = core::orderTrajectory(joints, msg.joint_names, points); !problem.empty()) {
    return drop(problem);
  }
  if (msg.points.empty()) {  // ros_controllers: an empty trajectory stops the joints where they are
    controllers.hold(c, sim_.robots[r]);
    ROS_INFO("sim_node: robot '%s': controller '%s': an empty trajectory: holding where the joints are",
             robot_names_[r].c_str(), spec.name.c_str());
    return;
  }
  const double now = time_.simTime();
  double start = now;
  if (!msg.header.stamp.isZero()) {
    start = time_.clock.simTimeAt(static_cast<int64_t>(msg.header.stamp.toNSec()));
    if (start - now > kMaxLeadTime) {
      return drop("header.stamp " + formatStamp(static_cast<int64_t>(msg.header.stamp.toNSec())) + " s is " +
                  std::to_string(start - now) + " s ahead of this node's clock (now " + time_.text() +
                  "): is it on another clock? 0 means now");
    }
  }
  std::vector<core::Clipped> clipped;
  int dropped = 0;
  const std::string problem = controllers.followTrajectory(c, now, start, std::move(points), clipped, dropped);
  if (!problem.empty()) return drop(problem);
  // A first point at 0 from "now" is where the joints are meant to be already: dropped quietly (ros_controllers).
  const bool quiet = dropped == 1 && msg.header.stamp.isZero() && msg.points.front().time_from_start.isZero();
  if (dropped > 0 && !quiet) {
    ROS_WARN_THROTTLE(kWarnPeriod,
                      "sim_node: robot '%s': controller '%s': the first %d of %zu points are past (now %s): dropped",
                      robot_names_[r].c_str(), spec.name.c_str(), dropped, msg.points.size(), time_.text().c_str());
  }
  warnClipped(r, "controller '" + spec.name + "'", clipped);
}

void RobotCommands::warnClipped(std::size_t r, const std::string& source, const std::vector<core::Clipped>& clipped) {
  for (const core::Clipped& k : clipped) {
    const std::string joint = robot_names_[r] + "/" + joint_names_[r][k.joint];
    if (!warned_.insert({joint, k.what}).second) continue;
    ROS_WARN(
        "sim_node: robot '%s': %s: a command for joint '%s' is past its URDF %s limit: held to it (said once "
        "per joint)",
        robot_names_[r].c_str(), source.c_str(), joint_names_[r][k.joint].c_str(), k.what.c_str());
  }
}

void RobotCommands::loadsFor(const core::Simulation& sim, double t, std::vector<core::ArticulationLoads>& loads) {
  loads.resize(controls_.size());
  const double dt = sim.model().dt();
  for (std::size_t r = 0; r < controls_.size(); ++r) {
    const core::ArticulationModel& model = sim.scene.robots()[r].model;
    controls_[r].loads(model, sim.robots[r], t, dt, sim.joint_efforts, r, loads[r]);  // the core's control stage
    applied_[r] = loads[r].effort;
    for (const std::string& trouble :
         watch_.observe(r, robot_names_[r], model, controls_[r].controllers, sim.robots[r], applied_[r], dt)) {
      ROS_WARN("sim_node: %s", trouble.c_str());
    }
  }
}

void RobotCommands::baseCommand(std::size_t r, const geometry_msgs::Twist& msg) {
  const core::Vec3 v(msg.linear.x, msg.linear.y, msg.linear.z), w(msg.angular.x, msg.angular.y, msg.angular.z);
  if (!v.allFinite() || !w.allFinite()) {
    ROS_WARN_THROTTLE(1.0, "sim_node: cmd_vel for robot '%s' ignored: not finite", robot_names_[r].c_str());
    return;
  }
  core::VelocityDriver& driver = *controls_[r].base_driver;
  if (driver.command(v, w, time_.simTime()) && warned_.insert({robot_names_[r], "cmd_vel"}).second) {
    ROS_WARN(
        "sim_node: cmd_vel for robot '%s' clipped to cmd_vel.max_linear_speed %g m/s, max_angular_speed %g rad/s "
        "(said once per robot)",
        robot_names_[r].c_str(), driver.settings().max_linear_speed, driver.settings().max_angular_speed);
  }
}

void RobotCommands::setTimeline(std::vector<io::TimedCommand> entries, io::BodyDrivers bodies) {
  timeline_ = io::Timeline(std::move(entries), sim_.scene.robots(), sim_.model().dt(), controls_, std::move(bodies));
}

void RobotCommands::giveTimed(double t, core::JointEffortSchedule& efforts) {
  if (timeline_.empty()) return;
  for (const std::string& said : timeline_.apply(t, sim_.scene.robots(), controls_, efforts)) {
    if (warned_.insert({said, "timeline"}).second) ROS_WARN("sim_node: %s (said once)", said.c_str());
  }
}

void RobotCommands::restart(const core::Simulation& sim) {
  for (std::size_t r = 0; r < controls_.size(); ++r) restart(sim, r, true);
}

void RobotCommands::restart(const core::Simulation& sim, std::size_t r, bool zero_odometry) {
  controls_.at(r).restart(sim.robots[r], zero_odometry);
  applied_[r].resize(0);
  watch_.restart(r);
}

}  // namespace rigid_body_sim::node
