// ~spawn_body: read, checked and built on the spawn thread (a mesh body's
// distance grid takes up to seconds, which the loop must not wait for), then
// added by the loop between two steps (insertPendingBodies). A step never
// sees the model change: the loop adds the body in place between steps
// (core::Model::addBody). Deleting is in world_requests.cpp.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <sstream>

#include "request_checks.h"
#include "rigid_body_sim/core/ranges.h"
#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/io/world.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {
namespace {

/// The checks that need nothing of the world: name, pose, twist and surface.
std::string checkSpawnRequest(const SpawnBody::Request& req) {
  const core::Quat q = fromQuaternion(req.pose.orientation);
  std::string orientation;
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-3) {
    std::ostringstream os;
    os << "pose.orientation is not a unit quaternion (norm " << q.norm() << "; the identity is x=0 y=0 z=0 w=1)";
    orientation = os.str();
  }
  return firstProblem({checkName(req.name),
                       checkVector(fromPoint(req.pose.position), kMaxPosition, "pose.position", "m"), orientation,
                       checkVector(fromVector3(req.twist.linear), kMaxPosition, "twist.linear", "m/s"),
                       checkVector(fromVector3(req.twist.angular), kMaxPosition, "twist.angular", "rad/s"),
                       req.own_friction ? checkCoefficient(req.friction, core::ranges::kMaxFriction, "friction") : "",
                       req.own_restitution ? checkCoefficient(req.restitution, 1.0, "restitution") : ""});
}

/// The body the request's URDF describes: exactly one of urdf_xml,
/// urdf_param (read from the parameter server) or urdf_file. Throws
/// std::exception with a message that starts with the field.
core::BodySpec loadRequestedUrdf(const SpawnBody::Request& req, const ros::NodeHandle& nh,
                                 const std::string& base_dir) {
  const int given = !req.urdf_xml.empty() + !req.urdf_param.empty() + !req.urdf_file.empty();
  if (given != 1) {
    throw std::invalid_argument("urdf_xml, urdf_param, urdf_file: give exactly one (" + std::to_string(given) +
                                " given)");
  }
  // Each loader's message starts with the source it was given: the field.
  if (!req.urdf_xml.empty()) return io::loadUrdfString(req.urdf_xml, "urdf_xml");
  if (!req.urdf_param.empty()) {
    std::string xml, where;
    try {
      where = "urdf_param '" + nh.resolveName(req.urdf_param) + "'";
      if (!nh.getParam(req.urdf_param, xml)) throw std::invalid_argument(where + ": not set, or holds no string");
    } catch (const ros::InvalidNameException& e) {
      throw std::invalid_argument("urdf_param '" + req.urdf_param + "': not a parameter name (" + e.what() + ")");
    }
    return io::loadUrdfString(xml, where);
  }
  const std::string& uri = req.urdf_file;
  if (uri.rfind("package://", 0) != 0 && uri.rfind("file://", 0) != 0 && uri.front() != '/') {
    throw std::invalid_argument("urdf_file '" + uri +
                                "' is a relative path, and the node's working folder is ROS's: give an "
                                "absolute path or package://PACKAGE/PATH");
  }
  try {
    return io::loadUrdfFile(io::resolveMeshUri(uri, base_dir));
  } catch (const std::exception& e) {
    throw std::invalid_argument("urdf_file: " + std::string(e.what()));
  }
}

}  // namespace

bool SimNode::spawnBody(SpawnBody::Request& req, SpawnBody::Response& res) {
  // The spawn thread: nothing here reads the model, the state or the ports
  // (the loop changes them); builder_ holds copies of what it needs.
  res.success = false;
  res.message = checkSpawnRequest(req);
  if (!res.message.empty()) return true;
  SpawnQueue::Spawn spawn;
  try {
    core::BodySpec spec = loadRequestedUrdf(req, nh_, params_.sim.base_dir);
    spec.name = req.name;
    if (req.own_friction) spec.friction = req.friction;
    if (req.own_restitution) spec.restitution = req.restitution;
    spawn.body = builder_.build(spec);
  } catch (const std::exception& e) {
    res.message = e.what();
    return true;
  }
  // The devices, each given as the YAML of its config map ("" = none); an
  // error starts with the field.
  const auto parsed = [&res](const std::string& field, const std::string& yaml, const auto& parse, auto& into) {
    if (yaml.empty()) return true;
    try {
      into = parse(yaml);
      return true;
    } catch (const std::exception& e) {
      const std::string what = e.what();
      res.message = what.rfind(field + ":", 0) == 0 ? what : field + ": " + what;
      return false;
    }
  };
  BodyDevices d;
  const double dt = dt_;
  if (!parsed(
          "imu", req.imu, [dt](const std::string& y) { return io::parseImuText(y, "imu", dt); }, d.imu) ||
      !parsed(
          "odom_noise", req.odom_noise, [](const std::string& y) { return io::parseOdomNoiseText(y, "odom_noise"); },
          d.odom_noise) ||
      !parsed(
          "cmd_vel", req.cmd_vel, [](const std::string& y) { return io::parseDriverText(y, "cmd_vel"); }, d.cmd_vel)) {
    return true;
  }
  try {
    spawn.ports = std::make_unique<BodyPorts>(openPorts(port_context_, spawn.body.body(), req.name + "/", d));
  } catch (const std::exception& e) {
    res.message = e.what();
    return true;
  }
  spawn.request = req;
  res = spawns_.submit(std::move(spawn), [] { return ros::ok(); });  // the loop adds it at its next tick
  return true;
}

