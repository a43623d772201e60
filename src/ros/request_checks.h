// What a request may ask for, and the checks every handler runs first (a
// refused request changes nothing). Private to the node.
#pragma once

#include <ros/names.h>
#include <ros/time.h>

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>

#include "rigid_body_sim/core/bodies/types.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/ros/sim_clock.h"

namespace rigid_body_sim::node {

using core::Vec3;

// What a request may ask for at most: beyond these it is refused as absurd.
inline constexpr double kMaxForce = 1e6;     // N
inline constexpr double kMaxTorque = 1e6;    // N·m
inline constexpr double kMaxImpulse = 1e5;   // N·s and N·m·s
inline constexpr double kMaxPosition = 1e6;  // m, also for points of application
inline constexpr int kMaxSteps = 1000000;    // per ~step call
inline constexpr double kMaxLeadTime = 1e6;  // s, how far ahead a start_time may be
/// s: a warning about a command or message (a flood of bad ones) is logged at
/// most this often, per place that logs it (ROS_WARN_THROTTLE, on the node's clock).
inline constexpr double kWarnPeriod = 1.0;

/// "" if v is finite and |v| ≤ limit, else why not.
inline std::string checkVector(const Vec3& v, double limit, const std::string& what, const std::string& unit) {
  std::ostringstream os;
  if (!v.allFinite()) {
    os << what << " is not finite: [" << v.x() << ", " << v.y() << ", " << v.z() << "]";
  } else if (v.norm() > limit) {
    os << what << " is absurd: |" << what << "| = " << v.norm() << " " << unit << " > " << limit << " " << unit;
  }
  return os.str();
}

/// "" if v is finite and |v| ≤ the model's speed limit `limit` (config key
/// `key`), else why not: a state the step would only scale back.
inline std::string checkSpeed(const Vec3& v, double limit, const std::string& what, const std::string& key,
                              const std::string& unit) {
  if (!v.allFinite()) return checkVector(v, limit, what, unit);
  if (!(v.norm() <= limit)) {
    std::ostringstream os;
    os << what << " is above the speed limit: |" << what << "| = " << v.norm() << " " << unit << " > " << key << " = "
       << limit << " " << unit;
    return os.str();
  }
  return {};
}

/// "" if `name` may name a body, else why not: the config's rule.
inline std::string checkName(const std::string& name) { return io::bodyNameProblem(name); }

/// "" if `ns` (a spawn's robot_namespace) is "" or a ROS namespace, global or
/// relative to the node's (never private), else why not.
inline std::string checkNamespace(const std::string& ns) {
  std::string why;
  if (ns.empty() || ns == "/") return {};
  if (ns.size() <= 256 && ns.front() != '~' && ros::names::validate(ns, why)) return {};
  return "robot_namespace '" + io::shownName(ns) +
         "': no ROS namespace (letters, digits, '_' and '/', starting with a letter or '/'; '/' is the root)";
}

/// "" if `value` (request field `field`) is within [0, max], else why not.
inline std::string checkCoefficient(double value, double max, const std::string& field) {
  if (value >= 0.0 && value <= max) return {};
  std::ostringstream os;
  os << field << " = " << value << ": must be within [0, " << max << "]";
  return os.str();
}

/// The first non-empty complaint, or "".
inline std::string firstProblem(std::initializer_list<std::string> problems) {
  for (const std::string& p : problems) {
    if (!p.empty()) return p;
  }
  return {};
}

/// When a request's `start_time` starts, in sim time: it is on the node's
/// clock (the stamps of /odom, tf and joint_states); 0 or the past means
/// now, the next step. Far ahead is another clock's reading: refused
/// (nullopt, `error` says why). `when` says which, for the answer.
inline std::optional<double> startOf(const ros::Time& start_time, const NodeTime& time, std::string& when,
                                     std::string& error) {
  when = "from now (t = " + time.text() + ")";
  if (start_time.isZero()) return time.simTime();
  const int64_t asked = static_cast<int64_t>(start_time.toNSec());
  const double at = time.clock.simTimeAt(asked), lead = at - time.simTime();
  if (lead > kMaxLeadTime) {
    error = "start_time " + formatStamp(asked) + " s is " + std::to_string(lead) +
            " s ahead of this node's clock (now " + time.text() +
            "): is it on another clock? Stamps of odom and tf are on this one; 0 means now";
    return std::nullopt;
  }
  if (lead > 0.0) {
    when = "from t = " + formatStamp(asked) + " s";
    return at;
  }
  if (lead < 0.0) when = "from now (start_time " + formatStamp(asked) + " s is past; t = " + time.text() + ")";
  return time.simTime();
}

}  // namespace rigid_body_sim::node
