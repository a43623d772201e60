// SIGINT at start-up and while running (issue 13): Ctrl-C during a long load
// once waited for the load, then published after ROS had shut down
// (SIGTRAP). Now the node ends at once while it loads (exit 130, nothing
// advertised) and stops cleanly once it runs (exit 0). Each case starts its
// own sim_node and signals it.
#include <gtest/gtest.h>
#include <poll.h>
#include <ros/ros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace rbs_test {
namespace {

std::chrono::steady_clock::time_point deadline(double seconds) {
  return std::chrono::steady_clock::now() +
         std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
}

/// A sim_node started in namespace `ns`, its stdout and stderr on a pipe.
class Child {
 public:
  explicit Child(const std::string& ns) {
    const std::string remap = "__ns:=" + ns;            // before fork: the child only execs
    setenv("ROSCONSOLE_STDOUT_LINE_BUFFERED", "1", 1);  // its INFO lines as they come, not at exit
    int fds[2];
    if (pipe(fds) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(fds[1], STDOUT_FILENO);
      dup2(fds[1], STDERR_FILENO);
      close(fds[0]);
      execl(RBS_SIM_NODE, RBS_SIM_NODE, remap.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    out_ = fds[0];
  }
  ~Child() {
    if (pid_ > 0 && !reaped_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (out_ >= 0) close(out_);
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  /// Reads its output until it contains `text` (true), or until it ends or
  /// `seconds` pass (false).
  bool waitFor(const std::string& text, double seconds) {
    const auto until = deadline(seconds);
    while (output_.find(text) == std::string::npos) {
      if (std::chrono::steady_clock::now() > until || !readSome(until)) return false;
    }
    return true;
  }

  void signal(int sig) const { kill(pid_, sig); }

  /// Reads to the end and reaps it; the raw wait status, or -1 if it did not
  /// end within `seconds` (then it is killed).
  int finish(double seconds) {
    const auto until = deadline(seconds);
    while (std::chrono::steady_clock::now() < until && readSome(until)) {
    }
    int status = 0;
    for (;;) {
      const pid_t done = waitpid(pid_, &status, WNOHANG);
      if (done == pid_) break;
      if (std::chrono::steady_clock::now() > until) return -1;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    reaped_ = true;
    return status;
  }

  const std::string& output() const { return output_; }

 private:
  /// One read of available output before `until`; false at its end.
  bool readSome(std::chrono::steady_clock::time_point until) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now());
    pollfd p{out_, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(std::max<long>(0, left.count()))) <= 0) return false;
    char buf[4096];
    const ssize_t n = read(out_, buf, sizeof buf);
    if (n <= 0) return false;
    output_.append(buf, static_cast<std::size_t>(n));
    return true;
  }

  pid_t pid_ = -1;
  int out_ = -1;
  bool reaped_ = false;
  std::string output_;
};

const char* kInertia = "<inertia ixx='0.016' iyy='0.016' izz='0.016' ixy='0' ixz='0' iyz='0'/>";

/// A 0.2 m cube as an OBJ: at the finest grid a mesh may have (256 cells a
/// side, 17 million samples), its distance grid takes a second or more to
/// build (a 100,000-triangle sphere took seconds before the grid was built
/// through a tree, and takes 0.1 s now).
void writeCube(const std::filesystem::path& path) {
  std::ofstream obj(path);
  for (int i = 0; i < 8; ++i)
    obj << "v " << (i & 1 ? 0.1 : -0.1) << ' ' << (i & 2 ? 0.1 : -0.1) << ' ' << (i & 4 ? 0.1 : -0.1) << '\n';
  for (const char* f :
       {"1 3 2", "2 3 4", "5 6 7", "6 8 7", "1 2 5", "2 6 5", "3 7 4", "4 7 8", "1 5 3", "3 5 7", "2 4 6", "4 8 6"}) {
    obj << "f " << f << '\n';
  }
}

XmlRpc::XmlRpcValue body(const std::string& name, const std::string& urdf, double x) {
  XmlRpc::XmlRpcValue b, initial, position;
  b["name"] = name;
  b["urdf"] = urdf;
  position[0] = x;
  position[1] = 0.0;
  position[2] = 0.5;
  initial["position"] = position;
  b["initial"] = initial;
  return b;
}

TEST(StartUp, SigintWhileLoadingEndsTheNodeAtOnce) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("rbs_startup_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  // Four bodies of four URDFs, each its own grid to build: seconds in all.
  writeCube(dir / "cube.obj");
  XmlRpc::XmlRpcValue bodies;
  for (int i = 0; i < 4; ++i) {
    const std::string urdf = (dir / ("cube" + std::to_string(i) + ".urdf")).string();
    std::ofstream(urdf) << "<robot name='cube'><link name='base'><inertial><mass value='1'/>" << kInertia
                        << "</inertial><collision><geometry><mesh filename='" << (dir / "cube.obj").string()
                        << "'/></geometry></collision></link></robot>";
    bodies[i] = body(std::string(1, static_cast<char>('a' + i)), urdf, 1.0 * i);
  }
  ros::param::set("/loading/sim_node/bodies", bodies);
  ros::param::set("/loading/sim_node/solver/mesh_grid_resolution", 256);
  Child node("/loading");
  ASSERT_TRUE(node.waitFor("loading the world", 30.0)) << node.output();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // inside the load (seconds long)
  node.signal(SIGINT);
  const int status = node.finish(30.0);
  ASSERT_NE(status, -1) << "still running 30 s after SIGINT:\n" << node.output();
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status) << ":\n" << node.output();
  EXPECT_EQ(WEXITSTATUS(status), 130) << node.output();
  EXPECT_NE(node.output().find("interrupted while loading the world"), std::string::npos) << node.output();
  // It ended inside the load: nothing after it ran.
  EXPECT_EQ(node.output().find("simulation keys given"), std::string::npos) << node.output();
  std::filesystem::remove_all(dir);
}

TEST(StartUp, SigintWhileRunningStopsTheNodeCleanly) {
  ros::param::set(
      "/running/robot_description",
      "<robot name='r'><link name='base'><inertial><mass value='1'/>" + std::string(kInertia) +
          "</inertial><collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision></link></robot>");
  Child node("/running");
  ASSERT_TRUE(node.waitFor("simulation keys given", 30.0)) << node.output();
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // stepping and publishing
  node.signal(SIGINT);
  const int status = node.finish(30.0);
  ASSERT_NE(status, -1) << "still running 30 s after SIGINT:\n" << node.output();
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status) << ":\n" << node.output();
  EXPECT_EQ(WEXITSTATUS(status), 0) << node.output();
}

}  // namespace
}  // namespace rbs_test
