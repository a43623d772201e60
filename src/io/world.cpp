#include "rigid_body_sim/io/world.h"

#include <map>
#include <sstream>

#include "rigid_body_sim/core/step/diagnostics.h"
#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"

namespace rigid_body_sim::io {
namespace {

/// Farthest from the origin a body may start (m): far beyond any scene, and
/// where a double still resolves a micrometre.
constexpr double kMaxStartDistance = 1e6;

/// A start state within the model's speed limits and reach: the body at
/// `key` (initial, or bodies[i].initial) as a ConfigError names it.
core::BodyState startState(const core::Model& model, std::size_t i, const core::LinkState& link,
                           const std::string& key) {
  checkStart(link, model.limits(), key);
  return core::bodyStateFromLink(model.body(i), link);
}

/// Joint values for a world of bodies: none has a moving joint.
[[noreturn]] void refuseJoints(const std::string& key) {
  throw ConfigError("config key '" + key +
                    ".joint_positions' / '.joint_velocities': a body has no moving joints (joint values are "
                    "for a robot: a URDF with moving joints)");
}

}  // namespace

core::Model buildModel(const SimConfig& config, const core::BodySpec& body) {
  core::ModelSpec spec = config.model;
  spec.bodies = {body};
  return core::Model(spec);
}

World buildWorld(const SimConfig& config, const BodyLoader& load) {
  core::ModelSpec spec = config.model;
  spec.bodies.clear();
  spec.bodies.reserve(config.bodies.size());
  // Each file is read and parsed once: a world of 10,000 boxes names one URDF 10,000 times.
  std::map<std::string, core::BodySpec> files;
  std::vector<std::string> notes;
  for (std::size_t i = 0; i < config.bodies.size(); ++i) {
    if (!config.bodies[i].initial_joints.empty()) refuseJoints("bodies[" + std::to_string(i) + "].initial");
  }
  for (const BodyEntry& entry : config.bodies) {
    core::BodySpec body;
    if (load) {
      body = load(entry);
    } else {
      auto file = files.find(entry.urdf);
      if (file == files.end()) {
        file = files
                   .emplace(entry.urdf, loadUrdfFile(resolveMeshUri(entry.urdf, config.base_dir),
                                                     UrdfOptions{config.urdf_repair, &notes}))
                   .first;
      }
      body = file->second;
    }
    body.name = entry.name;
    if (entry.friction) core::setBodyFriction(body, *entry.friction);  // else its URDF's <mu1>, or the scene's
    body.restitution = entry.restitution;
    spec.bodies.push_back(body);
  }
  World world{core::Model(spec), {}, std::move(notes)};
  world.state.bodies.reserve(config.bodies.size());
  for (std::size_t i = 0; i < config.bodies.size(); ++i) {
    world.state.bodies.push_back(
        startState(world.model, i, config.bodies[i].initial, "bodies[" + std::to_string(i) + "].initial"));
  }
  for (std::size_t i = 0; i < config.bodies.size(); ++i) {
    const std::string note = insideSceneNote(world.model, world.state, i, 1, "body '" + world.model.body(i).name + "'");
    if (!note.empty()) world.notes.push_back(note);
  }
  return world;
}

World loadWorld(const SimConfig& config, const std::function<core::BodySpec()>& single_body, const BodyLoader& load) {
  if (config.bodies_listed) return buildWorld(config, load);
  if (!single_body) throw ConfigError("bodies: the config lists no bodies, and no single body was given");
  if (!config.initial_joints.empty()) refuseJoints("initial");
  World world{buildModel(config, single_body()), {}, {}};
  world.state.bodies = {startState(world.model, 0, config.initial, "initial")};
  const std::string note = insideSceneNote(world.model, world.state, 0, 1, "body '" + world.model.body(0).name + "'");
  if (!note.empty()) world.notes.push_back(note);
  return world;
}

void checkStart(const core::LinkState& link, const core::SpeedLimits& limits, const std::string& key) {
  const auto refuse = [&key](const std::string& field, double value, const std::string& unit, const std::string& above,
                             double limit) {
    std::ostringstream os;
    os << "config key '" << key << "." << field << "': magnitude " << value << " " << unit << " is above " << above
       << " = " << limit << " " << unit;
    throw ConfigError(os.str());
  };
  // stableNorm: |x|² of a finite 1e300 overflows.
  if (link.p_WL.stableNorm() > kMaxStartDistance) {
    refuse("position", link.p_WL.stableNorm(), "m", "the farthest a body may start", kMaxStartDistance);
  }
  if (link.v_WL.stableNorm() > limits.max_linear_speed) {
    refuse("linear_velocity", link.v_WL.stableNorm(), "m/s", "limits.max_linear_speed", limits.max_linear_speed);
  }
  if (link.w_W.stableNorm() > limits.max_angular_speed) {
    refuse("angular_velocity", link.w_W.stableNorm(), "rad/s", "limits.max_angular_speed", limits.max_angular_speed);
  }
}

std::string insideSceneNote(const core::Model& model, const core::State& state, std::size_t first, std::size_t count,
                            const std::string& who) {
  constexpr double kWarnDepth = 1e-3;  // m: a start touching the ground to rounding is no news
  double deepest = 0.0;
  std::size_t at = first;
  for (std::size_t i = first; i < first + count; ++i) {
    const double depth = core::sceneDepth(model, i, state.bodies[i]);
    if (depth > deepest) {
      deepest = depth;
      at = i;
    }
  }
  if (!(deepest > kWarnDepth)) return "";
  std::ostringstream os;
  os.precision(3);
  os << who << " starts " << 1e3 * deepest << " mm inside the scene";
  if (count > 1) os << " (its link '" << model.body(at).name << "')";
  os << ": contacts push it out in the first steps, adding energy; start it clear of the scene";
  return os.str();
}

std::string touchesNothing(const core::BodyModel& body) {
  if (!body.contact_points.empty()) return "";
  return "body '" + body.name +
         "' has no <collision> geometry: it touches nothing (no ground, no body), as in Gazebo; add a "
         "<collision> to its URDF for contacts";
}

}  // namespace rigid_body_sim::io
