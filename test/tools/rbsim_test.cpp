// rbsim end to end: what a user running the binary gets (JSON, CSV, exit codes).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../scratch_dir.h"

namespace rigid_body_sim::test {
namespace {

struct Result {
  int code = -1;
  std::string out, err;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string tempPath(const std::string& name) { return (scratch().path() / name).string(); }

/// Runs rbsim with `args`; killed after 60 s (exit code 124) so that a hang fails instead of stalling.
Result rbsim(const std::string& args, const std::string& folder = "") {
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

const std::string kBox = std::string(RBS_SOURCE_DIR) + "/urdf/box.urdf";

void expectUsageError(const std::string& args, const std::string& message);

std::vector<double> seq(const YAML::Node& n) { return n.as<std::vector<double>>(); }

TEST(Rbsim, PrintsOneJsonLineWithTheRunsFigures) {
  const Result r = rbsim("--urdf " + kBox + " --set initial.position=[0,0,10] --duration 1 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1);
  EXPECT_TRUE(r.err.empty()) << r.err;
  const YAML::Node j = YAML::Load(r.out);  // JSON is YAML
  EXPECT_EQ(j["steps"].as<long>(), 1000);
  EXPECT_NEAR(j["sim_time"].as<double>(), 1.0, 1e-12);
  EXPECT_GT(j["wall_s"].as<double>(), 0.0);
  EXPECT_GT(j["ns_per_step"].as<double>(), 0.0);
  // Free fall from 10 m for 1 s with Euler-Cromer: z = 10 − ½ g t² − ½ g Δt t.
  const auto p = seq(j["final"]["position"]);
  EXPECT_NEAR(p[2], 10.0 - 0.5 * 9.81 - 0.5 * 9.81 * 1e-3, 1e-9);
  EXPECT_EQ(seq(j["final"]["quaternion"]), (std::vector<double>{0, 0, 0, 1}));
  EXPECT_NEAR(seq(j["final"]["linear_velocity"])[2], -9.81, 1e-10);
  EXPECT_EQ(seq(j["final"]["angular_velocity"]), (std::vector<double>{0, 0, 0}));
  EXPECT_NEAR(j["energy"]["start"].as<double>(), 1.0 * 9.81 * 10.0, 1e-12);
  // Euler-Cromer's energy error in free fall: ½ m g² Δt t.
  EXPECT_NEAR(j["energy"]["end"].as<double>() - j["energy"]["start"].as<double>(), -0.5 * 9.81 * 9.81 * 1e-3, 1e-9);
  EXPECT_EQ(seq(j["angular_momentum"]["start"]), (std::vector<double>{0, 0, 0}));
}

TEST(Rbsim, SpinConfigConservesMomentumAndReadsOverrides) {
  const Result r = rbsim("--urdf " + kBox + " --config " + RBS_SOURCE_DIR +
                         "/config/spin.yaml --set initial.angular_velocity=[0.01,3,0] --duration 20 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const YAML::Node j = YAML::Load(r.out);
  const auto l0 = seq(j["angular_momentum"]["start"]), l1 = seq(j["angular_momentum"]["end"]);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(l1[i], l0[i], 1e-12);
  EXPECT_NEAR(j["energy"]["end"].as<double>() / j["energy"]["start"].as<double>(), 1.0, 1e-10);
  EXPECT_EQ(seq(j["final"]["position"]), (std::vector<double>{0, 0, 1}));  // gravity off in spin.yaml
}

TEST(Rbsim, ReportsPenetrationAndRestOfADroppedBox) {
  const Result r = rbsim("--urdf " + kBox +
                         " --set initial.position=[0,0,1] --set initial.rpy=[0.4,0.3,0.2]"
                         " --set initial.angular_velocity=[1,2,3] --duration 5 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const YAML::Node j = YAML::Load(r.out);
  EXPECT_TRUE(j["at_rest"].as<bool>());
  EXPECT_GE(j["max_penetration"].as<double>(), 0.0);
  EXPECT_LT(j["max_penetration"].as<double>(), 1e-3);
  const double z = seq(j["final"]["position"])[2];
  EXPECT_TRUE(std::abs(z - 0.05) < 1e-3 || std::abs(z - 0.1) < 1e-3 || std::abs(z - 0.2) < 1e-3) << z;
  // docs/rbsim.md's drop: the config names its body, no --urdf needed.
  const Result drop = rbsim("--config " + std::string(RBS_SOURCE_DIR) + "/config/drop.yaml --duration 5 --quiet");
  ASSERT_EQ(drop.code, 0) << drop.err;
  const YAML::Node d = YAML::Load(drop.out);
  EXPECT_TRUE(d["at_rest"].as<bool>());
  const double dz = seq(d["bodies"][0]["final"]["position"])[2];
  EXPECT_TRUE(std::abs(dz - 0.05) < 1e-3 || std::abs(dz - 0.1) < 1e-3 || std::abs(dz - 0.2) < 1e-3) << dz;
  // In the air the whole time: no contact, not at rest.
  const Result air = rbsim("--urdf " + kBox + " --set initial.position=[0,0,10] --duration 1 --quiet");
  const YAML::Node a = YAML::Load(air.out);
  EXPECT_FALSE(a["at_rest"].as<bool>());
  EXPECT_EQ(a["max_penetration"].as<double>(), 0.0);
}

TEST(Rbsim, RunsAWorldOfBodiesFromTheConfig) {
  const std::string csv = tempPath("world.csv");
  const Result r = rbsim("--config " + std::string(RBS_SOURCE_DIR) +
                         "/config/world.yaml --duration 5 --every 1000 --csv " + csv + " --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const YAML::Node j = YAML::Load(r.out);
  ASSERT_EQ(j["bodies"].size(), 4u);
  EXPECT_EQ(j["bodies"][1]["name"].as<std::string>(), "ball");
  EXPECT_FALSE(j["final"]);  // per body, under bodies
  EXPECT_TRUE(j["at_rest"].as<bool>());
  // Written a body at a time, and still the bytes of one object's dump.
  const auto object = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(object.dump() + "\n", r.out);
  EXPECT_EQ(object.back().size(), 4u);  // the bodies, last
  EXPECT_LT(j["max_penetration"].as<double>(), 2e-3);
  // The ball came down on the box: it rests on its top face, 0.1 + 0.1 m up.
  EXPECT_NEAR(seq(j["bodies"][1]["final"]["position"])[2], 0.2, 1e-3);
  for (const auto& body : j["bodies"]) EXPECT_TRUE(body["at_rest"].as<bool>()) << body["name"].as<std::string>();
  // A tenth of a second in, the ball is still falling: it says so, and so does the whole.
  const Result early = rbsim("--config " + std::string(RBS_SOURCE_DIR) + "/config/world.yaml --duration 0.1 --quiet");
  ASSERT_EQ(early.code, 0) << early.err;
  const YAML::Node e = YAML::Load(early.out);
  EXPECT_FALSE(e["bodies"][1]["at_rest"].as<bool>());
  EXPECT_FALSE(e["at_rest"].as<bool>());
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t,body,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz");
  int rows = 0;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 6 * 4);  // t = 0, 1, ..., 5 s for four bodies
  expectUsageError("--urdf " + kBox + " --config " + std::string(RBS_SOURCE_DIR) + "/config/world.yaml --duration 1",
                   "give one or the other");
}

TEST(Rbsim, AWorldsRelativeUrdfIsFoundFromAnyFolder) {
  // The config given by a relative path, its URDF relative to it: the
  // folder was joined twice ("worlds/worlds/urdf/box.urdf").
  const std::filesystem::path dir = scratch().path() / "worlds";
  std::filesystem::create_directories(dir / "urdf");
  std::filesystem::copy_file(kBox, dir / "urdf" / "box.urdf", std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "world.yaml") << "bodies:\n  - {name: a, urdf: urdf/box.urdf, initial: {position: [0, 0, 1]}}\n";
  const Result r = rbsim("--config worlds/world.yaml --duration 0.1 --quiet", scratch().path().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(YAML::Load(r.out)["bodies"][0]["name"].as<std::string>(), "a");
}

TEST(Rbsim, RefusesABodyNameThatSpawnBodyWouldRefuse) {
  // One rule for names (letters, digits, '_'): quotes, a backslash and
  // control characters once went into the JSON line (escaped), and a/b into
  // the node's topics, where spawn_body refused the same names.
  const std::string config = tempPath("names.yaml");
  for (const std::string name : {"\"say \\\"hi\\\" \\\\ back\"", "\"tab\\tand\\x01\"", "a/b"}) {
    std::ofstream(config) << "scene: []\nbodies:\n  - {name: " << name << ", urdf: " << kBox << "}\n";
    const Result r = rbsim("--config " + config + " --duration 0.01 --quiet");
    EXPECT_NE(r.code, 0) << name;
    EXPECT_NE(r.err.find("bodies[0].name"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("starts with a letter"), std::string::npos) << r.err;
  }
}

TEST(Rbsim, HugeCountsAreSafe) {
  // Issue 13: --every 1e300 overflowed a long long and never ended; --duration 1e300 overflowed the step count.
  const std::string csv = tempPath("every.csv");
  const Result every = rbsim("--urdf " + kBox + " --duration 0.01 --every 1e300 --csv " + csv + " --quiet");
  ASSERT_EQ(every.code, 0) << every.err;
  const std::string rows = slurp(csv);
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 3) << rows;  // the header, t = 0 and the final state
  const Result duration = rbsim("--urdf " + kBox + " --duration 1e300 --quiet");
  EXPECT_EQ(duration.code, 2) << duration.err;
  EXPECT_NE(duration.err.find("--duration 1.0000000000000001e+300 is"), std::string::npos) << duration.err;
  EXPECT_NE(duration.err.find("at most 1000000000000 steps"), std::string::npos) << duration.err;
}

TEST(Rbsim, AFailedWriteIsAnError) {
  // Issue 13: --csv /dev/full exited 0 with nothing written.
  const Result r = rbsim("--urdf " + kBox + " --duration 0.1 --csv /dev/full --quiet");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--csv: writing '/dev/full' failed: No space left on device"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;  // no figures for a run whose output is lost
}

TEST(Rbsim, WritesTheCsvEveryNStepsAndTheFinalState) {
  const std::string csv = tempPath("traj.csv");
  const Result r = rbsim("--urdf " + kBox + " --duration 0.1 --dt 0.01 --every 3 --csv " + csv + " --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz");
  std::vector<double> times;
  while (std::getline(in, line)) {
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 13) << line;
    times.push_back(std::stod(line.substr(0, line.find(','))));
  }
  // Steps 0, 3, 6, 9 and the final step 10.
  ASSERT_EQ(times.size(), 5u);
  EXPECT_NEAR(times[1], 0.03, 1e-12);
  EXPECT_NEAR(times.back(), 0.1, 1e-12);
}

TEST(Rbsim, PrintsAReadableSummaryOnStderr) {
  const Result r = rbsim("--urdf " + kBox + " --duration 0.5");
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.err.find("rbsim: 'base_link' (1 kg) for 0.5 s: 500 steps"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("energy"), std::string::npos);
}

void expectUsageError(const std::string& args, const std::string& message) {
  const Result r = rbsim(args);
  EXPECT_EQ(r.code, 2) << args;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("rbsim: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << "'" << message << "' not in: " << r.err;
}

TEST(Rbsim, BadInputIsOneLineAndExitCodeTwo) {
  expectUsageError("--duration 1", "--urdf FILE is required");
  expectUsageError("--urdf " + kBox, "--duration S is required");
  expectUsageError("--urdf " + kBox + " --duration -1", "--duration: expected a number > 0, got '-1'");
  expectUsageError("--urdf " + kBox + " --duration 1 --every 2.5", "--every: expected a whole number");
  expectUsageError("--urdf " + kBox + " --duration 1 --frobnicate 3", "unknown argument '--frobnicate'");
  expectUsageError("--urdf " + kBox + " --duration 1 --bogus", "unknown argument '--bogus'");  // last, no value
  expectUsageError("--urdf " + kBox + " --duration", "--duration: missing value");
  expectUsageError("--urdf /nonexistent.urdf --duration 1", "URDF '/nonexistent.urdf': no such file");
  expectUsageError("--urdf " + kBox + " --config /nonexistent.yaml --duration 1",
                   "config '/nonexistent.yaml': no such file");
  expectUsageError("--urdf " + kBox + " --set dampign.linear=1 --duration 1", "config key 'dampign'");
  expectUsageError("--urdf " + kBox + " --set dt=-1 --duration 1", "dt = -1");
  expectUsageError("--urdf " + kBox + " --duration 0.0001", "shorter than one step");
  // The URDF loader's refusals carry the link name through.
  const std::string bad = tempPath("bad.urdf");
  std::ofstream(bad) << "<robot name='r'><link name='base'/></robot>";
  expectUsageError("--urdf " + bad + " --duration 1", "link 'base' has no <inertial>");
}

TEST(Rbsim, AbsurdMagnitudesAreRefusedNamingTheKey) {
  // Each ran to the end with null in the JSON before the physical ranges.
  expectUsageError("--urdf " + kBox + " --set initial.angular_velocity=[1e300,0,0] --duration 1",
                   "config key 'initial.angular_velocity': magnitude 1e+300 rad/s is above limits.max_angular_speed");
  expectUsageError("--urdf " + kBox + " --set gravity=[0,0,-1e308] --duration 1", "gravity = [0, 0, -1e+308]");
  expectUsageError("--urdf " + kBox + " --dt 300000 --duration 1e6", "dt = 300000: must be within [1e-06, 0.1] s");
  expectUsageError("--urdf " + kBox +
                       " --set contact.method=penalty_quadratic --set contact.penalty_stiffness=1e300 "
                       "--duration 1",
                   "contact.penalty_stiffness = 1e+300");
  expectUsageError("--urdf " + kBox + " --set contact.sample_spacing=1e-12 --duration 1",
                   "contact.sample_spacing = 1e-12");
  // The bunny at 1e7 m/s in a world crashed rbsim in the distance grid.
  const std::string fast = tempPath("fast_world.yaml");
  std::ofstream(fast) << "bodies:\n"
                         "  - {name: box, urdf: "
                      << kBox
                      << "}\n"
                         "  - {name: bunny, urdf: "
                      << RBS_SOURCE_DIR
                      << "/urdf/bunny.urdf,\n"
                         "     initial: {position: [-0.6, 0.2, 0.6], linear_velocity: [1, 0, 1e7]}}\n";
  expectUsageError(
      "--config " + fast + " --duration 1",
      "config key 'bodies[1].initial.linear_velocity': magnitude 1e+07 m/s is above limits.max_linear_speed = 500 m/s");
}

TEST(Rbsim, ABodyHeldByTheSpeedLimitsIsNamedOnce) {
  const Result r =
      rbsim("--urdf " + kBox + " --set scene=[] --set initial.linear_velocity=[0,0,-499.99] --duration 0.1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"speed_limited\":[\"base_link\"]"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("rbsim: warning: body 'base_link' reached the speed limits at t = 0.002 s"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("warning", r.err.find("warning") + 1), std::string::npos) << r.err;  // once
  const Result slow = rbsim("--urdf " + kBox + " --set scene=[] --duration 0.1");
  EXPECT_NE(slow.out.find("\"speed_limited\":[]"), std::string::npos) << slow.out;
}

// A robot: the shipped rod pendulum released from horizontal comes back
// after its closed-form period, 4 √(I/(m g l)) K(sin(θ₀/2)); the JSON gives
// final.joints.pivot, the CSV the joint's columns.
TEST(Rbsim, RunsARobotAndReportsItsJoints) {
  const double I = 1.0 / 12.0, m = 1.0, l = 0.25, g = 9.81;
  const double period = 4.0 * std::sqrt(I / (m * g * l)) * std::comp_ellint_1(std::sin(M_PI / 4.0));
  const double duration = std::round(period * 1e3) / 1e3;  // whole steps: off by ≤ 0.5 ms at the turning point
  const std::string csv = tempPath("robot.csv");
  const Result r = rbsim("--urdf " + std::string(RBS_SOURCE_DIR) +
                         "/urdf/pendulum.urdf --set 'initial.joint_positions={pivot: 1.5707963267948966}' --duration " +
                         std::to_string(duration) + " --every 100 --csv " + csv + " --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const YAML::Node j = YAML::Load(r.out);
  const YAML::Node pivot = j["final"]["joints"]["pivot"];
  // ½ θ̈ δt² with θ̈ = m g l / I = 29.4 rad/s² and δt ≤ 0.5 ms: 4e-6 rad, and the step's own phase error.
  EXPECT_NEAR(pivot["position"].as<double>(), M_PI / 2.0, 2e-3);
  EXPECT_NEAR(pivot["velocity"].as<double>(), 0.0, 0.03);  // θ̈ δt
  EXPECT_EQ(j["bodies"][0]["name"].as<std::string>(), "pendulum");
  EXPECT_NEAR(j["energy"]["end"].as<double>(), j["energy"]["start"].as<double>(), 1e-3 * m * g * l);
  const std::string rows = slurp(csv);
  EXPECT_EQ(rows.substr(0, rows.find('\n')), "t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz,pivot.position,pivot.velocity");
  EXPECT_NE(rows.find("\n0,0,0,0,0,0,0,1,0,0,0,0,0,0,1.57079632679,0\n"), std::string::npos) << rows;
}

// The shipped four-wheeled base, its wheels spun at 10 rad/s on the ground:
// they slip until it rolls, then it rolls at ω r.
TEST(Rbsim, AFourWheeledBaseRollsAtOmegaR) {
  const Result r = rbsim("--urdf " + std::string(RBS_SOURCE_DIR) +
                         "/urdf/four_wheeler.urdf --set initial.position=[0,0,0.1] --set "
                         "'initial.joint_velocities={front_left_axle: 10, front_right_axle: 10, rear_left_axle: 10, "
                         "rear_right_axle: 10}' --duration 2 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const YAML::Node j = YAML::Load(r.out);
  const double speed = seq(j["final"]["linear_velocity"])[0];
  EXPECT_GT(speed, 0.1);
  for (const char* wheel : {"front_left_axle", "front_right_axle", "rear_left_axle", "rear_right_axle"}) {
    EXPECT_NEAR(speed, 0.1 * j["final"]["joints"][wheel]["velocity"].as<double>(), 1e-3 * speed) << wheel;
  }
  EXPECT_NEAR(seq(j["final"]["position"])[2], 0.1, 1e-4);
  EXPECT_LT(j["max_penetration"].as<double>(), 1e-4);
}

TEST(Rbsim, RefusesARobotsBadStart) {
  const std::string pendulum = " --urdf " + std::string(RBS_SOURCE_DIR) + "/urdf/pendulum.urdf --duration 1";
  expectUsageError(pendulum + " --set initial.linear_velocity=[1,0,0]",
                   "'initial.linear_velocity' / 'initial.angular_velocity': robot 'pendulum' is fixed to the world");
  expectUsageError(pendulum + " --set 'initial.joint_positions={elbow: 1}'", "elbow");
  expectUsageError(
      pendulum + " --set 'controllers={a: {type: effort_controllers/JointEffortController, joint: pivot}}'",
      "'controllers': rbsim runs no controllers");
  const std::string world = tempPath("robot_world.yaml");
  std::ofstream(world) << "bodies:\n  - {name: swing, urdf: " << RBS_SOURCE_DIR
                       << "/urdf/pendulum.urdf, initial: {angular_velocity: [0, 1, 0]}}\n";
  expectUsageError("--config " + world + " --duration 1", "'bodies[0].initial.linear_velocity'");
}

// The shipped world of robots and bodies: each entry in the config's
// order, a robot's with its joints; the pendulum strikes the ball forward,
// the rover rolls into the crate and stops against it.
TEST(Rbsim, RunsAWorldOfRobotsAndBodies) {
  const std::string csv = tempPath("scene.csv");
  const Result r = rbsim("--config " + std::string(RBS_SOURCE_DIR) + "/config/robots.yaml --duration 3 --every 500 " +
                         "--csv " + csv + " --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const YAML::Node j = YAML::Load(r.out);
  const YAML::Node bodies = j["bodies"];
  ASSERT_EQ(bodies.size(), 4u);
  const std::vector<std::string> names{"pendulum", "ball", "rover", "crate"};
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(bodies[i]["name"].as<std::string>(), names[i]);
  EXPECT_TRUE(bodies[0]["final"]["joints"]["pivot"]["position"].IsDefined());
  EXPECT_FALSE(bodies[1]["final"]["joints"].IsDefined());
  EXPECT_GT(seq(bodies[1]["final"]["linear_velocity"])[0], 0.3);  // struck forward, rolling
  EXPECT_EQ(bodies[2]["final"]["joints"].size(), 4u);
  EXPECT_TRUE(bodies[3]["at_rest"].as<bool>());
  EXPECT_GT(seq(bodies[3]["final"]["position"])[0], 0.6);  // pushed a little
  EXPECT_LT(j["max_penetration"].as<double>(), 1e-4);
  // The CSV: a row per entry, the robots' joints as ROBOT/JOINT columns,
  // empty on every other entry's row.
  std::istringstream rows(slurp(csv));
  std::string header, first, second;
  std::getline(rows, header);
  std::getline(rows, first);
  std::getline(rows, second);
  EXPECT_EQ(header.substr(0, header.find(",pendulum/pivot.position")), "t,body,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz");
  EXPECT_NE(header.find(",rover/rear_right_axle.velocity"), std::string::npos) << header;
  const auto fields = [](const std::string& line) { return std::count(line.begin(), line.end(), ',') + 1; };
  EXPECT_EQ(fields(first), fields(header));
  EXPECT_EQ(fields(second), fields(header));
  EXPECT_EQ(first.rfind("0,pendulum,", 0), 0u) << first;
  EXPECT_NE(first.find(",1.57079632679,0,"), std::string::npos) << first;
  EXPECT_EQ(second.substr(second.size() - 11), "0" + std::string(10, ',')) << second;  // 5 joints, none its own
}

// A robot among bodies it never touches moves exactly as it does alone.
TEST(Rbsim, ARobotAmongBodiesItDoesNotTouchMovesAsAlone) {
  const std::string pendulum = std::string(RBS_SOURCE_DIR) + "/urdf/pendulum.urdf";
  const Result alone =
      rbsim("--urdf " + pendulum + " --set 'initial.joint_positions={pivot: 1.5707963267948966}' --duration 2 --quiet");
  ASSERT_EQ(alone.code, 0) << alone.err;
  const std::string world = tempPath("apart.yaml");
  std::ofstream(world) << "bodies:\n  - {name: pendulum, urdf: " << pendulum
                       << ", initial: {joint_positions: {pivot: 1.5707963267948966}}}\n  - {name: box, urdf: " << kBox
                       << ", initial: {position: [3, 0, 0.05]}}\n";
  const Result both = rbsim("--config " + world + " --duration 2 --quiet");
  ASSERT_EQ(both.code, 0) << both.err;
  const YAML::Node a = YAML::Load(alone.out)["final"]["joints"]["pivot"];
  const YAML::Node b = YAML::Load(both.out)["bodies"][0]["final"]["joints"]["pivot"];
  EXPECT_EQ(a["position"].as<double>(), b["position"].as<double>());
  EXPECT_EQ(a["velocity"].as<double>(), b["velocity"].as<double>());
}

}  // namespace
}  // namespace rigid_body_sim::test
