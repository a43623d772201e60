// The model's settings by name (setting_keys.h).
#include "rigid_body_sim/core/bodies/setting_keys.h"

#include <cmath>
#include <limits>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "validate.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using Kind = SettingKey::Kind;

SettingKey number(std::string_view key, std::string_view unit, double min, double max, double* (*field)(ModelSpec&),
                  bool min_open = false) {
  SettingKey k;
  k.key = key;
  k.unit = unit;
  k.kind = Kind::kNumber;
  k.min = min;
  k.max = max;
  k.min_open = min_open;
  k.number = field;
  return k;
}

SettingKey count(std::string_view key, double min, double max, int* (*field)(ModelSpec&)) {
  SettingKey k;
  k.key = key;
  k.kind = Kind::kCount;
  k.min = min;
  k.max = max;
  k.count = field;
  return k;
}

SettingKey flag(std::string_view key, bool* (*field)(ModelSpec&)) {
  SettingKey k;
  k.key = key;
  k.kind = Kind::kFlag;
  k.flag = field;
  return k;
}

SettingKey choice(std::string_view key, std::string_view choices) {
  SettingKey k;
  k.key = key;
  k.kind = Kind::kChoice;
  k.choices = choices;
  return k;
}

std::vector<SettingKey> makeKeys() {
  using ranges::kMaxBuffer;
  using ranges::kMaxThresholdSpeed;
  SettingKey gravity;
  gravity.key = "gravity";
  gravity.unit = "m/s^2";
  gravity.kind = Kind::kVector;
  gravity.max = ranges::kMaxGravity;
  gravity.vector = [](ModelSpec& m) { return &m.gravity_W; };
  // clang-format off
  return {
      number("dt", "s", ranges::kMinDt, ranges::kMaxDt, [](ModelSpec& m) { return &m.dt; }),
      gravity,
      flag("gyroscopic", [](ModelSpec& m) { return &m.gyroscopic; }),
      choice("articulation_integrator", "verlet | symplectic_euler"),
      number("damping.linear", "1/s", 0, ranges::kMaxDecayRate, [](ModelSpec& m) { return &m.damping.linear; }),
      number("damping.angular", "1/s", 0, ranges::kMaxDecayRate, [](ModelSpec& m) { return &m.damping.angular; }),
      number("damping.linear_drag", "N*s/m", 0, kInf, [](ModelSpec& m) { return &m.damping.linear_drag; }),
      number("damping.angular_drag", "N*m*s/rad", 0, kInf, [](ModelSpec& m) { return &m.damping.angular_drag; }),
      choice("contact.method", "impulse | penalty_quadratic | penalty_log_barrier | shape_matching"),
      number("contact.restitution", "", 0, 1, [](ModelSpec& m) { return &m.contact.restitution; }),
      number("contact.friction", "", 0, ranges::kMaxFriction, [](ModelSpec& m) { return &m.contact.friction; }),
      choice("contact.friction_combine", "min | max | average | multiply | geometric"),
      choice("contact.restitution_combine", "min | max | average | multiply | geometric"),
      number("contact.restitution_threshold", "m/s", 0, kMaxThresholdSpeed,
             [](ModelSpec& m) { return &m.contact.restitution_threshold; }),
      number("contact.sample_spacing", "m", ranges::kMinSampleSpacing, ranges::kMaxExtent,
             [](ModelSpec& m) { return &m.contact.sample_spacing; }),
      count("contact.iterations", 1, ranges::kMaxIterations, [](ModelSpec& m) { return &m.contact.iterations; }),
      number("contact.position_slop", "m", 0, kMaxBuffer, [](ModelSpec& m) { return &m.contact.position_slop; }),
      number("contact.penalty_stiffness", "N/m", 0, kInf, [](ModelSpec& m) { return &m.contact.penalty_stiffness; },
             true),
      number("contact.penalty_damping", "N*s/m", 0, kInf, [](ModelSpec& m) { return &m.contact.penalty_damping; }),
      number("contact.penalty_buffer", "m", 0, kMaxBuffer, [](ModelSpec& m) { return &m.contact.penalty_buffer; },
             true),
      number("contact.barrier_strength", "N*m", 0, ranges::kMaxBarrierStrength,
             [](ModelSpec& m) { return &m.contact.barrier_strength; }, true),
      number("contact.barrier_buffer", "m", 0, kMaxBuffer, [](ModelSpec& m) { return &m.contact.barrier_buffer; },
             true),
      flag("contact.self_collision", [](ModelSpec& m) { return &m.contact.self_collision; }),
      flag("sleep.enabled", [](ModelSpec& m) { return &m.sleep.enabled; }),
      number("sleep.linear_velocity", "m/s", 0, kMaxThresholdSpeed,
             [](ModelSpec& m) { return &m.sleep.linear_velocity; }),
      number("sleep.angular_velocity", "rad/s", 0, kMaxThresholdSpeed,
             [](ModelSpec& m) { return &m.sleep.angular_velocity; }),
      number("sleep.time", "s", 0, ranges::kMaxDuration, [](ModelSpec& m) { return &m.sleep.time; }),
      number("solver.velocity_tolerance", "m/s", 0, kInf,
             [](ModelSpec& m) { return &m.solver.velocity_tolerance; }, true),
      number("solver.relative_tolerance", "", 0, kInf, [](ModelSpec& m) { return &m.solver.relative_tolerance; }),
      number("solver.resting_speed", "m/s", 0, kInf, [](ModelSpec& m) { return &m.solver.resting_speed; }),
      count("solver.position_iterations", 0, ranges::kMaxIterations,
            [](ModelSpec& m) { return &m.solver.position_iterations; }),
      count("solver.mesh_grid_resolution", 2, ranges::kMaxGridResolution,
            [](ModelSpec& m) { return &m.solver.mesh_grid_resolution; }),
      number("limits.max_linear_speed", "m/s", 0, ranges::kMaxSpeedLimit,
             [](ModelSpec& m) { return &m.limits.max_linear_speed; }, true),
      number("limits.max_angular_speed", "rad/s", 0, ranges::kMaxSpeedLimit,
             [](ModelSpec& m) { return &m.limits.max_angular_speed; }, true),
  };
  // clang-format on
}

}  // namespace

