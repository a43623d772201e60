// Bounds on what the loaders read, checked before anything is parsed: a
// file must be a regular file of bounded size, a YAML text has one document
// and no alias bomb, a URDF's nesting and link count are capped. Each check
// returns why the input is refused ("" when it is not), for the loader to
// throw in its own error type.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace rigid_body_sim::io {

/// Caps on input (docs/physics.md §5.9 lists them with the model's ranges).
struct InputCaps {
  static constexpr std::uintmax_t kConfigBytes = 16u << 20;  ///< a YAML config (10,000 bodies take about 1 MB)
  static constexpr std::uintmax_t kUrdfBytes = 16u << 20;    ///< a URDF document
  static constexpr std::uintmax_t kMeshBytes = 256u << 20;   ///< a mesh file (a million-vertex OBJ is about 40 MB)
  static constexpr int kYamlDepth = 64;                      ///< nested maps and sequences
  static constexpr std::uint64_t kYamlAliasNodes = 100000;   ///< nodes YAML aliases may repeat, in all
  static constexpr int kXmlDepth = 64;                       ///< nested XML elements (a URDF needs 5)
  static constexpr int kUrdfLinks = 10000;                   ///< <link> elements in one URDF
};

/// Why `path` cannot be read as an input file: it does not exist, is not a
/// regular file (a directory, a device, a pipe), or holds more than
/// `max_bytes`. "" when it can.
std::string fileProblem(const std::string& path, std::uintmax_t max_bytes);

/// The bytes of `path`, which fileProblem() found readable. Throws
/// std::runtime_error naming the file if it cannot be read or grew past
/// `max_bytes` since (at most max_bytes + 1 bytes are ever read).
std::string readFile(const std::string& path, std::uintmax_t max_bytes);

/// fileProblem() then readFile(), each refusal thrown as the loader's own
/// `Error`, its message starting with `what` ("config", "URDF").
template <class Error>
std::string readInput(const std::string& path, std::uintmax_t max_bytes, const std::string& what) {
  const std::string problem = fileProblem(path, max_bytes);
  if (!problem.empty()) throw Error(what + " " + problem);
  try {
    return readFile(path, max_bytes);
  } catch (const std::runtime_error& e) {
    throw Error(what + " " + e.what());
  }
}

/// Why a YAML text is refused before a tree is built from it: aliases that
/// repeat more than kYamlAliasNodes nodes in all (an alias bomb expands
/// exponentially) or an alias as a key, a key said twice in one map, a
/// second document (it would be ignored), nesting deeper than kYamlDepth,
/// or a syntax error. "" when it is accepted.
std::string yamlProblem(const std::string& text);

/// Why an XML text is refused before it is parsed: a NUL byte (the parser
/// stops there, the rest unread), bytes that are not UTF-8 (the parser
/// stepped past the end of a text cut inside a character), elements nested deeper than kXmlDepth
/// (the parser recurses), or more than kUrdfLinks <link> elements. "" when
/// it is accepted. A scan of tags only: comments, CDATA, processing
/// instructions and declarations are skipped.
std::string xmlProblem(const std::string& xml);

/// Why a mesh file's bytes are refused before any reader allocates: a
/// format other than STL, OBJ and DAE (Collada) (`extension`, any case,
/// without the dot), or a count its header declares that the file's size
/// cannot hold. Readers size their arrays by those counts: a 169-byte PLY
/// that said `element vertex 4000000000` made assimp ask for 48 GB, and
/// assimp's PLY reader (Debian 12's 5.2.5) hangs on a malformed header
/// (mesh_fuzzer found one in a minute), so PLY is not read. A DAE count="N"
/// counts items of at least a byte each; STL and OBJ declare none that the
/// reader trusts (assimp takes an STL as binary only when its size matches
/// its count). "" when accepted.
std::string meshProblem(const std::string& bytes, const std::string& extension);

}  // namespace rigid_body_sim::io
