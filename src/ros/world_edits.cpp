#include "rigid_body_sim/ros/world_edits.h"

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "request_checks.h"
#include "rigid_body_sim/io/world.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/robot_ports.h"

namespace rigid_body_sim::node {

bool WorldEdits::deleteBody(DeleteBody::Request& req, DeleteBody::Response& res) {
  res.success = false;
  if (req.name.empty()) {
    res.message = "name is empty: give the name of the body to delete";
    return true;
  }
  const std::vector<core::SceneRobot>& robots = sim_.scene.robots();
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (robots[r].name == req.name) {
      deleteRobot(r, res);
      return true;
    }
  }
  std::string why;
  const auto found = address_.body(req.name, why);
  if (!found) {
    res.message = "name: " + why;
    return true;
  }
  const int i = *found;
  const auto start = std::chrono::steady_clock::now();
  // In place, the others not copied; wakes what may touch it; its wrenches
  // and those in its axes go.
  const std::size_t dropped = sim_.removeBody(i);
  ports_.erase(static_cast<std::size_t>(i));  // its topics closed off the loop
  hooks_.removed(req.name);
  if (settings_.report_timing) {
    pacer_.recordDelete(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  res.success = true;
  res.message = "body '" + req.name + "' deleted at t = " + time_.text() + " (" + std::to_string(dropped) +
                " timed wrenches went with it); " + std::to_string(sim_.freeBodyCount()) + " bodies left";
  ROS_INFO("sim_node: %s", res.message.c_str());
  return true;
}

void WorldEdits::deleteRobot(std::size_t r, DeleteBody::Response& res) {
  const std::string name = sim_.scene.robots()[r].name;
  const auto start = std::chrono::steady_clock::now();
  // Its links, state, start and timed efforts; what its links touched wakes.
  sim_.removeRobot(r);
  topics_.release(name);
  hooks_.robot_removed(r, name);  // its topics and controllers
  // What it held goes back to the system, not only to the allocator: after
  // 200 robots spawned and deleted, 24 at most at once, glibc kept 2 MB
  // more of them (20 MB -> 25.1 MB resident, 23.1 MB with this; churn.test).
  malloc_trim(0);
  if (settings_.report_timing) {
    pacer_.recordDelete(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  res.success = true;
  res.message = "robot '" + name + "' deleted at t = " + time_.text() +
                " (its joint_states, controllers and timed joint efforts went with it); " +
                std::to_string(sim_.scene.robots().size()) + " robots and " + std::to_string(sim_.freeBodyCount()) +
                " bodies left";
  ROS_INFO("sim_node: %s", res.message.c_str());
}

void WorldEdits::insertQueued(SpawnQueue& queue) {
  queue.drain([this](SpawnQueue::Spawn& spawn) {
    const auto start = std::chrono::steady_clock::now();
    SpawnBody::Response res = insert(spawn);
    if (settings_.report_timing) {
      pacer_.recordSpawn(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return res;
  });
}

std::string WorldEdits::nameTaken(const std::string& name) const {
  if (ports_.directory().byName(name)) return "name '" + name + "' is taken by a body in the world";
  for (const core::SceneRobot& robot : sim_.scene.robots()) {
    if (robot.name == name) return "name '" + name + "' is taken by a robot in the world";
  }
  return {};
}

std::string WorldEdits::frameOwner(const std::string& frame) const {
  if (frame == settings_.world_frame) return "the world";
  if (const auto body = ports_.directory().ownerOf(frame)) return "body '" + sim_.model().body(*body).name + "'";
  if (!robots_) return {};
  for (const RobotPorts& robot : robots_->robots()) {
    if (std::find(robot.frames.begin(), robot.frames.end(), frame) != robot.frames.end()) {
      return "robot '" + robot.name + "'";
    }
  }
  return {};
}

std::optional<core::LinkState> WorldEdits::requestedStart(const SpawnBody::Request& req, std::string& why) const {
  const auto X_WF = address_.pose(req.frame, why);
  if (!X_WF) return std::nullopt;
  core::LinkState link;
  link.p_WL = *X_WF * fromPoint(req.pose.position);
  link.q_WL = (X_WF->rotation * fromQuaternion(req.pose.orientation).normalized()).normalized();
  link.v_WL = X_WF->rotation * fromVector3(req.twist.linear);
  link.w_W = X_WF->rotation * fromVector3(req.twist.angular);
  why = firstProblem(
      {checkVector(link.p_WL, kMaxPosition, "pose.position (in the world)", "m"),
       checkSpeed(link.v_WL, sim_.model().limits().max_linear_speed, "twist.linear", "limits.max_linear_speed", "m/s"),
       checkSpeed(link.w_W, sim_.model().limits().max_angular_speed, "twist.angular", "limits.max_angular_speed",
                  "rad/s")});
  if (!why.empty()) return std::nullopt;
  return link;
}

SpawnBody::Response WorldEdits::insertRobot(SpawnQueue::Spawn& spawn) {
  SpawnBody::Response res;
  res.success = false;
  const SpawnBody::Request& req = spawn.request;
  res.message = nameTaken(req.name);
  if (!res.message.empty()) return res;
  const core::ArticulationModel& model = spawn.robot->model;
  // Its links' frames are the URDF's names after its tf_prefix (robot_state_publisher's): none may be taken.
  for (const std::string& frame : robotFrames(model, spawn.frame_prefix)) {
    if (const std::string owner = frameOwner(frame); !owner.empty()) {
      res.message = "name '" + req.name + "': the robot's link frame '" + frame + "' is a frame of " + owner +
                    " (robot_state_publisher names links as the URDF does, after the tf_prefix it finds: set " +
                    req.name + "/tf_prefix, as for robot_state_publisher in namespace " + req.name +
                    ", or give each robot its own link names)";
      return res;
    }
  }
  // One topic, one publisher: none of its publishers' topics may be taken.
  if (const std::string problem = topics_.problem(spawn.topics); !problem.empty()) {
    res.message = "name '" + req.name + "': " + problem;
    return res;
  }
  const auto base = requestedStart(req, res.message);
  if (!base) return res;
  core::ArticulationState start = spawn.robot_start;
  core::setBaseLinkState(start, *base);
  try {
    sim_.addRobot(std::move(*spawn.robot), start);  // unchanged if it throws; reset puts it back here
  } catch (const std::exception& e) {
    res.message = e.what();
    return res;
  }
  const std::string& prefix = spawn.control_prefix;
  std::string controllers, drives;
  for (const core::JointControllerSpec& c : spawn.controls.controllers.specs()) {
    controllers += (controllers.empty() ? "" : ", ") + c.name;
  }
  for (std::size_t d = 0; d < spawn.controls.drives.size(); ++d) {
    const io::DriveTopics& t = spawn.controls.drive_topics.at(d);
    const std::string& name = spawn.controls.drives[d].spec().name;
    const std::string topic = deviceTopic(driveNamespace(prefix, name, t), t.cmd_vel_topic);
    drives += (drives.empty() ? "" : ", ") + name + " on '" + topic + "'";
  }
  std::string runs =
      controllers.empty() ? "" : ", controllers " + controllers + " on '" + prefix + "CONTROLLER/command'";
  if (!drives.empty()) runs += ", drives " + drives;
  if (runs.empty()) runs = " (no controllers: apply_joint_effort drives it)";
  topics_.take(req.name, spawn.topics);
  hooks_.robot_added(spawn);
  res.success = true;
  res.message = "robot '" + req.name + "' added at t = " + time_.text() + ": " +
                std::to_string(sim_.scene.robots().back().model.jointCount()) + " moving joints, '" + prefix +
                "joint_states'" + runs;
  ROS_INFO("sim_node: %s", res.message.c_str());
  return res;
}

SpawnBody::Response WorldEdits::insert(SpawnQueue::Spawn& spawn) {
  if (spawn.robot) return insertRobot(spawn);
  SpawnBody::Response res;
  res.success = false;
  const SpawnBody::Request& req = spawn.request;
  const core::BodyModel& body = spawn.body.body();
  // A spawned body's frames and topics are under its name; none may be taken
  // (tf would see two parents of one frame).
  const std::string prefix = req.name + "/";
  std::vector<std::string> new_frames{prefix + body.link};
  for (const core::FixedLink& link : body.fixed_links) new_frames.push_back(prefix + link.name);
  if (spawn.ports->sensors && spawn.ports->sensors->imu()) {
    new_frames.push_back(spawn.ports->imu_frame);  // not one of the body's (openPorts)
  }
  res.message = nameTaken(req.name);
  if (!res.message.empty()) return res;
  for (const std::string& frame : new_frames) {
    if (const std::string owner = frameOwner(frame); !owner.empty()) {
      res.message = "name '" + req.name + "': the new body's frame '" + frame + "' is a frame of " + owner;
      return res;
    }
  }
  const auto link = requestedStart(req, res.message);
  if (!link) return res;
  // Everything that may refuse runs before the world changes (the ports,
  // opened on the spawn thread, refused an IMU on no such link).
  try {
    const core::BodyState start = core::bodyStateFromLink(body, *link);
    sim_.addBody(spawn.body, start);  // in place, unchanged if it throws; reset puts it back here
    ports_.add(std::move(*spawn.ports), body, start, time_.simTime());
  } catch (const std::exception& e) {
    res.message = e.what();
    return res;
  }
  hooks_.added();
  res.success = true;
  const BodyPorts& added = ports_[ports_.size() - 1];
  const auto resolved = [](const std::optional<ros::NodeHandle>& nh, const std::string& topic) {
    return nh ? nh->resolveName(topic) : topic;
  };
  res.message = "body '" + req.name + "' added at t = " + time_.text() + ": frame '" + added.frame + "', topics '" +
                resolved(added.nh, prefix + "odom") + "' and '" + resolved(added.pnh, prefix + "wrench") + "'";
  ROS_INFO("sim_node: %s", res.message.c_str());
  if (const std::string warning = io::touchesNothing(body); !warning.empty()) {
    ROS_WARN("sim_node: %s", warning.c_str());
    res.message += "; warning: " + warning;
  }
  return res;
}

}  // namespace rigid_body_sim::node
