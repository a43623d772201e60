// The config's `scene`: static shapes, compositions and meshes (private to io).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/sdf.h"

namespace rigid_body_sim::io {

/// The shapes of a `scene` list; mesh files resolve from `base_dir` (the config's folder).
std::vector<core::Sdf> parseScene(const YAML::Node& node, const std::string& base_dir);

}  // namespace rigid_body_sim::io
