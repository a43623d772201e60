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

#include "rbsim_run.h"

namespace rigid_body_sim::test {
namespace {

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
  expectUsageError("--urdf " + bad + " --duration 1", "link 'base' has a total mass of 0 kg");
  expectUsageError("--urdf " + bad + " --set urdf.repair=false --duration 1", "link 'base' has no <inertial>");
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

// A body's velocity driver commanded by a timeline (issue 57: rbsim ran
// none): the box floating in zero gravity, told 0.3 m/s ahead and 0.5 rad/s
// about its z at every step from 0.2 s to 1.2 s. The PI driver holds both
// (its integral takes up the turning frame's 0.15 N), so at 1.2 s it moves
// at 0.3 m/s along its heading; with no command it never moves.
TEST(Rbsim, ATimelineDrivesABodysVelocityDriver) {
  const std::string box = "--urdf " + kBox + " --set gravity=[0,0,0] --set scene=[] --set 'cmd_vel={}' --quiet";
  const Result r = rbsim(box +
                         " --set 'timeline=[{t: 0.2, until: 1.2, body: base_link, cmd_vel: {linear: [0.3, 0, 0], "
                         "angular: [0, 0, 0.5]}}]' --duration 1.2");
  ASSERT_EQ(r.code, 0) << r.err;
  const YAML::Node end = YAML::Load(r.out)["final"];
  const std::vector<double> v = seq(end["linear_velocity"]), w = seq(end["angular_velocity"]),
                            q = seq(end["quaternion"]);
  const double heading = 2.0 * std::atan2(q[2], q[3]);
  EXPECT_NEAR(w[2], 0.5, 1e-4);
  EXPECT_NEAR(v[0], 0.3 * std::cos(heading), 1e-4);
  EXPECT_NEAR(v[1], 0.3 * std::sin(heading), 1e-4);
  EXPECT_NEAR(heading, 0.5, 0.05);  // 0.5 rad/s for 1 s, less the driver's start
  const Result idle = rbsim(box + " --duration 1.2");
  ASSERT_EQ(idle.code, 0) << idle.err;
  EXPECT_EQ(seq(YAML::Load(idle.out)["final"]["linear_velocity"]), (std::vector<double>{0, 0, 0}));
}

}  // namespace
}  // namespace rigid_body_sim::test