std::string_view SettingKey::section() const {
  const std::size_t dot = key.find('.');
  return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
}

std::string_view SettingKey::name() const {
  const std::size_t dot = key.find('.');
  return dot == std::string_view::npos ? key : key.substr(dot + 1);
}

std::string SettingKey::reconfigureName() const {
  std::string n(key);
  for (char& c : n) {
    if (c == '.') c = '_';
  }
  return n;
}

std::string SettingKey::range() const {
  if (kind == Kind::kVector) return "of length at most " + detail::str(max);
  if (kind == Kind::kCount) return "a whole number within [" + detail::str(min) + ", " + detail::str(max) + "]";
  if (std::isinf(max)) return "finite and " + std::string(min_open ? "> " : ">= ") + detail::str(min);
  if (min_open) return "> " + detail::str(min) + " and at most " + detail::str(max);
  return "within [" + detail::str(min) + ", " + detail::str(max) + "]";
}

const std::vector<SettingKey>& settingKeys() {
  static const std::vector<SettingKey> keys = makeKeys();
  return keys;
}

const SettingKey* findSettingKey(std::string_view key) {
  for (const SettingKey& k : settingKeys()) {
    if (k.key == key) return &k;
  }
  return nullptr;
}

void checkSetting(const SettingKey& key, double value) {
  const bool below = key.min_open ? !(value > key.min) : !(value >= key.min);
  if (!std::isfinite(value) || below || value > key.max) {
    detail::fail(std::string(key.key), detail::str(value),
                 "must be " + key.range() + (key.unit.empty() ? "" : " " + std::string(key.unit)));
  }
}

void checkSetting(const SettingKey& key, const Vec3& value) {
  if (!value.allFinite()) detail::fail(std::string(key.key), detail::str(value), "must be finite");
  if (value.norm() > key.max) {
    detail::fail(std::string(key.key), detail::str(value),
                 "its length " + detail::str(value.norm()) + " must be at most " + detail::str(key.max) + " " +
                     std::string(key.unit));
  }
}

void checkSettings(const ModelSpec& spec) {
  auto& m = const_cast<ModelSpec&>(spec);  // the fields are only read
  for (const SettingKey& k : settingKeys()) {
    if (k.number) checkSetting(k, *k.number(m));
    if (k.count) checkSetting(k, static_cast<double>(*k.count(m)));
    if (k.vector) checkSetting(k, *k.vector(m));
  }
}

}  // namespace rigid_body_sim::core
