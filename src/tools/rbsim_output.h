// rbsim's outputs: the JSON line and its numbers, the CSV trajectory and the
// progress bar; the error a bad command line or output raises (exit 2) and
// the one a run that diverged ends with (exit 3).
#pragma once

#include <Eigen/Core>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/state.h"

namespace rigid_body_sim::tools {

namespace core = rigid_body_sim::core;

/// A bad command line, or an output that cannot be written: exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Closes the `file` of each of `logs`, emptied first (so a destructor
/// after it closes none twice); a UsageError saying `what` could not be
/// written whole if one could not.
template <class Log>
void closeLogs(std::vector<Log>& logs, const std::string& what) {
  std::vector<Log> closing;
  closing.swap(logs);
  bool whole = true;
  for (const Log& log : closing) whole = std::ferror(log.file) == 0 && std::fclose(log.file) == 0 && whole;
  if (!whole) throw UsageError("--out: " + what + " could not be written whole");
}

/// A state stopped being finite (the step's guard put it back): the run's
/// figures would mean nothing, so it ends with exit code 3.
struct Diverged : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Json = nlohmann::ordered_json;  // keys in the order written

/// A number for the JSON line: non-finite values become null (JSON has no NaN).
inline Json num(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }
inline Json vec(const core::Vec3& v) { return Json::array({num(v.x()), num(v.y()), num(v.z())}); }
inline Json quat(const core::Quat& q) { return Json::array({num(q.x()), num(q.y()), num(q.z()), num(q.w())}); }

/// A number for messages: as precise as the double.
inline std::string text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// A link's final pose and twist, as the JSON line gives it.
inline Json finalJson(const core::LinkState& link) {
  return {{"position", vec(link.p_WL)},
          {"quaternion", quat(link.q_WL)},
          {"linear_velocity", vec(link.v_WL)},
          {"angular_velocity", vec(link.w_W)}};
}

/// The steps of a run of `duration` seconds at `dt`: at least one, at most
/// 1e12 (eleven days at 1 µs a step); else a UsageError.
inline long long stepCount(double duration, double dt) {
  constexpr double kMaxSteps = 1e12;
  const double count = duration / dt;
  if (!(count < kMaxSteps)) {  // also keeps llround below from overflowing
    throw UsageError("--duration " + text(duration) + " is " + text(count) + " steps of " + text(dt) + " s: at most " +
                     text(kMaxSteps) + " steps per run");
  }
  const long long steps = std::llround(count);
  if (steps < 1) throw UsageError("--duration " + text(duration) + " is shorter than one step of " + text(dt) + " s");
  return steps;
}

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
  /// With `with_body`, a body column after t (a world of several bodies);
  /// with `joints` (robots), two columns per joint after the base's,
  /// JOINT.position and JOINT.velocity (in a world, ROBOT/JOINT: a robot's
  /// row fills its own, every other row leaves them empty).
  CsvWriter(const std::string& path, bool with_body, const std::vector<std::string>& joints = {})
      : file_(std::fopen(path.c_str(), "w"), &std::fclose),
        path_(path),
        with_body_(with_body),
        joints_(static_cast<int>(joints.size())) {
    if (!file_) throw UsageError("--csv: cannot write '" + path + "': " + std::strerror(errno));
    std::fputs(with_body_ ? "t,body,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz" : "t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz",
               file_.get());
    for (const std::string& joint : joints) {
      std::fprintf(file_.get(), ",%s,%s", field(joint + ".position").c_str(), field(joint + ".velocity").c_str());
    }
    std::fputc('\n', file_.get());
  }
  /// Flushes and closes the file; a failed write (a full disk) is an error.
  void finish() {
    FILE* f = file_.release();
    const bool failed = std::ferror(f) != 0;
    const int closed = std::fclose(f);
    if (failed || closed != 0) throw UsageError("--csv: writing '" + path_ + "' failed: " + std::strerror(errno));
  }
  void row(double t, const std::string& body, const core::LinkState& s) { row(t, body, s, 0, {}, {}); }
  /// A robot's row: its base, then each joint's position and velocity.
  void row(double t, const core::LinkState& base, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    row(t, "", base, 0, q, v);
  }
  /// A row whose joints (q, v) fill the joint columns from `first` on.
  void row(double t, const std::string& body, const core::LinkState& s, int first, const Eigen::VectorXd& q,
           const Eigen::VectorXd& v) {
    start(t, body, s);
    const int filled = static_cast<int>(q.size());
    for (int i = 0; i < joints_; ++i) {
      if (i >= first && i < first + filled) {
        std::fprintf(file_.get(), ",%.12g,%.12g", q(i - first), v(i - first));
      } else {
        std::fputs(",,", file_.get());
      }
    }
    std::fputc('\n', file_.get());
  }

 private:
  void start(double t, const std::string& body, const core::LinkState& s) {
    std::fprintf(file_.get(), "%.9g,", t);
    if (with_body_) std::fprintf(file_.get(), "%s,", body.c_str());
    std::fprintf(file_.get(), "%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g",
                 s.p_WL.x(), s.p_WL.y(), s.p_WL.z(), s.q_WL.x(), s.q_WL.y(), s.q_WL.z(), s.q_WL.w(), s.v_WL.x(),
                 s.v_WL.y(), s.v_WL.z(), s.w_W.x(), s.w_W.y(), s.w_W.z());
  }
  /// A header field: quoted (RFC 4180) when a URDF's name holds a comma, a quote or a line break.
  static std::string field(const std::string& name) {
    if (name.find_first_of(",\"\r\n") == std::string::npos) return name;
    std::string out = "\"";
    for (const char c : name) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
  }

  std::unique_ptr<FILE, int (*)(FILE*)> file_;
  std::string path_;
  bool with_body_;
  int joints_;  ///< joint columns (pairs)
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