void SimNode::insertPendingBodies() {
  spawns_.drain([this](SpawnQueue::Spawn& spawn) {
    const auto start = std::chrono::steady_clock::now();
    SpawnBody::Response res = insertBody(spawn);
    if (settings_.report_timing) {
      pacer_.recordSpawn(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return res;
  });
}

SpawnBody::Response SimNode::insertBody(SpawnQueue::Spawn& spawn) {
  SpawnBody::Response res;
  res.success = false;
  const SpawnBody::Request& req = spawn.request;
  const core::BodyModel& body = spawn.body.body();
  // A spawned body's frames and topics are under its name; none may be taken
  // (tf would see two parents of one frame).
  const std::string prefix = req.name + "/";
  std::vector<std::string> new_frames{prefix + body.link};
  for (const core::FixedLink& link : body.fixed_links) new_frames.push_back(prefix + link.name);
  if (spawn.ports->imu) new_frames.push_back(spawn.ports->imu_frame);  // not one of the body's (openPorts)
  if (ports_.directory().byName(req.name)) {
    res.message = "name '" + req.name + "' is taken by a body in the world";
    return res;
  }
  for (const std::string& frame : new_frames) {
    if (const auto owner = ports_.directory().ownerOf(frame)) {
      res.message = "name '" + req.name + "': the new body's frame '" + frame + "' is a frame of body '" +
                    model_.body(*owner).name + "'";
      return res;
    }
  }
  if (std::find(new_frames.begin(), new_frames.end(), settings_.world_frame) != new_frames.end()) {
    res.message =
        "name '" + req.name + "': the new body's frames include the world frame '" + settings_.world_frame + "'";
    return res;
  }
  const auto X_WF = address_.pose(req.frame, res.message);
  if (!X_WF) return res;
  core::LinkState link;
  link.p_WL = *X_WF * fromPoint(req.pose.position);
  link.q_WL = (X_WF->rotation * fromQuaternion(req.pose.orientation).normalized()).normalized();
  link.v_WL = X_WF->rotation * fromVector3(req.twist.linear);
  link.w_W = X_WF->rotation * fromVector3(req.twist.angular);
  res.message = firstProblem(
      {checkVector(link.p_WL, kMaxPosition, "pose.position (in the world)", "m"),
       checkSpeed(link.v_WL, model_.limits().max_linear_speed, "twist.linear", "limits.max_linear_speed", "m/s"),
       checkSpeed(link.w_W, model_.limits().max_angular_speed, "twist.angular", "limits.max_angular_speed", "rad/s")});
  if (!res.message.empty()) return res;
  // Everything that may refuse runs before the world changes (the ports,
  // opened on the spawn thread, refused an IMU on no such link).
  try {
    const core::BodyState start = core::bodyStateFromLink(body, link);
    sim_.addBody(spawn.body, start);  // in place, unchanged if it throws; reset puts it back here
    ports_.add(std::move(*spawn.ports), body, start, simTime());
  } catch (const std::exception& e) {
    res.message = e.what();
    return res;
  }
  afterSpawn();
  res.success = true;
  res.message = "body '" + req.name + "' added at t = " + now() + ": frame '" + ports_[ports_.size() - 1].frame +
                "', topics '" + nh_.resolveName(prefix + "odom") + "' and '" + pnh_.resolveName(prefix + "wrench") +
                "'";
  ROS_INFO("sim_node: %s", res.message.c_str());
  if (const std::string warning = io::touchesNothing(body); !warning.empty()) {
    ROS_WARN("sim_node: %s", warning.c_str());
    res.message += "; warning: " + warning;
  }
  return res;
}

}  // namespace rigid_body_sim::node
