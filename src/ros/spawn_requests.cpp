// ~spawn_body: read, checked and built on the spawn thread (a mesh body's
// distance grid takes up to seconds, which the loop must not wait for), its
// ports opened, then handed to the loop (SpawnQueue), which adds it between
// two steps (WorldEdits::insert). Deleting is in world_edits.cpp.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <sstream>

#include "request_checks.h"
#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/scene_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/io/world.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/joint_requests.h"
#include "rigid_body_sim/ros/params.h"
#include "rigid_body_sim/ros/robot_ports.h"
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
                       req.own_restitution ? checkCoefficient(req.restitution, 1.0, "restitution") : "",
                       checkNamespace(req.robot_namespace)});
}

/// The namespace of a robot's controllers' topics and joint_states, from its
/// markup's gazebo_ros_control `robotNamespace` (`markup`, "": none): a
/// robot_namespace given takes its place, as the previous choice here made
/// multi-robot launches work; spawn_model's own (robot_namespace_implied,
/// the script's when -robot_namespace is not given) fills it only where
/// the markup names none, as Gazebo's spawn adds robotNamespace only to a
/// plugin that has none.
std::string controlNamespace(const SpawnBody::Request& req, const std::string& markup) {
  if (req.robot_namespace.empty() || (req.robot_namespace_implied && !markup.empty())) return markup;
  return req.robot_namespace;
}

/// Where a robot's controllers and tf_prefix are looked up: its name, or,
/// given a robot_namespace, its controllers' namespace (`control_ns`).
std::string paramNamespace(const SpawnBody::Request& req, const std::string& control_ns) {
  return req.robot_namespace.empty() ? req.name : control_ns;
}

/// The URDF text of the request: exactly one of urdf_xml, urdf_param
/// (read from the parameter server) or urdf_file. Throws std::exception
/// with a message that starts with the field.
io::UrdfText readRequestedUrdf(const SpawnBody::Request& req, const ros::NodeHandle& nh, const std::string& base_dir) {
  const int given = !req.urdf_xml.empty() + !req.urdf_param.empty() + !req.urdf_file.empty();
  if (given != 1) {
    throw std::invalid_argument("urdf_xml, urdf_param, urdf_file: give exactly one (" + std::to_string(given) +
                                " given)");
  }
  // Each loader's message starts with the source it was given: the field.
  if (!req.urdf_xml.empty()) return {req.urdf_xml, "urdf_xml", ""};
  if (!req.urdf_param.empty()) {
    std::string xml, where;
    try {
      where = "urdf_param '" + nh.resolveName(req.urdf_param) + "'";
      if (!nh.getParam(req.urdf_param, xml)) throw std::invalid_argument(where + ": not set, or holds no string");
    } catch (const ros::InvalidNameException& e) {
      throw std::invalid_argument("urdf_param '" + io::shownName(req.urdf_param) + "': not a parameter name");
    }
    return {xml, where, ""};
  }
  const std::string& uri = req.urdf_file;
  if (uri.rfind("package://", 0) != 0 && uri.rfind("file://", 0) != 0 && uri.front() != '/') {
    throw std::invalid_argument("urdf_file '" + uri +
                                "' is a relative path, and the node's working folder is ROS's: give an "
                                "absolute path or package://PACKAGE/PATH");
  }
  try {
    return io::readUrdfFile(uri, base_dir);
  } catch (const std::exception& e) {
    throw std::invalid_argument("urdf_file: " + std::string(e.what()));
  }
}

/// An answer that added something says what its URDF's load repaired, as
/// the log does.
void tellRepairs(const std::vector<std::string>& notes, SpawnBody::Response& res) {
  for (const std::string& note : notes) {
    ROS_WARN("sim_node: ~spawn_body: %s", note.c_str());
    if (res.success) res.message += (res.message.empty() ? "" : "; ") + note;
  }
}

/// The controllers of robot `model` the request gives: its `controllers`
/// YAML, else those loaded under its robot_namespace or name (resolved on
/// `nh`), as a Gazebo user loads them for gazebo_ros_control; and the drives of its
/// URDF's markup. Throws std::exception starting with the field or the parameter.
io::RobotControls requestedControls(const SpawnBody::Request& req, const ros::NodeHandle& nh,
                                    const core::ArticulationModel& model,
                                    const std::vector<io::ControllerEntry>& markup, const std::string& ns) {
  try {
    if (!req.controllers.empty()) {
      return io::controlsOf(io::loadYamlText(req.controllers, "controllers"), "controllers", model, false, markup);
    }
    XmlRpc::XmlRpcValue params;
    if (!nh.getParam(ns, params) || params.getType() != XmlRpc::XmlRpcValue::TypeStruct) {
      return io::buildControls(markup, model);
    }
    return io::controlsOf(toYaml(params), nh.resolveName(ns), model, true, markup);
  } catch (const io::ConfigError& e) {
    if (!req.controllers.empty()) throw std::invalid_argument("controllers: " + std::string(e.what()));
    throw std::invalid_argument("controllers (the parameters under '" + nh.resolveName(ns) + "'): " + e.what());
  }
}

