// The files assimp may open while it reads one mesh: mesh_files.h.
#include "mesh_files.h"

#include <assimp/MemoryIOWrapper.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "rigid_body_sim/io/input_bounds.h"

namespace rigid_body_sim::io::detail {

namespace fs = std::filesystem;

MeshFiles::MeshFiles(const std::string& path, std::string bytes, std::uintmax_t cap)
    : bytes_(std::move(bytes)), cap_(cap), left_(cap > bytes_.size() ? cap - bytes_.size() : 0) {
  if (path.empty()) return;
  std::error_code ec;
  path_ = fs::absolute(path, ec).lexically_normal();
  folder_ = fs::weakly_canonical(path_.parent_path(), ec);
  if (ec) {
    folder_.clear();
    return;
  }
  // The mesh's package, if it is in one: its files may name a sibling
  // folder's (meshes/visual/x.obj naming ../materials/x.mtl).
  for (fs::path dir = folder_; !dir.empty(); dir = dir.parent_path()) {
    if (fs::is_regular_file(dir / "package.xml", ec)) {
      folder_ = dir;
      break;
    }
    if (dir == dir.root_path()) break;
  }
}

bool MeshFiles::isMesh(const std::string& file) const {
  if (path_.empty()) return false;
  std::error_code ec;
  return fs::absolute(file, ec).lexically_normal() == path_;
}

std::string MeshFiles::problem(const std::string& file) const {
  const std::string name = fs::path(file).filename().string();
  if (folder_.empty()) return "names a file ('" + name + "'), and a mesh read from memory may name none";
  std::error_code ec;
  const fs::path real = fs::weakly_canonical(fs::absolute(file, ec), ec);
  if (ec) return "names a file ('" + name + "') that cannot be resolved";
  const auto [in_folder, in_real] = std::mismatch(folder_.begin(), folder_.end(), real.begin(), real.end());
  if (in_folder != folder_.end()) {
    return "names a file ('" + name +
           "') outside its own folder and package: the files a mesh names must be beside it or below, or in its "
           "package";
  }
  const fs::file_status status = fs::status(real, ec);
  if (!ec && fs::is_regular_file(status) && fs::file_size(real, ec) > left_ && !ec) {
    return "names a file ('" + name + "') that holds more than the " + std::to_string(cap_ >> 20) +
           " MiB a mesh and the files it names may hold together";
  }
  const std::string why = fileProblem(real.string(), left_);
  return why.empty() ? "" : "names a file: " + why;
}

bool MeshFiles::Exists(const char* file) const {
  if (isMesh(file)) return true;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(file, ec)) || ec) return false;  // assimp goes without it, as it would
  const std::string why = problem(file);
  if (why.empty()) return true;
  if (refusal_.empty()) refusal_ = why;
  return false;
}

Assimp::IOStream* MeshFiles::Open(const char* file, const char* mode) {
  if (std::strpbrk(mode, "wa+") != nullptr) return nullptr;  // read only
  if (isMesh(file)) return new Assimp::MemoryIOStream(reinterpret_cast<const uint8_t*>(bytes_.data()), bytes_.size());
  if (!Exists(file)) return nullptr;
  try {
    std::error_code ec;
    named_.push_back(readFile(fs::weakly_canonical(fs::absolute(file, ec), ec).string(), left_));
  } catch (const std::runtime_error& e) {
    if (refusal_.empty()) refusal_ = std::string("names a file: ") + e.what();
    return nullptr;
  }
  left_ -= named_.back().size();
  return new Assimp::MemoryIOStream(reinterpret_cast<const uint8_t*>(named_.back().data()), named_.back().size());
}

void MeshFiles::Close(Assimp::IOStream* stream) { delete stream; }

}  // namespace rigid_body_sim::io::detail
