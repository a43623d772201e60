// The files assimp may open while it reads one mesh (private to io): the mesh
// itself, from the bytes already read and checked, and the files the mesh
// names (an OBJ's `mtllib`, a texture) only when they pass the checks the
// mesh passed: a regular file, within the bytes the mesh's cap leaves, and
// in the mesh's folder or below it, or in its ROS package (the nearest
// folder above it with a package.xml). assimp's own file system opened
// whatever a mesh named: a FIFO as an OBJ's material file blocked the spawn
// thread for good, a 1.5 GB `.mtl` took 1.58 GB beside a 79-byte OBJ.
#pragma once

#include <assimp/IOSystem.hpp>
#include <cstdint>
#include <filesystem>
#include <list>
#include <string>

namespace rigid_body_sim::io::detail {

class MeshFiles : public Assimp::IOSystem {
 public:
  /// The mesh at `path` (empty: bytes from memory, which may name no file)
  /// whose `bytes` are read; its files together may hold `cap` bytes.
  MeshFiles(const std::string& path, std::string bytes, std::uintmax_t cap);

  bool Exists(const char* file) const override;
  char getOsSeparator() const override { return '/'; }
  /// The mesh or a file it names that passes the checks, read whole into
  /// memory first; nullptr for any other (assimp then goes without it, as
  /// it does for a file that is missing) and for writing.
  Assimp::IOStream* Open(const char* file, const char* mode) override;
  void Close(Assimp::IOStream* stream) override;

  /// The mesh's bytes.
  const char* bytes() const { return bytes_.data(); }
  /// Why the first file the mesh named was refused ("" if none was): the
  /// loader refuses the mesh with it, rather than take it half-read.
  const std::string& refusal() const { return refusal_; }

 private:
  /// Whether `file` is the mesh itself.
  bool isMesh(const std::string& file) const;
  /// Why `file`, which exists, may not be read ("" if it may).
  std::string problem(const std::string& file) const;

  std::filesystem::path path_;    ///< the mesh's, absolute and normal
  std::filesystem::path folder_;  ///< its package's or its folder, canonical; empty for bytes from memory
  std::string bytes_;
  std::list<std::string> named_;  ///< the bytes of each file it named, alive while assimp reads
  std::uintmax_t cap_;            ///< bytes the mesh and its files may hold together
  std::uintmax_t left_;           ///< bytes its files may still take
  mutable std::string refusal_;
};

}  // namespace rigid_body_sim::io::detail
