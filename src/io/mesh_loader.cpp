#include "rigid_body_sim/io/mesh_loader.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "mesh_files.h"
#include "rigid_body_sim/io/input_bounds.h"

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

/// Where the crawl for a package stops (rospack's rules): a package does not
/// hold packages, CATKIN_IGNORE and rospack_nosubdirs close a folder, and
/// hidden folders (.git) are passed by. Depth and folder count are bounded,
/// so a ROS_PACKAGE_PATH of / ends; symbolic links are followed once.
struct PackageCrawl {
  static constexpr int kMaxDepth = 100;               // rospack's is 1000
  static constexpr std::size_t kMaxFolders = 200000;  // folders read per root
  const std::string& name;
  std::set<fs::path> seen;  // canonical folders already crawled

  /// The package folder named `name` at or below `dir`, or "".
  std::string find(const fs::path& dir, int depth) {
    std::error_code ec;
    if (depth > kMaxDepth || seen.size() >= kMaxFolders) return "";
    if (!seen.insert(fs::canonical(dir, ec)).second || ec) return "";
    if (fs::exists(dir / "CATKIN_IGNORE", ec)) return "";
    if (fs::exists(dir / "package.xml", ec)) return packageName(dir) == name ? dir.string() : "";
    if (fs::exists(dir / "rospack_nosubdirs", ec)) return "";
    std::vector<fs::path> children;  // in name order: the same package whatever the file system's order
    for (const auto& child : fs::directory_iterator(dir, ec)) {
      const std::string leaf = child.path().filename().string();
      if (!leaf.empty() && leaf[0] != '.' && child.is_directory(ec)) children.push_back(child.path());
    }
    std::sort(children.begin(), children.end());
    for (const fs::path& child : children) {
      std::string found = find(child, depth + 1);
      if (!found.empty()) return found;
    }
    return "";
  }
};

/// A package folder named `name` at or below `root`, as rospack finds it.
std::string findPackage(const fs::path& root, const std::string& name) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return "";
  PackageCrawl crawl{name, {}};
  return crawl.find(root, 0);
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
  // A path inside the package: '..' would step out of it, and a refusal
  // would then tell a caller where the package is installed.
  for (const fs::path& part : fs::path(path)) {
    if (part == "..") throw MeshError("'" + uri + "': package://NAME/PATH may not leave the package ('..')");
  }
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

namespace {

/// The meshes of an imported scene as one TriangleMesh (see loadMesh).
core::TriangleMesh fromScene(const aiScene* scene, const Assimp::Importer& importer, const std::string& path,
                             const core::Vec3& scale) {
  if (scene == nullptr || scene->mNumMeshes == 0) {
    throw MeshError("mesh '" + path + "': cannot read it (" + importer.GetErrorString() + ")");
  }
  std::vector<core::Vec3> raw;
  std::vector<std::array<int, 3>> raw_triangles;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const int base = static_cast<int>(raw.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      raw.emplace_back(p.x * scale.x(), p.y * scale.y(), p.z * scale.z());
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines: no surface
      raw_triangles.push_back({base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
                               base + static_cast<int>(face.mIndices[2])});
    }
  }
  for (const core::Vec3& v : raw) {
    if (!v.allFinite()) throw MeshError("mesh '" + path + "': a vertex is not finite");
  }
  // Formats repeat a vertex per face (STL) or per normal: keep each position
  // once, in a fixed order, and renumber the triangles.
  std::vector<int> order(raw.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  const auto less = [&](int a, int b) {
    return std::lexicographical_compare(raw[a].data(), raw[a].data() + 3, raw[b].data(), raw[b].data() + 3);
  };
  std::stable_sort(order.begin(), order.end(), less);
  core::TriangleMesh out;
  std::vector<int> index(raw.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k == 0 || raw[order[k]] != raw[order[k - 1]]) out.vertices.push_back(raw[order[k]]);
    index[order[k]] = static_cast<int>(out.vertices.size()) - 1;
  }
  for (const auto& t : raw_triangles) out.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  if (out.vertices.empty()) throw MeshError("mesh '" + path + "': no vertices");
  return out;
}

/// An importer that reads mesh coordinates as ROS does.
void configure(Assimp::Importer& importer) {
  // ROS reads mesh coordinates as they are, z up (rviz, Gazebo): a Collada
  // <up_axis> must not rotate them.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
}

// Bake node transforms into the vertices (DAE files carry them); triangles only.
constexpr unsigned kImportSteps = aiProcess_PreTransformVertices | aiProcess_Triangulate;

/// Imports `bytes` (the mesh at `path`, or from memory when `path` is
/// empty), every file assimp opens for it through detail::MeshFiles.
core::TriangleMesh import(const std::string& path, std::string bytes, const std::string& format,
                          const core::Vec3& scale) {
  const std::string shown = path.empty() ? "<" + format + " bytes>" : path;
  // A count a header declares is checked before any reader allocates by it.
  const std::string header_problem = meshProblem(bytes, format);
  if (!header_problem.empty()) throw MeshError("mesh '" + shown + "': " + header_problem);
  Assimp::Importer importer;
  configure(importer);
  const std::size_t size = bytes.size();
  auto* files = new detail::MeshFiles(path, std::move(bytes), InputCaps::kMeshBytes);
  importer.SetIOHandler(files);  // the importer owns it
  const aiScene* scene = path.empty() ? importer.ReadFileFromMemory(files->bytes(), size, kImportSteps, format.c_str())
                                      : importer.ReadFile(path, kImportSteps);
  if (!files->refusal().empty()) throw MeshError("mesh '" + shown + "' " + files->refusal());
  return fromScene(scene, importer, shown, scale);
}

}  // namespace

core::TriangleMesh loadMesh(const std::string& path, const core::Vec3& scale) {
  std::string extension = fs::path(path).extension().string();
  if (!extension.empty()) extension.erase(0, 1);
  // assimp reads these bytes, not the file again: what was checked is what is read.
  return import(path, readInput<MeshError>(path, InputCaps::kMeshBytes, "mesh"), extension, scale);
}

core::TriangleMesh loadMeshBytes(const std::string& bytes, const std::string& format, const core::Vec3& scale) {
  if (bytes.size() > InputCaps::kMeshBytes) throw MeshError("mesh bytes: more than the cap");
  return import("", bytes, format, scale);
}

}  // namespace rigid_body_sim::io
