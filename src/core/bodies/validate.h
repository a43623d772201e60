// Validation helpers shared by the core's constructors (private header).
// Every message names the field and the value: "<field> = <value>: <why>".
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rigid_body_sim/core/bodies/types.h"

namespace rigid_body_sim::core::detail {

inline std::string str(double x) {
  std::ostringstream os;
  os.precision(9);
  os << x;
  return os.str();
}

inline std::string str(const Vec3& v) { return "[" + str(v.x()) + ", " + str(v.y()) + ", " + str(v.z()) + "]"; }

/// Inertia in the six URDF terms, so a message reads like the file.
inline std::string str(const Mat3& I) {
  return "(ixx=" + str(I(0, 0)) + ", iyy=" + str(I(1, 1)) + ", izz=" + str(I(2, 2)) + ", ixy=" + str(I(0, 1)) +
         ", ixz=" + str(I(0, 2)) + ", iyz=" + str(I(1, 2)) + ")";
}

[[noreturn]] inline void fail(const std::string& field, const std::string& value, const std::string& why) {
  throw std::invalid_argument(field + " = " + value + ": " + why);
}

inline void requirePositive(double x, const std::string& field, const std::string& unit) {
  if (!std::isfinite(x) || !(x > 0.0)) fail(field, str(x), "must be finite and > 0 " + unit);
}

inline void requireNonNegative(double x, const std::string& field, const std::string& unit) {
  if (!std::isfinite(x) || x < 0.0) fail(field, str(x), "must be finite and >= 0 " + unit);
}

/// x within [lo, hi]: the range a setting makes physical sense in.
inline void requireWithin(double x, double lo, double hi, const std::string& field, const std::string& unit) {
  if (!std::isfinite(x) || x < lo || x > hi) {
    fail(field, str(x), "must be within [" + str(lo) + ", " + str(hi) + "]" + (unit.empty() ? "" : " " + unit));
  }
}

/// x within (0, hi].
inline void requirePositiveAtMost(double x, double hi, const std::string& field, const std::string& unit) {
  if (!std::isfinite(x) || !(x > 0.0) || x > hi) {
    fail(field, str(x), "must be > 0 and at most " + str(hi) + (unit.empty() ? "" : " " + unit));
  }
}

/// An integer count within [lo, hi].
inline void requireCount(int n, int lo, int hi, const std::string& field) {
  if (n < lo || n > hi) {
    fail(field, std::to_string(n), "must be within [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
}

inline void requireFinite(const Vec3& v, const std::string& field) {
  if (!v.allFinite()) fail(field, str(v), "must be finite");
}

}  // namespace rigid_body_sim::core::detail
