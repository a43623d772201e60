// rbsim as a user runs it, for its end-to-end suites (rbsim_test.cpp,
// rbsim_robot_test.cpp): the binary run with arguments, its exit code and
// what it printed.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../scratch_dir.h"

namespace rigid_body_sim::test {

struct Result {
  int code = -1;
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string tempPath(const std::string& name) { return (scratch().path() / name).string(); }

/// Runs rbsim with `args`; killed after 60 s (exit code 124) so that a hang fails instead of stalling.
inline Result rbsim(const std::string& args, const std::string& folder = "") {
  const std::string out = tempPath("out"), err = tempPath("err");
  const std::string cmd = (folder.empty() ? "" : "cd '" + folder + "' && ") + "timeout 60 " + std::string(RBS_RBSIM) +
                          " " + args + " >" + out + " 2>" + err;
  const int status = std::system(cmd.c_str());
  Result r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

inline const std::string kBox = std::string(RBS_SOURCE_DIR) + "/urdf/box.urdf";

/// A YAML (or JSON) list of numbers.
inline std::vector<double> seq(const YAML::Node& n) { return n.as<std::vector<double>>(); }

/// rbsim refuses `args` with exit code 2 and one line naming `message`.
inline void expectUsageError(const std::string& args, const std::string& message) {
  const Result r = rbsim(args);
  EXPECT_EQ(r.code, 2) << args;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("rbsim: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << "'" << message << "' not in: " << r.err;
}

}  // namespace rigid_body_sim::test
