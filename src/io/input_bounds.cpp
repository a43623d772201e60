#include "rigid_body_sim/io/input_bounds.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/parser.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rigid_body_sim::io {
namespace {

namespace fs = std::filesystem;

/// A YAML event handler that refuses aliases and anchors and counts depth.
class ShapeCheck : public YAML::EventHandler {
 public:
  std::string problem;
  int documents = 0;

  void OnDocumentStart(const YAML::Mark&) override { ++documents; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { anchored(mark, anchor); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override {
    refuse(mark, "an alias (*name): aliases are refused (an alias bomb expands exponentially); write the value out");
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string&) override {
    anchored(mark, anchor);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnSequenceEnd() override { --depth_; }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnMapEnd() override { --depth_; }

 private:
  int depth_ = 0;

  void refuse(const YAML::Mark& mark, const std::string& why) {
    if (problem.empty()) problem = "line " + std::to_string(mark.line + 1) + ": " + why;
  }
  void anchored(const YAML::Mark& mark, YAML::anchor_t anchor) {
    if (anchor != YAML::NullAnchor) refuse(mark, "an anchor (&name): anchors and aliases are refused");
  }
  void open(const YAML::Mark& mark, YAML::anchor_t anchor) {
    anchored(mark, anchor);
    if (++depth_ > InputCaps::kYamlDepth) {
      refuse(mark, "nested more than " + std::to_string(InputCaps::kYamlDepth) + " levels deep");
    }
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

}  // namespace

std::string fileProblem(const std::string& path, std::uintmax_t max_bytes) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return "'" + path + "': no such file";
  if (fs::is_directory(status)) return "'" + path + "' is a directory, not a file";
  if (!fs::is_regular_file(status)) return "'" + path + "' is not a regular file (a device, pipe or socket)";
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return "'" + path + "': " + ec.message();
  if (size > max_bytes) {
    return "'" + path + "' is " + std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) +
           " this input may have";
  }
  return "";
}

std::string readFile(const std::string& path, std::uintmax_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read '" + path + "': " + std::strerror(errno));
  // In chunks, up to one byte past the cap: a buffer of the cap's size for
  // every file (16 MiB, written through) cost 16 MiB of peak memory and of
  // writing per URDF, 160 GB of it for a world of 10,000 bodies.
  std::string bytes;
  constexpr std::size_t kChunk = 1 << 16;
  while (in && bytes.size() <= max_bytes) {
    const std::size_t at = bytes.size();
    bytes.resize(at + kChunk);
    in.read(bytes.data() + at, static_cast<std::streamsize>(kChunk));
    bytes.resize(at + static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw std::runtime_error("cannot read '" + path + "': " + std::strerror(errno));
  if (bytes.size() > max_bytes) {
    throw std::runtime_error("'" + path + "' holds more than the " + std::to_string(max_bytes) +
                             " bytes this input may have");
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

std::string xmlProblem(const std::string& xml) {
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