/// The robot a request's URDF describes, its joints set as joint_names says
/// (the base where the loop puts it), its controllers. Throws std::exception
/// naming the field.
void loadRequestedRobot(const SpawnBody::Request& req, const io::UrdfText& urdf, const io::UrdfOptions& options,
                        const core::SpeedLimits& limits, double dt, const ros::NodeHandle& nh, io::DeviceMemory memory,
                        SpawnQueue::Spawn& spawn) {
  io::RobotDevices config, markup;
  if (!req.imu.empty()) config.imus.push_back(io::parseImuText(req.imu, "imu", dt));
  if (!req.odom_noise.empty()) {
    config.odometry.push_back(
        io::OdometryEntry::ofOdomNoise(io::parseOdomNoiseText(req.odom_noise, "odom_noise"), "odom_noise"));
  }
  io::UrdfOptions with_sensors = options;
  with_sensors.sensors = &markup;
  core::ArticulationModel model = io::loadArticulationString(urdf.xml, urdf.source, urdf.base_dir, with_sensors);
  model.name = req.name;
  spawn.sensors = io::mountSensors(config, markup, model, dt, memory);
  if (model.fixed_base &&
      (fromVector3(req.twist.linear) != core::Vec3::Zero() || fromVector3(req.twist.angular) != core::Vec3::Zero())) {
    throw std::invalid_argument("twist: robot '" + req.name +
                                "' is fixed to the world (its root link is 'world'): it may be placed, not set moving");
  }
  spawn.robot_start = core::restState(model);
  const std::string problem =
      configureJoints(model, limits, req.joint_names, req.joint_positions, {}, spawn.robot_start);
  if (!problem.empty()) throw std::invalid_argument(problem);
  const std::string control_ns = controlNamespace(req, markup.robot_namespace);
  spawn.controls = requestedControls(req, nh, model, markup.controllers, paramNamespace(req, control_ns));
  spawn.controls.robot_namespace = control_ns;
  spawn.sensor_prefix = robotTopicPrefix(req.robot_namespace, req.name + "/");
  spawn.control_prefix = robotTopicPrefix(spawn.controls.robot_namespace, req.name + "/");
  if (!req.cmd_vel.empty() && model.fixed_base) {
    throw std::invalid_argument("cmd_vel: robot '" + req.name + "' is fixed to the world");
  }
  std::optional<core::DriverSettings> cmd_vel;
  if (!req.cmd_vel.empty()) cmd_vel = io::parseDriverText(req.cmd_vel, "cmd_vel");
  try {
    io::addBaseDrive(cmd_vel, markup.base_drive, model, "", spawn.controls);
  } catch (const io::ConfigError& e) {
    throw std::invalid_argument(req.cmd_vel.empty() ? e.what() : "cmd_vel: " + std::string(e.what()));
  }
  spawn.frame_prefix = framePrefix(nh, paramNamespace(req, control_ns));
  core::Scene::RobotSpec robot{req.name, std::move(model)};
  if (req.own_friction) robot.friction = req.friction;
  if (req.own_restitution) robot.restitution = req.restitution;
  spawn.robot = std::move(robot);
}

}  // namespace

bool SimNode::spawnBody(SpawnBody::Request& req, SpawnBody::Response& res) {
  // The spawn thread: nothing here reads the model, the state or the ports
  // (the loop changes them); builder_ holds copies of what it needs.
  res.success = false;
  res.message = checkSpawnRequest(req);
  if (!res.message.empty()) return true;
  SpawnQueue::Spawn spawn;
  std::vector<std::string> notes;
  const io::UrdfOptions options{params_.sim.urdf_repair, &notes};
  try {
    const io::UrdfText urdf = readRequestedUrdf(req, nh_, params_.sim.base_dir);
    if (io::describesRobot(urdf.xml, urdf.source)) {
      // Its devices counted on top of those built so far (a delete on the loop may lower that meanwhile).
      loadRequestedRobot(req, urdf, options, spawn_limits_, dt_, nh_,
                         io::DeviceMemory{params_.sim.device_memory, link_sensors_ ? link_sensors_->bytes() : 0},
                         spawn);
      spawn.topics = robotTopics(spawn.sensor_prefix, spawn.control_prefix, spawn.sensors, spawn.controls);
      notes.insert(notes.end(), spawn.controls.notes.begin(), spawn.controls.notes.end());
      notes.insert(notes.end(), spawn.sensors.notes.begin(), spawn.sensors.notes.end());
      spawn.request = req;
      res = spawns_.submit(std::move(spawn), [] { return ros::ok(); });  // the loop adds it at its next tick
      tellRepairs(notes, res);
      return true;
    }
    if (!req.joint_names.empty() || !req.joint_positions.empty()) {
      throw std::invalid_argument("joint_names: the URDF has no moving joints (a body, not a robot)");
    }
    if (!req.controllers.empty()) {
      throw std::invalid_argument("controllers: the URDF has no moving joints (a body, not a robot)");
    }
    if (!req.robot_namespace.empty()) {
      throw std::invalid_argument(
          "robot_namespace: the URDF has no moving joints (a body, not a robot): "
          "its topics are under its name");
    }
    core::BodySpec spec = io::loadUrdfString(urdf.xml, urdf.source, urdf.base_dir, options);
    spec.name = req.name;
    if (req.own_friction) core::setBodyFriction(spec, req.friction);
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
  tellRepairs(notes, res);
  return true;
}

}  // namespace rigid_body_sim::node
