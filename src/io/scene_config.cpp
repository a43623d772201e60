// The config's `scene` (scene_config.h): primitives, compositions, meshes.
#include "scene_config.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/core/bodies/sdf_grid.h"
#include "rigid_body_sim/core/bodies/settings.h"
#include "rigid_body_sim/io/mesh_loader.h"
#include "yaml_fields.h"

namespace rigid_body_sim::io {
namespace {

using core::Vec3;
using namespace yaml_fields;

/// One scene entry: a primitive or a composition, with an optional pose.
/// A `mesh` item: the file's solid as a sampled signed distance (the grid
/// mesh bodies use), `resolution` cells along its longest side, fewer if the
/// grid's cost bound needs it.
core::Sdf meshShape(const YAML::Node& node, const std::string& path, const std::string& base_dir) {
  if (!node["file"])
    fail(join(path, "file"), "a mesh needs file: PATH (STL, OBJ or DAE; relative to the config, or package://)");
  Vec3 scale = Vec3::Ones();
  if (const YAML::Node s = node["scale"]) {
    scale = s.IsSequence() ? vec3(s, join(path, "scale")) : Vec3::Constant(positiveNumber(s, join(path, "scale")));
    if (!(scale.minCoeff() > 0.0)) fail(join(path, "scale"), "must be > 0, got " + show(s));
  }
  int wanted = core::SolverSettings{}.mesh_grid_resolution;
  if (const YAML::Node r = node["resolution"]) {
    const double n = number(r, join(path, "resolution"));
    if (n != std::floor(n) || n < core::ranges::kMinGridResolution || n > core::ranges::kMaxGridResolution) {
      fail(join(path, "resolution"), "expected a whole number of cells within [" +
                                         std::to_string(core::ranges::kMinGridResolution) + ", " +
                                         std::to_string(core::ranges::kMaxGridResolution) + "], got " + show(r));
    }
    wanted = static_cast<int>(n);
  }
  const std::string file = text(node["file"], join(path, "file"));
  core::TriangleMesh mesh;
  try {
    mesh = loadMesh(resolveMeshUri(file, base_dir), scale);
  } catch (const std::exception& e) {
    fail(join(path, "file"), e.what());
  }
  if (!core::SdfGrid::hasArea(mesh))
    fail(join(path, "file"), "'" + file + "' has no triangles: a scene mesh needs a closed surface");
  double extent = 0.0;  // m from the mesh's origin
  for (const Vec3& v : mesh.vertices) extent = std::max(extent, v.cwiseAbs().maxCoeff());
  if (!(extent <= core::ranges::kMaxExtent)) {
    std::ostringstream why;
    why << "'" << file << "' reaches " << extent << " m from its origin (at most " << core::ranges::kMaxExtent << " m)";
    fail(join(path, "file"), why.str());
  }
  const double triangles = static_cast<double>(mesh.triangles.size());
  const int resolution = core::SdfGrid::resolutionWithin(triangles, wanted);
  if (resolution == 0) {
    fail(join(path, "file"), "'" + file + "' has " + std::to_string(mesh.triangles.size()) +
                                 " triangles, too many for its distance grid (simplify the mesh)");
  }
  return core::Sdf::grid(core::SdfGrid::fromMesh(mesh, resolution));
}

core::Sdf parseShape(const YAML::Node& node, const std::string& path, const std::string& base_dir) {
  if (!node.IsMap() || !node["type"]) fail(path, "expected a map with a 'type', got " + show(node));
  const std::string type = text(node["type"], join(path, "type"));
  const std::set<std::string> pose_keys{"type", "position", "rpy", "quaternion"};
  auto known = [&](std::initializer_list<std::string> extra) {
    std::set<std::string> keys = pose_keys;
    keys.insert(extra.begin(), extra.end());
    requireKnownKeys(node, path, keys);
  };
  core::Sdf shape = core::Sdf::sphere(1.0);
  if (type == "plane") {
    known({"normal"});
    const Vec3 normal = node["normal"] ? vec3(node["normal"], join(path, "normal")) : Vec3::UnitZ();
    if (!(normal.norm() > 0.0)) fail(join(path, "normal"), "must not be zero");
    shape = core::Sdf::plane(normal);
  } else if (type == "box") {
    known({"size"});
    if (!node["size"]) fail(join(path, "size"), "a box needs size: [x, y, z] (m)");
    const Vec3 size = vec3(node["size"], join(path, "size"));
    if (!(size.minCoeff() > 0.0)) fail(join(path, "size"), "must be > 0, got " + show(node["size"]));
    shape = core::Sdf::box(size);
  } else if (type == "sphere") {
    known({"radius"});
    if (!node["radius"]) fail(join(path, "radius"), "a sphere needs a radius (m)");
    shape = core::Sdf::sphere(positiveNumber(node["radius"], join(path, "radius")));
  } else if (type == "capsule" || type == "cylinder") {
    known({"radius", "length"});
    if (!node["radius"] || !node["length"]) fail(path, "a " + type + " needs radius and length (m)");
    const double r = positiveNumber(node["radius"], join(path, "radius"));
    const double l = positiveNumber(node["length"], join(path, "length"));
    shape = type == "capsule" ? core::Sdf::capsule(r, l) : core::Sdf::cylinder(r, l);
  } else if (type == "mesh") {
    known({"file", "scale", "resolution"});
    shape = meshShape(node, path, base_dir);
  } else if (type == "union" || type == "intersection" || type == "difference") {
    known({"shapes"});
    const YAML::Node list = node["shapes"];
    const std::size_t least = type == "difference" ? 2 : 1;
    if (!list || !list.IsSequence() || list.size() < least) {
      fail(join(path, "shapes"), "a " + type + " needs a list of at least " + std::to_string(least) + " shapes");
    }
    std::vector<core::Sdf> children;
    for (std::size_t i = 0; i < list.size(); ++i) {
      children.push_back(parseShape(list[i], join(path, "shapes") + "[" + std::to_string(i) + "]", base_dir));
    }
    shape = type == "union"          ? core::Sdf::unite(std::move(children))
            : type == "intersection" ? core::Sdf::intersect(std::move(children))
                                     : core::Sdf::subtract(std::move(children));
  } else {
    fail(join(path, "type"),
         "unknown shape '" + type + "' (plane, box, sphere, capsule, cylinder, mesh, union, intersection, difference)");
  }
  const Vec3 position = node["position"] ? vec3(node["position"], join(path, "position")) : Vec3::Zero();
  return shape.transformed({orientation(node, path), position});
}

}  // namespace

std::vector<core::Sdf> parseScene(const YAML::Node& node, const std::string& base_dir) {
  if (!node.IsSequence()) fail("scene", "expected a list of shapes, got " + show(node));
  std::vector<core::Sdf> scene;
  for (std::size_t i = 0; i < node.size(); ++i)
    scene.push_back(parseShape(node[i], "scene[" + std::to_string(i) + "]", base_dir));
  return scene;
}

}  // namespace rigid_body_sim::io
