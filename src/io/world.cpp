#include "rigid_body_sim/io/world.h"

#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"

namespace rigid_body_sim::io {

core::Model buildModel(const SimConfig& config, const core::BodySpec& body) {
  core::ModelSpec spec = config.model;
  spec.bodies = {body};
  return core::Model(spec);
}

World buildWorld(const SimConfig& config, const BodyLoader& load) {
  core::ModelSpec spec = config.model;
  spec.bodies.clear();
  for (const BodyEntry& entry : config.bodies) {
    core::BodySpec body = load ? load(entry) : loadUrdfFile(resolveMeshUri(entry.urdf, config.base_dir));
    body.name = entry.name;
    spec.bodies.push_back(body);
  }
  World world{core::Model(spec), {}};
  for (std::size_t i = 0; i < config.bodies.size(); ++i) {
    world.state.bodies.push_back(core::bodyStateFromLink(world.model.body(i), config.bodies[i].initial));
  }
  return world;
}

World loadWorld(const SimConfig& config, const std::function<core::BodySpec()>& single_body, const BodyLoader& load) {
  if (!config.bodies.empty()) return buildWorld(config, load);
  if (!single_body) throw ConfigError("bodies: the config lists no bodies, and no single body was given");
  World world{buildModel(config, single_body()), {}};
  world.state.bodies = {core::bodyStateFromLink(world.model.body(0), config.initial)};
  return world;
}

}  // namespace rigid_body_sim::io
