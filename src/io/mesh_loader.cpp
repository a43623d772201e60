#include "rigid_body_sim/io/mesh_loader.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace rigid_body_sim::io {
namespace {

namespace fs = std::filesystem;

/// The <name> of a package.xml, or "" if there is none.
std::string packageName(const fs::path& dir) {
  std::ifstream in(dir / "package.xml");
  if (!in) return "";
  std::stringstream text;
  text << in.rdbuf();
  std::smatch m;
  const std::string s = text.str();
  return std::regex_search(s, m, std::regex("<name>\\s*([^<\\s]+)\\s*</name>")) ? m[1].str() : "";
}

/// A package directory named `name` under `root` (root itself, a child, or a grandchild).
std::string findPackage(const fs::path& root, const std::string& name) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return "";
  if (packageName(root) == name) return root.string();
  if (packageName(root / name) == name) return (root / name).string();
  for (const auto& child : fs::directory_iterator(root, ec)) {
    if (!child.is_directory(ec)) continue;
    if (packageName(child.path()) == name) return child.path().string();
    for (const auto& grandchild : fs::directory_iterator(child.path(), ec)) {
      if (grandchild.is_directory(ec) && packageName(grandchild.path()) == name) return grandchild.path().string();
    }
  }
  return "";
}

}  // namespace

std::string resolveMeshUri(const std::string& uri, const std::string& base_dir) {
  const std::string package_scheme = "package://", file_scheme = "file://";
  if (uri.rfind(file_scheme, 0) == 0) return uri.substr(file_scheme.size());
  if (uri.rfind(package_scheme, 0) != 0) {
    const fs::path p(uri);
    return p.is_absolute() || base_dir.empty() ? uri : (fs::path(base_dir) / p).string();
  }
  const std::string rest = uri.substr(package_scheme.size());
  const auto slash = rest.find('/');
  if (slash == std::string::npos) throw MeshError("mesh '" + uri + "': expected package://NAME/PATH");
  const std::string name = rest.substr(0, slash), path = rest.substr(slash + 1);
  if (const char* env = std::getenv("ROS_PACKAGE_PATH")) {
    std::stringstream roots(env);
    for (std::string root; std::getline(roots, root, ':');) {
      const std::string dir = root.empty() ? "" : findPackage(root, name);
      if (!dir.empty()) return (fs::path(dir) / path).string();
    }
  }
  std::error_code ec;
  for (fs::path dir = base_dir.empty() ? fs::path() : fs::absolute(base_dir, ec); !dir.empty();
       dir = dir.parent_path()) {
    if (packageName(dir) == name) return (dir / path).string();
    if (dir == dir.root_path()) break;
  }
  throw MeshError("mesh '" + uri + "': package '" + name +
                  "' not found in ROS_PACKAGE_PATH nor above the URDF's folder");
}

std::vector<core::Vec3> loadMeshVertices(const std::string& path, const core::Vec3& scale) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw MeshError("mesh '" + path + "': no such file");
  Assimp::Importer importer;
  // ROS reads mesh coordinates as they are, z up (rviz, Gazebo): a Collada
  // <up_axis> must not rotate them.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  // Bake node transforms into the vertices (DAE files carry them).
  const aiScene* scene = importer.ReadFile(path, aiProcess_PreTransformVertices);
  if (scene == nullptr || scene->mNumMeshes == 0) {
    throw MeshError("mesh '" + path + "': cannot read it (" + importer.GetErrorString() + ")");
  }
  std::vector<core::Vec3> vertices;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      vertices.emplace_back(p.x * scale.x(), p.y * scale.y(), p.z * scale.z());
    }
  }
  // Formats repeat a vertex per face (STL) or per normal: keep each position once.
  const auto less = [](const core::Vec3& a, const core::Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(vertices.begin(), vertices.end(), less);
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  if (vertices.empty()) throw MeshError("mesh '" + path + "': no vertices");
  for (const core::Vec3& v : vertices) {
    if (!v.allFinite()) throw MeshError("mesh '" + path + "': a vertex is not finite");
  }
  return vertices;
}

}  // namespace rigid_body_sim::io
