// A DiffDriveController's keys: drive_config.h.
#include "drive_config.h"

#include <set>
#include <utility>

#include "yaml_fields.h"

namespace rigid_body_sim::io {

using namespace yaml_fields;

namespace {

std::vector<std::string> jointNames(const YAML::Node& node, const std::string& key);

/// `left_wheel` or `right_wheel`: a joint name or a non-empty list of them.
std::vector<std::string> wheelNames(const YAML::Node& node, const std::string& key) {
  if (!node) fail(key, "is missing: a DiffDriveController needs left_wheel and right_wheel (a joint or a list)");
  return jointNames(node, key);
}

/// A joint name or a non-empty list of them.
std::vector<std::string> jointNames(const YAML::Node& node, const std::string& key) {
  if (node.IsScalar()) return {text(node, key)};
  if (!node.IsSequence() || node.size() == 0) fail(key, "expected a joint name or a non-empty list of them");
  std::vector<std::string> names;
  for (std::size_t k = 0; k < node.size(); ++k) names.push_back(text(node[k], key + "[" + std::to_string(k) + "]"));
  return names;
}

/// `linear: {x: {...}}` or `angular: {z: {...}}`: ros_controllers' limiter
/// keys for `axis`, the map's keys `axes` (default: `axis` alone).
core::TwistLimiter parseLimits(const YAML::Node& node, const std::string& path, const char* axis,
                               const std::set<std::string>& axes = {}) {
  core::TwistLimiter l;
  if (!node) return l;
  if (!node.IsMap()) fail(path, std::string("expected {") + axis + ": {has_velocity_limits, max_velocity, ...}}");
  requireKnownKeys(node, path, axes.empty() ? std::set<std::string>{axis} : axes);
  const YAML::Node& a = node[axis];
  const std::string at = join(path, axis);
  if (!a) return l;
  if (!a.IsMap()) fail(at, "expected a map {has_velocity_limits, max_velocity, min_velocity, ...}");
  requireKnownKeys(a, at,
                   {"has_velocity_limits", "max_velocity", "min_velocity", "has_acceleration_limits",
                    "max_acceleration", "min_acceleration", "has_jerk_limits", "max_jerk", "min_jerk"});
  struct Bound {
    const char* what;
    bool* has;
    double *lo, *hi;
  };
  for (const Bound& b : {Bound{"velocity", &l.has_velocity_limits, &l.min_velocity, &l.max_velocity},
                         Bound{"acceleration", &l.has_acceleration_limits, &l.min_acceleration, &l.max_acceleration},
                         Bound{"jerk", &l.has_jerk_limits, &l.min_jerk, &l.max_jerk}}) {
    const std::string has = std::string("has_") + b.what + "_limits", max = std::string("max_") + b.what,
                      min = std::string("min_") + b.what;
    if (a[has]) *b.has = boolean(a[has], join(at, has));
    if (a[max]) *b.hi = number(a[max], join(at, max));
    *b.lo = a[min] ? number(a[min], join(at, min)) : -*b.hi;  // ros_controllers: min defaults to -max
    if (*b.has && !a[max]) {
      fail(join(at, max), "is missing: " + has + " is true (ros_controllers would hold the " + b.what + " to 0)");
    }
    if (*b.has && *b.lo > *b.hi) fail(join(at, min), "must be <= " + max);
    // A pair not holding 0 turns a zero command into a drive: the base would move with no cmd_vel.
    if (*b.has && *b.hi < 0.0) fail(join(at, max), "must be >= 0: a zero command would drive the base");
    if (*b.has && *b.lo > 0.0) fail(join(at, min), "must be <= 0: a zero command would drive the base");
  }
  return l;
}

std::array<double, 6> covariance(const YAML::Node& node, const std::string& key) {
  if (!node.IsSequence() || node.size() != 6) fail(key, "expected 6 numbers (x, y, z, rotation about x, y, z)");
  std::array<double, 6> out{};
  for (std::size_t k = 0; k < 6; ++k) {
    out[k] = number(node[k], key + "[" + std::to_string(k) + "]");
    if (out[k] < 0.0) fail(key + "[" + std::to_string(k) + "]", "a variance must be >= 0");
  }
  return out;
}

/// A controller's frame id: one leading '/' dropped, as tf2's buffer drops
/// it from every transform it receives (a ROS 1 controller publishes it as
/// given; AgileX Hunter's odom_frame_id has one), then checked as a frame id.
std::string controllerFrame(const YAML::Node& node, const std::string& key) {
  std::string frame = text(node, key);
  if (frame.size() > 1 && frame.front() == '/') frame.erase(0, 1);
  if (const std::string problem = frameIdProblem(frame); !problem.empty()) fail(key, problem);
  return frame;
}

}  // namespace

namespace {

/// The keys every wheeled base's controller reads (readDriveSettings's), and its type.
std::set<std::string> sharedKeys() {
  return {"type",
          "wheel_radius",
          "wheel_separation_multiplier",
          "wheel_radius_multiplier",
          "publish_rate",
          "pose_covariance_diagonal",
          "twist_covariance_diagonal",
          "cmd_vel_timeout",
          "base_frame_id",
          "odom_frame_id",
          "enable_odom_tf",
          "open_loop",
          "velocity_rolling_window_size",
          "allow_multiple_cmd_vel_publishers",
          "publish_cmd",
          "linear",
          "angular"};
}

/// What every wheeled base's controller reads alike, into `d`: the wheel
/// radius, the multipliers, the timeout, the odometry's window and loop,
/// the limits (`linear/y` too, for a mecanum base), the topics and frames.
void readDriveSettings(const YAML::Node& body, const std::string& key, DiffDriveEntry& d) {
  if (body["wheel_radius"]) d.wheel_radius = positiveNumber(body["wheel_radius"], join(key, "wheel_radius"));
  core::DiffDriveSettings& s = d.settings;
  const auto positive = [&](const char* k, double& field) {
    if (body[k]) field = positiveNumber(body[k], join(key, k));
  };
  positive("wheel_separation_multiplier", s.wheel_separation_multiplier);
  // ros_controllers: wheel_radius_multiplier, when given, is both sides'.
  if (body["wheel_radius_multiplier"]) {
    for (const char* side : {"left_wheel_radius_multiplier", "right_wheel_radius_multiplier"}) {
      if (body[side]) fail(join(key, side), "give wheel_radius_multiplier (both sides) or the sides', not both");
    }
    s.left_wheel_radius_multiplier = s.right_wheel_radius_multiplier =
        positiveNumber(body["wheel_radius_multiplier"], join(key, "wheel_radius_multiplier"));
  }
  positive("left_wheel_radius_multiplier", s.left_wheel_radius_multiplier);
  positive("right_wheel_radius_multiplier", s.right_wheel_radius_multiplier);
  if (body["cmd_vel_timeout"]) {
    s.cmd_vel_timeout = number(body["cmd_vel_timeout"], join(key, "cmd_vel_timeout"));
    if (s.cmd_vel_timeout < 0.0) fail(join(key, "cmd_vel_timeout"), "must be >= 0 s");
  }
  if (body["velocity_rolling_window_size"]) {
    const std::string k = join(key, "velocity_rolling_window_size");
    s.velocity_rolling_window_size = integer(body["velocity_rolling_window_size"], k);
    if (s.velocity_rolling_window_size < 1 || s.velocity_rolling_window_size > 100000) {
      fail(k, "must be within [1, 100000] steps");
    }
  }
  if (body["open_loop"]) s.open_loop = boolean(body["open_loop"], join(key, "open_loop"));
  // A mecanum base's linear/y beside linear/x (ros_controllers' limiter keys for each).
  const std::set<std::string> linear_axes = d.mecanum ? std::set<std::string>{"x", "y"} : std::set<std::string>{};
  s.linear = parseLimits(body["linear"], join(key, "linear"), "x", linear_axes);
  if (d.mecanum) s.lateral = parseLimits(body["linear"], join(key, "linear"), "y", linear_axes);
  s.angular = parseLimits(body["angular"], join(key, "angular"), "z");
  DriveTopics& t = d.topics;
  if (body["publish_rate"]) t.publish_rate = publishRate(body["publish_rate"], join(key, "publish_rate"));
  if (body["pose_covariance_diagonal"]) {
    t.pose_covariance_diagonal = covariance(body["pose_covariance_diagonal"], join(key, "pose_covariance_diagonal"));
  }
  if (body["twist_covariance_diagonal"]) {
    t.twist_covariance_diagonal = covariance(body["twist_covariance_diagonal"], join(key, "twist_covariance_diagonal"));
  }
  if (body["base_frame_id"]) t.base_frame_id = controllerFrame(body["base_frame_id"], join(key, "base_frame_id"));
  if (body["odom_frame_id"]) t.odom_frame_id = controllerFrame(body["odom_frame_id"], join(key, "odom_frame_id"));
  if (t.base_frame_id == t.odom_frame_id) fail(join(key, "odom_frame_id"), "is base_frame_id: tf needs two frames");
  for (const auto& [k, field] : {std::pair<const char*, bool*>{"enable_odom_tf", &t.enable_odom_tf},
                                 {"publish_cmd", &t.publish_cmd},
                                 {"allow_multiple_cmd_vel_publishers", &t.allow_multiple_cmd_vel_publishers}}) {
    if (body[k]) *field = boolean(body[k], join(key, k));
  }
}

}  // namespace

DiffDriveEntry parseDiffDrive(const YAML::Node& body, const std::string& key) {
  DiffDriveEntry d;
  for (const char* k : {"publish_wheel_joint_controller_state", "publish_joint_trajectory_controller_state"}) {
    if (body[k] && boolean(body[k], join(key, k))) {
      d.unread.push_back({join(key, k), "its message is control_msgs', which Debian 12 does not have"});
    }
  }
  std::set<std::string> known = sharedKeys();
  known.insert({"left_wheel", "right_wheel", "wheel_separation", "left_wheel_radius_multiplier",
                "right_wheel_radius_multiplier", "publish_wheel_joint_controller_state",
                "publish_joint_trajectory_controller_state"});
  const std::vector<std::string> others = keysNotRead(body, key, known);
  for (const std::string& k : others)
    d.unread.push_back({k, "diff_drive_controller/DiffDriveController reads no such key"});
  d.left = wheelNames(body["left_wheel"], join(key, "left_wheel"));
  d.right = wheelNames(body["right_wheel"], join(key, "right_wheel"));
  if (d.left.size() != d.right.size()) {
    fail(join(key, "right_wheel"), std::to_string(d.right.size()) + " wheels against left_wheel's " +
                                       std::to_string(d.left.size()) + ": give as many on each side");
  }
  if (body["wheel_separation"])
    d.wheel_separation = positiveNumber(body["wheel_separation"], join(key, "wheel_separation"));
  readDriveSettings(body, key, d);
  return d;
}

DiffDriveEntry parseMecanumDrive(const YAML::Node& body, const std::string& key) {
  DiffDriveEntry d;
  d.mecanum = true;
  std::set<std::string> known = sharedKeys();
  known.insert({"front_left_wheel_joint", "back_left_wheel_joint", "front_right_wheel_joint", "back_right_wheel_joint",
                "wheel_separation_x", "wheel_separation_y"});
  const std::vector<std::string> others = keysNotRead(body, key, known);
  for (const std::string& k : others) d.unread.push_back({k, std::string(kMecanumType) + " reads no such key"});
  const auto wheel = [&](const char* k) {
    if (!body[k]) fail(join(key, k), "is missing: a MecanumDriveController needs its four wheels' joints");
    return text(body[k], join(key, k));
  };
  d.left = {wheel("front_left_wheel_joint"), wheel("back_left_wheel_joint")};
  d.right = {wheel("front_right_wheel_joint"), wheel("back_right_wheel_joint")};
  if (body["wheel_separation_x"] || body["wheel_separation_y"]) {
    for (const char* k : {"wheel_separation_x", "wheel_separation_y"}) {
      if (!body[k]) fail(join(key, k), "is missing: give wheel_separation_x and wheel_separation_y, or neither");
    }
    d.wheel_separation = positiveNumber(body["wheel_separation_x"], join(key, "wheel_separation_x")) +
                         positiveNumber(body["wheel_separation_y"], join(key, "wheel_separation_y"));
  }
  readDriveSettings(body, key, d);
  return d;
}

DiffDriveEntry parseAckermannDrive(const YAML::Node& body, const std::string& key) {
  DiffDriveEntry d;
  std::set<std::string> known = sharedKeys();
  known.erase("wheel_separation_multiplier");
  known.insert(
      {"rear_wheel", "front_steer", "wheel_separation_h", "wheel_separation_h_multiplier", "steer_pos_multiplier"});
  for (const std::string& k : keysNotRead(body, key, known)) {
    d.unread.push_back({k, std::string(kAckermannType) + " reads no such key"});
  }
  d.left = body["rear_wheel"] ? jointNames(body["rear_wheel"], join(key, "rear_wheel"))
                              : std::vector<std::string>{"rear_wheel_joint"};
  d.steers = body["front_steer"] ? jointNames(body["front_steer"], join(key, "front_steer"))
                                 : std::vector<std::string>{"front_steer_joint"};
  if (body["wheel_separation_h"]) {
    d.wheel_separation = positiveNumber(body["wheel_separation_h"], join(key, "wheel_separation_h"));
  }
  if (body["wheel_separation_h_multiplier"]) {
    d.settings.wheel_separation_multiplier =
        positiveNumber(body["wheel_separation_h_multiplier"], join(key, "wheel_separation_h_multiplier"));
  }
  if (body["steer_pos_multiplier"] && number(body["steer_pos_multiplier"], join(key, "steer_pos_multiplier")) != 1.0) {
    d.unread.push_back(
        {join(key, "steer_pos_multiplier"), "the odometry reads the steering joints' angles as they are"});
  }
  readDriveSettings(body, key, d);
  return d;
}

}  // namespace rigid_body_sim::io
