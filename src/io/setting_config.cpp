// The model's settings in the config (setting_config.h).
#include "setting_config.h"

#include <set>
#include <string>

#include "rigid_body_sim/core/bodies/setting_keys.h"
#include "yaml_fields.h"

namespace rigid_body_sim::io {
namespace {

using namespace yaml_fields;

core::ContactMethod contactMethod(const YAML::Node& node) {
  const std::string m = node.IsScalar() ? node.as<std::string>() : show(node);
  if (m == "impulse") return core::ContactMethod::kImpulse;
  if (m == "penalty_quadratic") return core::ContactMethod::kPenaltyQuadratic;
  if (m == "penalty_log_barrier") return core::ContactMethod::kPenaltyLogBarrier;
  if (m == "shape_matching") return core::ContactMethod::kShapeMatching;
  fail("contact.method",
       "unknown method '" + m + "' (impulse, penalty_quadratic, penalty_log_barrier, shape_matching)");
}

core::ArticulationIntegrator articulationIntegrator(const YAML::Node& node) {
  const std::string m = node.IsScalar() ? node.as<std::string>() : show(node);
  if (m == "verlet") return core::ArticulationIntegrator::kVerlet;
  if (m == "symplectic_euler") return core::ArticulationIntegrator::kSymplecticEuler;
  fail("articulation_integrator", "unknown integrator '" + m + "' (verlet, symplectic_euler)");
}

core::CombineRule combineRule(const YAML::Node& node, const std::string& key) {
  const std::string r = node.IsScalar() ? node.as<std::string>() : show(node);
  if (r == "min") return core::CombineRule::kMin;
  if (r == "max") return core::CombineRule::kMax;
  if (r == "average") return core::CombineRule::kAverage;
  if (r == "multiply") return core::CombineRule::kMultiply;
  if (r == "geometric") return core::CombineRule::kGeometric;
  fail(key, "unknown rule '" + r + "' (min, max, average, multiply, geometric)");
}

/// One setting's value into its ModelSpec field (core/bodies/setting_keys.h). Its
/// range is checked once, by the model built from it; a count is checked
/// whole here, before it becomes an int.
void parseSetting(const core::SettingKey& k, const YAML::Node& node, core::ModelSpec& m) {
  const std::string key(k.key);
  switch (k.kind) {
    case core::SettingKey::Kind::kNumber:
      *k.number(m) = number(node, key);
      return;
    case core::SettingKey::Kind::kCount:
      *k.count(m) = integer(node, key);
      return;
    case core::SettingKey::Kind::kFlag:
      *k.flag(m) = boolean(node, key);
      return;
    case core::SettingKey::Kind::kVector:
      *k.vector(m) = vec3(node, key);
      return;
    case core::SettingKey::Kind::kChoice:
      if (key == "contact.method") m.contact.method = contactMethod(node);
      if (key == "articulation_integrator") m.articulation_integrator = articulationIntegrator(node);
      if (key == "contact.friction_combine") m.contact.friction_combine = combineRule(node, key);
      if (key == "contact.restitution_combine") m.contact.restitution_combine = combineRule(node, key);
      return;
  }
}

}  // namespace

void parseSection(const YAML::Node& root, const std::string& section, core::ModelSpec& m) {
  const YAML::Node node = section.empty() ? root : root[section];
  if (!node) return;
  if (!section.empty()) {
    std::set<std::string> known;
    for (const core::SettingKey& k : core::settingKeys()) {
      if (k.section() == section) known.emplace(k.name());
    }
    requireKnownKeys(node, section, known);
  }
  for (const core::SettingKey& k : core::settingKeys()) {
    if (k.section() != section) continue;
    const std::string name(k.name());
    if (node[name]) parseSetting(k, node[name], m);
  }
}

}  // namespace rigid_body_sim::io
