#include "rigid_body_sim/io/input_bounds.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/parser.h>

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rigid_body_sim::io {
namespace {

namespace fs = std::filesystem;

/// A cap in words: "256 MiB", "16 MiB", or "10 bytes".
std::string capText(std::uintmax_t bytes) {
  constexpr std::uintmax_t kMiB = 1u << 20;
  return bytes >= kMiB && bytes % kMiB == 0 ? std::to_string(bytes / kMiB) + " MiB" : std::to_string(bytes) + " bytes";
}

/// A YAML event handler that refuses repeated keys and alias bombs, and
/// counts depth. yaml-cpp keeps one of two equal keys in a map without a
/// word ({rate: 100, rate: 200}): a half-read file. An alias counts as the
/// nodes its anchor holds (aliases within included), so nested aliases that
/// would expand exponentially are refused before any tree is built.
class ShapeCheck : public YAML::EventHandler {
 public:
  std::string problem;
  int documents = 0;

  void OnDocumentStart(const YAML::Mark&) override { ++documents; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor, "~"); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    if (!open_.empty() && open_.back().map && open_.back().key_next) {
      refuse(mark, "an alias (*name) as a key: write the key out");
    }
    const auto size = sizes_.find(anchor);
    const std::uint64_t nodes = size == sizes_.end() ? 1 : size->second;
    expanded_ += nodes;
    if (expanded_ > InputCaps::kYamlAliasNodes) {
      refuse(mark, "aliases (*name) repeat more than " + std::to_string(InputCaps::kYamlAliasNodes) +
                       " nodes (an alias bomb expands exponentially): write the values out");
    }
    node(mark, "", false);
    if (!open_.empty()) open_.back().size += nodes;
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string& value) override {
    leaf(mark, anchor, value);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, anchor, false);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, anchor, true);
  }
  void OnMapEnd() override { close(); }

 private:
  /// An open map or sequence: a map's keys so far, whether its next node is
  /// a key, its anchor and the nodes it holds so far (itself included).
  struct Open {
    bool map = false;
    bool key_next = true;
    std::set<std::string> keys;
    YAML::anchor_t anchor = YAML::NullAnchor;
    std::uint64_t size = 1;
  };
  std::vector<Open> open_;
  std::map<YAML::anchor_t, std::uint64_t> sizes_;  ///< nodes under each anchor, expanded
  std::uint64_t expanded_ = 0;                     ///< nodes the aliases repeat

  void refuse(const YAML::Mark& mark, const std::string& why) {
    if (problem.empty()) problem = "line " + std::to_string(mark.line + 1) + ": " + why;
  }
  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor, const std::string& value) {
    if (anchor != YAML::NullAnchor) sizes_[anchor] = 1;
    node(mark, value);
    if (!open_.empty()) ++open_.back().size;
  }
  /// A node starts: in a map, every other one is a key (a map or sequence
  /// as a key is never equal to a scalar one; it is let through).
  void node(const YAML::Mark& mark, const std::string& scalar, bool is_scalar = true) {
    if (open_.empty() || !open_.back().map) return;
    Open& map = open_.back();
    if (map.key_next && is_scalar && !map.keys.insert(scalar).second) {
      refuse(mark, "key '" + scalar + "' appears twice in one map: say it once");
    }
    map.key_next = !map.key_next;
  }
  void open(const YAML::Mark& mark, YAML::anchor_t anchor, bool map) {
    node(mark, "", false);
    open_.push_back({map, true, {}, anchor, 1});
    if (static_cast<int>(open_.size()) > InputCaps::kYamlDepth) {
      refuse(mark, "nested more than " + std::to_string(InputCaps::kYamlDepth) + " levels deep");
    }
  }
  void close() {
    if (open_.empty()) return;
    const Open done = open_.back();
    open_.pop_back();
    if (done.anchor != YAML::NullAnchor) sizes_[done.anchor] = done.size;
    if (!open_.empty()) open_.back().size += done.size;
  }
};

/// The end of the markup construct starting at `at` ("<!--", "<![CDATA[",
/// "<?", "<!"), or npos.
std::size_t skipSpecial(const std::string& xml, std::size_t at) {
  if (xml.compare(at, 4, "<!--") == 0) {
    const std::size_t end = xml.find("-->", at + 4);
    return end == std::string::npos ? end : end + 3;
  }
  if (xml.compare(at, 9, "<![CDATA[") == 0) {
    const std::size_t end = xml.find("]]>", at + 9);
    return end == std::string::npos ? end : end + 3;
  }
  const std::size_t end = xml.find('>', at);
  return end == std::string::npos ? end : end + 1;
}

/// The '>' closing the tag that starts at `at`, skipping quoted attribute
/// values (a '>' or "/>" inside quotes ends nothing), or npos.
std::size_t tagEnd(const std::string& xml, std::size_t at) {
  char quote = '\0';
  for (std::size_t i = at + 1; i < xml.size(); ++i) {
    const char c = xml[i];
    if (quote != '\0') {
      if (c == quote) quote = '\0';
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '>') {
      return i;
    }
  }
  return std::string::npos;
}

/// Why a Collada count="N" attribute exceeds what the file can hold, or "".
std::string daeProblem(const std::string& bytes) {
  for (std::size_t at = bytes.find("count"); at != std::string::npos; at = bytes.find("count", at + 5)) {
    std::size_t v = at + 5;
    while (v < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[v]))) ++v;
    if (v >= bytes.size() || bytes[v] != '=') continue;
    ++v;
    while (v < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[v]))) ++v;
    if (v >= bytes.size() || (bytes[v] != '"' && bytes[v] != '\'')) continue;
    const double n = std::strtod(bytes.c_str() + v + 1, nullptr);
    if (n > static_cast<double>(bytes.size())) {
      std::ostringstream os;
      os << "it declares count=" << n << ", more than the file's " << bytes.size()
         << " bytes can hold (readers allocate by that count)";
      return os.str();
    }
  }
  return "";
}

}  // namespace

