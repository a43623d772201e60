// Mesh files (STL, OBJ, DAE, ... through assimp) as collision vertices. ROS-free.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/collision.h"

namespace rigid_body_sim::io {

class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The file a URDF mesh reference points to:
///  - package://NAME/PATH: NAME is looked up in ROS_PACKAGE_PATH, at any
///    depth below each entry, as rospack crawls (the folder whose package.xml
///    says <name>NAME</name>; not inside another package, nor below a
///    CATKIN_IGNORE or rospack_nosubdirs, nor in hidden folders; the first
///    entry that has it, and in one entry the first in name order), then
///    upward from `base_dir` (so a package's own URDFs resolve without ROS);
///  - file:///ABS/PATH: that path;
///  - a relative path: relative to `base_dir` (the URDF file's folder).
/// Throws MeshError naming the URI when nothing is found.
std::string resolveMeshUri(const std::string& uri, const std::string& base_dir);

/// Every mesh in the file as one: distinct vertices (node transforms applied,
/// multiplied by `scale`, m) and the triangles over them. Throws MeshError
/// naming the file, also when it is not a regular file of at most
/// InputCaps::kMeshBytes (input_bounds.h).
core::TriangleMesh loadMesh(const std::string& path, const core::Vec3& scale);

/// The same from the file's bytes; `format` is its extension ("obj", "stl",
/// "dae"). What the mesh fuzzer calls.
core::TriangleMesh loadMeshBytes(const std::string& bytes, const std::string& format, const core::Vec3& scale);

}  // namespace rigid_body_sim::io
