// rbsim's outputs: the JSON line, the CSV trajectory and the progress bar;
// and the error a bad command line or output raises (exit 2).
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "rigid_body_sim/core/state.h"

namespace rigid_body_sim::tools {

namespace core = rigid_body_sim::core;

/// A bad command line, or an output that cannot be written: exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Json = nlohmann::ordered_json;  // keys in the order written

/// One JSON object on one line of stdout whose last member, an array, is
/// written an element at a time: a world's bodies as one nlohmann tree and
/// its text took 1.9 KB a body, a third of rbsim's peak memory at N = 10,000.
/// The bytes are those of the whole object's dump().
class JsonLine {
 public:
  /// Writes `head`'s members and opens `array_key`.
  JsonLine(const Json& head, const std::string& array_key) {
    std::string text = dump(head);
    text.pop_back();  // its '}'
    put(text + (head.empty() ? "" : ",") + dump(Json(array_key)) + ":[");
  }
  void element(const Json& e) {
    put((first_ ? "" : ",") + dump(e));
    first_ = false;
  }
  void finish() {
    put("]}\n");
    if (std::fflush(stdout) != 0) fail();
  }

 private:
  bool first_ = true;

  /// Names are the user's: escaped by the library; bytes that are not UTF-8 are replaced, not refused.
  static std::string dump(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }
  static void put(const std::string& s) {
    if (std::fwrite(s.data(), 1, s.size(), stdout) != s.size()) fail();
  }
  [[noreturn]] static void fail() {
    throw UsageError(std::string("stdout: writing the JSON line failed: ") + std::strerror(errno));
  }
};

class CsvWriter {
 public:
  /// With `with_body`, a body column after t (a world of several bodies).
  CsvWriter(const std::string& path, bool with_body)
      : file_(std::fopen(path.c_str(), "w"), &std::fclose), path_(path), with_body_(with_body) {
    if (!file_) throw UsageError("--csv: cannot write '" + path + "': " + std::strerror(errno));
    std::fputs(with_body_ ? "t,body,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz\n" : "t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz\n",
               file_.get());
  }
  /// Flushes and closes the file; a failed write (a full disk) is an error.
  void finish() {
    FILE* f = file_.release();
    const bool failed = std::ferror(f) != 0;
    const int closed = std::fclose(f);
    if (failed || closed != 0) throw UsageError("--csv: writing '" + path_ + "' failed: " + std::strerror(errno));
  }
  void row(double t, const std::string& body, const core::LinkState& s) {
    std::fprintf(file_.get(), "%.9g,", t);
    if (with_body_) std::fprintf(file_.get(), "%s,", body.c_str());
    std::fprintf(file_.get(), "%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g\n",
                 s.p_WL.x(), s.p_WL.y(), s.p_WL.z(), s.q_WL.x(), s.q_WL.y(), s.q_WL.z(), s.q_WL.w(), s.v_WL.x(),
                 s.v_WL.y(), s.v_WL.z(), s.w_W.x(), s.w_W.y(), s.w_W.z());
  }

 private:
  std::unique_ptr<FILE, int (*)(FILE*)> file_;
  std::string path_;
  bool with_body_;
};

class ProgressBar {
 public:
  ProgressBar(long long total, bool enabled) : total_(total), enabled_(enabled) {}
  void show(long long done) {
    if (!enabled_) return;
    const int width = 40;
    const int filled = static_cast<int>(width * done / total_);
    std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################", width - filled, "",
                 static_cast<int>(100 * done / total_));
    if (done == total_) std::fputc('\n', stderr);
    std::fflush(stderr);
  }

 private:
  long long total_;
  bool enabled_;
};

}  // namespace rigid_body_sim::tools