std::string meshProblem(const std::string& bytes, const std::string& extension) {
  std::string ext = extension;
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "dae") return daeProblem(bytes);
  if (ext == "stl" || ext == "obj") return "";
  return "the format '" + extension +
         "' is not read here: STL, OBJ and DAE (Collada) are, the formats Gazebo reads (each of assimp's "
         "other parsers is one more for a file to attack; its PLY reader hangs on a malformed header)";
}

std::string fileProblem(const std::string& path, std::uintmax_t max_bytes) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return "'" + path + "': no such file";
  if (fs::is_directory(status)) return "'" + path + "' is a directory, not a file";
  if (!fs::is_regular_file(status)) return "'" + path + "' is not a regular file (a device, pipe or socket)";
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return "'" + path + "': " + ec.message();
  // The cap, not the size: a refusal must not tell a caller how big a file is.
  if (size > max_bytes) return "'" + path + "' holds more than the " + capText(max_bytes) + " this input may have";
  return "";
}

std::string readFile(const std::string& path, std::uintmax_t max_bytes) {
  // Opened without blocking and checked again on the descriptor: a file
  // swapped for a FIFO after fileProblem() looked would block an ifstream
  // for good (and the spawn thread with it).
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot read '" + path + "': " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    throw std::runtime_error("'" + path + "' is not a regular file (a device, pipe or socket)");
  }
  // In chunks, up to one byte past the cap: a buffer of the cap's size for
  // every file (16 MiB, written through) cost 16 MiB of peak memory and of
  // writing per URDF, 160 GB of it for a world of 10,000 bodies.
  std::string bytes;
  constexpr std::size_t kChunk = 1 << 16;
  while (bytes.size() <= max_bytes) {
    const std::size_t at = bytes.size();
    bytes.resize(at + kChunk);
    const ssize_t got = ::read(fd, bytes.data() + at, kChunk);
    if (got < 0 && errno == EINTR) {
      bytes.resize(at);
      continue;
    }
    if (got < 0) throw std::runtime_error("cannot read '" + path + "': " + std::strerror(errno));
    bytes.resize(at + static_cast<std::size_t>(got));
    if (got == 0) break;
  }
  if (bytes.size() > max_bytes) {
    throw std::runtime_error("'" + path + "' holds more than the " + capText(max_bytes) + " this input may have");
  }
  return bytes;
}

std::string yamlProblem(const std::string& text) {
  std::istringstream in(text);
  ShapeCheck check;
  try {
    YAML::Parser parser(in);
    while (check.problem.empty() && parser.HandleNextDocument(check)) {
      if (check.documents > 1) return "a second YAML document (after ---): one document per file";
    }
  } catch (const YAML::Exception& e) {
    return std::string("not valid YAML: ") + e.what();
  }
  return check.problem;
}

namespace {

/// Where `text` stops being UTF-8 (a byte that starts no character, or a
/// character cut short or not continued), or npos.
std::size_t notUtf8At(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    std::size_t length = 0;
    if (lead < 0x80) {
      length = 1;
    } else if (lead >= 0xC2 && lead <= 0xDF) {
      length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      length = 3;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      length = 4;
    }
    if (length == 0 || i + length > text.size()) return i;
    for (std::size_t k = i + 1; k < i + length; ++k) {
      if ((byte(k) & 0xC0) != 0x80) return i;
    }
    i += length;
  }
  return std::string::npos;
}

}  // namespace

std::string xmlProblem(const std::string& xml) {
  // TinyXML, which urdfdom parses with, reads a C string: it would stop at
  // a NUL byte and the rest of the text would be dropped unread.
  // (Where, it does not say: a file's contents are not told to a caller,
  // and /proc/self/environ's first NUL was the length of a variable.)
  if (xml.find('\0') != std::string::npos) {
    return "it holds a NUL byte: a URDF is text (the parser would stop there, the rest unread)";
  }
  // And after an XML declaration it steps over a character by the length
  // its first byte announces: a character cut short by the end of the text
  // took it past the end (urdf_fuzzer, under ASan, in CI).
  if (notUtf8At(xml) != std::string::npos)
    return "it holds bytes that are not UTF-8: a URDF is UTF-8 text, XML's default";
  int depth = 0;
  int links = 0;
  for (std::size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at)) {
    const char next = at + 1 < xml.size() ? xml[at + 1] : '\0';
    if (next == '!' || next == '?') {
      at = skipSpecial(xml, at);
      continue;
    }
    const std::size_t end = tagEnd(xml, at);
    if (end == std::string::npos) break;  // unterminated: the parser says so
    if (next == '/') {
      --depth;
    } else if (xml[end - 1] != '/') {  // not self-closing
      if (++depth > InputCaps::kXmlDepth) {
        return "XML elements nested more than " + std::to_string(InputCaps::kXmlDepth) + " levels deep";
      }
    }
    if (xml.compare(at, 5, "<link") == 0 && (at + 5 >= xml.size() || std::strchr(" \t\r\n/>", xml[at + 5]))) {
      if (++links > InputCaps::kUrdfLinks) {
        return "more than " + std::to_string(InputCaps::kUrdfLinks) + " <link> elements";
      }
    }
    at = end + 1;
  }
  return "";
}

}  // namespace rigid_body_sim::io
