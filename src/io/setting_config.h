// The config's model settings, by core::settingKeys() (private to io):
// numbers, counts, flags, vectors and the choices (contact.method, the
// combine rules, articulation_integrator), each refused naming its key.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "rigid_body_sim/core/bodies/model.h"

namespace rigid_body_sim::io {

/// The model settings of one section of the root (`damping`, `contact`,
/// ...), or with "" those at the top level: every key the section may have
/// is in core::settingKeys(), and no other is accepted.
void parseSection(const YAML::Node& root, const std::string& section, core::ModelSpec& m);

}  // namespace rigid_body_sim::io
