// rbsim end to end with robots: the rod pendulum's period, the wheeled
// base rolling at ω r, a world of robots and bodies, and the refusals.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../test_util.h"
#include "rbsim_run.h"

namespace rigid_body_sim::test {
namespace {

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

// A floating robot started in the ground (issue 44): the four-wheeled base
// at its zero pose, z = 0, its wheels (radius 0.1 m) 100 mm deep. rbsim says
// so with the depth, and the position stage lifts it out without giving it
// speed: no velocity at any step, at rest on its wheels, its energy up by
// the lift's M g Δz and no more (M = 5 + 4 × 0.5 kg).
TEST(Rbsim, AFloatingRobotStartedInTheGroundIsWarnedAndLiftedWithoutSpeed) {
  const std::string csv = tempPath("lifted.csv");
  const Result r = rbsim("--urdf " + std::string(RBS_SOURCE_DIR) +
                         "/urdf/four_wheeler.urdf --duration 1 --every 1 --csv " + csv + " --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("robot 'four_wheeler' starts 100 mm inside the scene"), std::string::npos) << r.err;
  const YAML::Node j = YAML::Load(r.out);
  EXPECT_TRUE(j["at_rest"].as<bool>());
  const double lifted = seq(j["final"]["position"])[2];
  EXPECT_NEAR(lifted, 0.1, 2e-4);  // on its wheels, less the position slop
  const double mass = 7.0, g = 9.81;
  EXPECT_NEAR(j["energy"]["end"].as<double>() - j["energy"]["start"].as<double>(), mass * g * lifted, 1e-6);
  std::istringstream rows(slurp(csv));
  std::string line;
  std::getline(rows, line);  // t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz, then each wheel's position and velocity
  int count = 0;
  while (std::getline(rows, line)) {
    std::vector<double> x;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) x.push_back(std::stod(cell));
    ASSERT_EQ(x.size(), 22u) << line;
    for (int k = 8; k < 14; ++k) EXPECT_LT(std::abs(x[k]), 1e-9) << line;      // the base's twist
    for (int k = 15; k < 22; k += 2) EXPECT_LT(std::abs(x[k]), 1e-9) << line;  // the wheels' speeds
    ++count;
  }
  EXPECT_EQ(count, 1001);
}

// A link's surface from its Gazebo markup (issue 45): a sled (a 1 kg box,
// 0.4 × 0.2 × 0.1 m, with a flag on a vertical axis, so a robot) whose
// base says <mu1>0.2</mu1><mu2>0.3</mu2> slides v²/(2 μ g) with μ = 0.2 (the
// smaller, against the ground's 0.5 by the min rule), not 0.5's distance,
// given as text or, as PR2 and Husky give it, as a value attribute; a
// Gazebo user's "never slip" (mu1 1e15) loads, said once, read as 10 (the
// ground's 0.5 then rules); a <mu1> that is not a coefficient is refused
// naming the element.
TEST(Rbsim, ALinksGazeboFrictionIsItsSurfaces) {
  const auto sled = [](const std::string& markup) {
    const std::string path = tempPath("sled.urdf");
    std::ofstream(path) << "<robot name='sled'><link name='base'><inertial><mass value='1'/>"
                           "<inertia ixx='0.00417' iyy='0.01417' izz='0.01667' ixy='0' ixz='0' iyz='0'/></inertial>"
                           "<collision><geometry><box size='0.4 0.2 0.1'/></geometry></collision></link>"
                           "<link name='flag'><inertial><mass value='0.01'/>"
                           "<inertia ixx='1e-5' iyy='1e-5' izz='1e-5' ixy='0' ixz='0' iyz='0'/></inertial></link>"
                           "<joint name='mast' type='continuous'><parent link='base'/><child link='flag'/>"
                           "<axis xyz='0 0 1'/></joint>"
                        << markup << "</robot>";
    return rbsim("--urdf " + path +
                 " --set initial.position=[0,0,0.05] --set initial.linear_velocity=[2,0,0] --duration 2 --quiet");
  };
  const double g = 9.81, v = 2.0;
  for (const auto& [markup, mu] :
       {std::pair<std::string, double>{"<gazebo reference='base'><mu1>0.2</mu1><mu2>0.3</mu2></gazebo>", 0.2},
        {"<gazebo reference='base'><mu1 value='0.2'/><mu2 value='0.3'/></gazebo>", 0.2},
        {"<gazebo reference='base'><mu1>1e15</mu1></gazebo>", 0.5},
        {"", 0.5}}) {
    const Result r = sled(markup);
    ASSERT_EQ(r.code, 0) << r.err;
    if (markup.find("1e15") != std::string::npos) {
      EXPECT_NE(r.err.find("1 friction coefficient of Gazebo markup above 10 (a Gazebo user's 'never slip') read as "
                           "10, the largest here: <gazebo reference=\"base\"> <mu1> = '1e15'"),
                std::string::npos)
          << r.err;
    }
    const YAML::Node j = YAML::Load(r.out);
    const double slid = seq(j["final"]["position"])[0];
    EXPECT_NEAR(slid, v * v / (2.0 * mu * g), 0.02 * v * v / (2.0 * mu * g)) << "mu " << mu;
  }
  const Result bad = sled("<gazebo reference='base'><mu1>slippery</mu1></gazebo>");
  EXPECT_EQ(bad.code, 2) << bad.err;
  EXPECT_NE(bad.err.find("<gazebo reference=\"base\"> <mu1> = 'slippery': a friction coefficient must be a number "
                         ">= 0"),
            std::string::npos)
      << bad.err;
}

TEST(Rbsim, RefusesARobotsBadStart) {
  const std::string pendulum = " --urdf " + std::string(RBS_SOURCE_DIR) + "/urdf/pendulum.urdf --duration 1";
  expectUsageError(pendulum + " --set initial.linear_velocity=[1,0,0]",
                   "'initial.linear_velocity' / 'initial.angular_velocity': robot 'pendulum' is fixed to the world");
  expectUsageError(pendulum + " --set 'initial.joint_positions={elbow: 1}'", "elbow");
  // A timeline naming what the robot does not have, by its key.
  const std::string effort = " --set 'controllers={a: {type: effort_controllers/JointEffortController, joint: pivot}}'";
  for (const auto& [entry, refusal] : std::vector<std::pair<std::string, std::string>>{
           {"{t: 0, controller: b, command: [1]}",
            "'timeline[0].controller': robot 'pendulum' has no joint controller 'b'"},
           {"{t: 0, controller: a, command: [1, 2]}",
            "'timeline[0].command': 'a' takes 1 values (one per joint), got 2"},
           {"{t: 0, controller: a, command: []}", "'timeline[0].command': expected a list of numbers, got none"},
           {"{t: 0, controller: a, command: 1}", "'timeline[0].command': expected a list of numbers, got 1"},
           {"{t: 0, controller: a, command: [1, x]}", "'timeline[0].command[1]'"},
           {"{t: 0, controller: a, cmd_vel: {}}",
            "'timeline[0].controller': 'a' is a joint controller: give it a command, not a cmd_vel"},
           {"{t: 0, robot: arm, controller: a, command: [1]}", "'timeline[0].robot': no robot 'arm' in the world"},
           {"{t: 1, until: 0.5, controller: a, command: [1]}", "'timeline[0].until': must be after t"},
           {"{t: 1, controller: a}", "'timeline[0]': needs one of cmd_vel (a twist), command"},
           {"{t: 0, joint_effort: {joint_name: elbow, effort: 1, duration: 1}}",
            "'timeline[0].joint_effort.joint_name': robot 'pendulum' has no moving joint 'elbow'"},
           {"{t: 0, joint_effort: {joint_name: pivot, effort: 1, duration: 0}}",
            "'timeline[0].joint_effort.duration': must be > 0 (for that long) or < 0"},
           {"{t: 0, joint_effort: {joint_name: pivot, effort: 2e6, duration: 1}}",
            "'timeline[0].joint_effort.effort': must be within 1e6"},
           {"{t: 0, joint_effort: {joint_name: pivot, duration: 1}}",
            "'timeline[0].joint_effort.effort': every joint effort needs it"},
           {"{t: 0, until: 2, joint_effort: {joint_name: pivot, effort: 1, duration: 1}}",
            "'timeline[0].until': a joint effort lasts its joint_effort.duration"},
           {"{t: 0, command: [1], joint_effort: {joint_name: pivot, effort: 1, duration: 1}}",
            "'timeline[0]': needs one of"}}) {
    expectUsageError(pendulum + effort + " --set 'timeline=[" + entry + "]'", refusal);
  }
  // A world of bodies alone: a timeline drives their velocity drivers, and nothing else.
  const std::string driven = "--urdf " + kBox + " --duration 1 --set 'cmd_vel={}' --set 'timeline=[";
  for (const auto& [entry, refusal] : std::vector<std::pair<std::string, std::string>>{
           {"{t: 0, command: [1]}", "'timeline[0].robot': a world of 0 robots: name the one it is for"},
           {"{t: 0, robot: arm, cmd_vel: {}}", "'timeline[0].robot': no robot 'arm' in the world"},
           {"{t: 0, body: lid, cmd_vel: {}}", "'timeline[0].body': no free body 'lid' with a cmd_vel"},
           {"{t: 0, body: base_link, command: [1]}", "'timeline[0].body': a body takes a cmd_vel"},
           {"{t: 0, body: base_link, robot: arm, cmd_vel: {}}",
            "'timeline[0].robot': an entry is for a body or a robot"},
           {"{t: 0, body: base_link, controller: c, cmd_vel: {}}", "'timeline[0].controller': a body has one"},
           {"{t: 0, body: '', cmd_vel: {}}", "'timeline[0].body': expected a non-empty string"}}) {
    expectUsageError(driven + entry + "]'", refusal);
  }
  expectUsageError("--urdf " + kBox + " --duration 1 --set 'timeline=[{t: 0, body: base_link, cmd_vel: {}}]'",
                   "'timeline[0].body': no free body 'base_link' with a cmd_vel");
  // A body's cmd_vel with no timeline runs and says nothing of it (it was named as not run).
  const Result box =
      rbsim("--urdf " + kBox +
            " --set initial.position=[0,0,0.05] --set 'cmd_vel={}' --set 'imu={}' --duration 0.01 --quiet");
  EXPECT_EQ(box.code, 0) << box.err;
  EXPECT_TRUE(box.err.empty()) << box.err;
  expectUsageError("--urdf " + kBox + " --duration 1 --set initial.position=[0,0,0.05] --set 'imu={link: lid}'",
                   "config key 'imu.link' = 'lid': no such link of body 'base_link'");
  expectUsageError("--urdf " + kBox + " --duration 1 --out /tmp", "--out: no body has a device");
  const std::string world = tempPath("robot_world.yaml");
  std::ofstream(world) << "bodies:\n  - {name: swing, urdf: " << RBS_SOURCE_DIR
                       << "/urdf/pendulum.urdf, initial: {angular_velocity: [0, 1, 0]}}\n";
  expectUsageError("--config " + world + " --duration 1", "'bodies[0].initial.linear_velocity'");
}

// A robot's controllers run as the node runs them (issue 57): the shipped
// arm under the node's own config/arm2.yaml, its shoulder commanded to
// -0.5 rad at 0.5 s by a timeline, gets there within 10 s (the PID's integral takes the
// steady error away) while its elbow is held at 0 against gravity; the
// node's own keys are named, not refused.
TEST(Rbsim, RunsTheNodesControllersCommandedByATimeline) {
  const Result r =
      rbsim("--urdf " + std::string(RBS_SOURCE_DIR) + "/urdf/arm2.urdf --config " + std::string(RBS_SOURCE_DIR) +
            "/config/arm2.yaml --set 'timeline=[{t: 0.5, controller: shoulder_position_controller, "
            "command: [-0.5]}]' --duration 10 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("config keys 'rate', 'realtime_factor' are sim_node's own"), std::string::npos) << r.err;
  const YAML::Node joints = YAML::Load(r.out)["final"]["joints"];
  EXPECT_NEAR(joints["shoulder"]["position"].as<double>(), -0.5, 2e-4);  // 1.4e-5 measured
  EXPECT_NEAR(joints["elbow"]["position"].as<double>(), 0.0, 5e-4);      // 9e-5 measured
  // Without its controllers (a config of none) the arm falls: the test can fail.
  const Result limp = rbsim("--urdf " + std::string(RBS_SOURCE_DIR) + "/urdf/arm2.urdf --duration 6 --quiet");
  ASSERT_EQ(limp.code, 0) << limp.err;
  const YAML::Node fell = YAML::Load(limp.out)["final"]["joints"];
  EXPECT_GT(
      std::abs(fell["shoulder"]["position"].as<double>() + 0.5) + std::abs(fell["elbow"]["position"].as<double>()),
      0.1);
}

// A timeline's joint effort is apply_joint_effort's (issue 57: rbsim ran
// none): the shipped scenario (config/pendulum_effort_timeline.yaml) pushes
// the pendulum in zero gravity with 1 N·m for 0.5 s from half a step off
// the grid, and it leaves at τ d / I = 6 rad/s (I = 1/12 kg·m²); one with
// no end (duration < 0) pushes to the end of the run.
TEST(Rbsim, GivesATimelinesJointEffortsAsApplyJointEffort) {
  const std::string pendulum = "--urdf " + std::string(RBS_SOURCE_DIR) + "/urdf/pendulum.urdf";
  const Result r = rbsim(pendulum + " --config " + std::string(RBS_SOURCE_DIR) +
                         "/config/pendulum_effort_timeline.yaml --duration 1 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const YAML::Node pivot = YAML::Load(r.out)["final"]["joints"]["pivot"];
  EXPECT_NEAR(pivot["velocity"].as<double>(), 6.0, 1e-9);
  // 1.5 rad over the push (α d² / 2), then 6 rad/s for 0.2495 s; the steps' lag is α h d / 2 = 3 mrad.
  EXPECT_NEAR(pivot["position"].as<double>(), 1.5 + 6.0 * 0.2495, 4e-3);
  const Result held = rbsim(pendulum +
                            " --set gravity=[0,0,0] --set 'timeline=[{t: 0.5, joint_effort: {joint_name: pivot, "
                            "effort: -0.5, duration: -1}}]' --duration 2 --quiet");
  ASSERT_EQ(held.code, 0) << held.err;
  const YAML::Node pushed = YAML::Load(held.out)["final"]["joints"]["pivot"];
  EXPECT_NEAR(pushed["velocity"].as<double>(), -0.5 * 12.0 * 1.5, 1e-9);
  EXPECT_NEAR(pushed["position"].as<double>(), -0.5 * 6.0 * 1.5 * 1.5, 6e-3);
}

// A timeline's trajectory is a trajectory_msgs/JointTrajectory on
// CONTROLLER/command received at t (issue 57: a trajectory controller took
// no timeline entry): the shipped scenario (config/arm2_trajectory_timeline.yaml)
// names the arm's joints in another order than its controller's and sends
// it through [-0.25, 0.4] to [-0.5, 0.8] at rest 2 s after 0.5 s. The arm
// ends there (the PID's lag under gravity, 3.6 mrad at 3 s, 0.1 mrad at 6 s,
// measured); without the entry the controller holds it at its start (1.0 mrad
// from it at 6 s, measured).
TEST(Rbsim, GivesATimelinesTrajectoryToATrajectoryController) {
  const std::string arm = "--urdf " + std::string(RBS_SOURCE_DIR) + "/urdf/arm2.urdf --config " +
                          std::string(RBS_SOURCE_DIR) + "/config/arm2_trajectory_timeline.yaml --quiet";
  const Result r = rbsim(arm + " --duration 6");
  ASSERT_EQ(r.code, 0) << r.err;
  const YAML::Node joints = YAML::Load(r.out)["final"]["joints"];
  EXPECT_NEAR(joints["shoulder"]["position"].as<double>(), -0.5, 1e-3);
  EXPECT_NEAR(joints["elbow"]["position"].as<double>(), 0.8, 1e-3);
  // Halfway, 1 s after it was given, the arm is near the first waypoint, not yet at the last.
  const Result half = rbsim(arm + " --duration 1.5");
  ASSERT_EQ(half.code, 0) << half.err;
  const YAML::Node mid = YAML::Load(half.out)["final"]["joints"];
  EXPECT_NEAR(mid["shoulder"]["position"].as<double>(), -0.25, 0.05);
  EXPECT_NEAR(mid["elbow"]["position"].as<double>(), 0.4, 0.05);
  const Result held = rbsim(arm + " --set 'timeline=[]' --duration 6");
  ASSERT_EQ(held.code, 0) << held.err;
  const YAML::Node still = YAML::Load(held.out)["final"]["joints"];
  EXPECT_NEAR(still["shoulder"]["position"].as<double>(), 0.0, 0.01);
  EXPECT_NEAR(still["elbow"]["position"].as<double>(), 0.0, 0.01);
}

// A trajectory that does not fit its controller is refused at start, naming its field.
TEST(Rbsim, RefusesATimelinesTrajectoryThatDoesNotFit) {
  const std::string arm = "--urdf " + std::string(RBS_SOURCE_DIR) +
                          "/urdf/arm2.urdf --duration 1 --set 'controllers={arm_controller: {type: "
                          "effort_controllers/JointTrajectoryController, joints: [shoulder, elbow], gains: "
                          "{shoulder: {p: 400, d: 40}, elbow: {p: 200, d: 20}}}}'";
  const std::string both = "joint_names: [shoulder, elbow], points: ";
  for (const auto& [entry, refusal] : std::vector<std::pair<std::string, std::string>>{
           {"{t: 0, controller: arm_controller, command: [1, 2]}",
            "'timeline[0].command': 'arm_controller' follows trajectories: give it a trajectory, not a command"},
           {"{t: 0, controller: arm_controller, trajectory: {joint_names: [shoulder, wrist], points: [{positions: "
            "[0, 0], time_from_start: 1}]}}",
            "'timeline[0].trajectory': 'arm_controller': joint_names[1]: 'wrist' is not its joint"},
           {"{t: 0, controller: arm_controller, trajectory: {joint_names: [shoulder], points: [{positions: [0], "
            "time_from_start: 1}]}}",
            "'timeline[0].trajectory': 'arm_controller': joint_names has 1 names"},
           {"{t: 0, controller: arm_controller, trajectory: {" + both +
                "[{positions: [0, 0], time_from_start: 1}, {positions: [1, 1], time_from_start: 1}]}}",
            "'timeline[0].trajectory': 'arm_controller': points[1].time_from_start must be after the point before's"},
           {"{t: 0, controller: arm_controller, trajectory: {" + both + "[{positions: [0], time_from_start: 1}]}}",
            "'timeline[0].trajectory': 'arm_controller': points[0].positions has 1 values for 2 joints"},
           {"{t: 0, controller: arm_controller, trajectory: {" + both + "[{positions: [0, 0]}]}}",
            "'timeline[0].trajectory.points[0].time_from_start': every waypoint needs its time"},
           {"{t: 0, controller: arm_controller, trajectory: {" + both + "[{positions: [0, 0], time_from_start: -1}]}}",
            "'timeline[0].trajectory.points[0].time_from_start': must be within [0, 1e6] s"},
           {"{t: 0, controller: arm_controller, trajectory: {" + both +
                "[{positions: [0, 0], effort: [1, 1], time_from_start: 1}]}}",
            "'timeline[0].trajectory.points[0].effort': an effort trajectory controller takes no efforts"},
           {"{t: 0, controller: arm_controller, trajectory: {" + both + "[]}}",
            "'timeline[0].trajectory.points': expected a list of one or more waypoints"},
           {"{t: 0, until: 1, controller: arm_controller, trajectory: {" + both +
                "[{positions: [0, 0], time_from_start: 1}]}}",
            "'timeline[0].until': a trajectory runs by its points' times"},
           {"{t: 0, trajectory: {" + both + "[{positions: [0, 0], time_from_start: 1}]}}",
            "'timeline[0].controller': a trajectory is for a trajectory controller: name it"}}) {
    expectUsageError(arm + " --set 'timeline=[" + entry + "]'", refusal);
  }
  // A trajectory to a controller that follows none.
  expectUsageError("--urdf " + std::string(RBS_SOURCE_DIR) +
                       "/urdf/pendulum.urdf --duration 1 --set 'controllers={a: {type: "
                       "effort_controllers/JointEffortController, joint: pivot}}' --set 'timeline=[{t: 0, "
                       "controller: a, trajectory: {joint_names: [pivot], points: [{positions: [1], "
                       "time_from_start: 1}]}}]'",
                   "'timeline[0].trajectory': 'a' follows no trajectory: give it a command");
}

/// The rows of one of --out's files after its header, which is `header` if given.
std::vector<std::vector<double>> csvRows(const std::string& path, const std::string& header = "") {
  std::istringstream in(slurp(path));
  std::string line;
  std::getline(in, line);
  if (!header.empty()) {
    EXPECT_EQ(line, header) << path;
  }
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> x;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) x.push_back(std::stod(cell));
    rows.push_back(x);
  }
  return rows;
}

// The shipped scenario (config/diff_drive_timeline.yaml): a DiffDriveController
// on the differential-drive base, 0.5 m/s and 0.3 rad/s for 2 s, then a
// zero. Its odometry at 50 Hz from the start: the arc's speeds held at 2 s
// (the acceleration limits of 1 m/s^2 and 2 rad/s^2 took 0.5 s and 0.15 s,
// so the heading is 0.3 (2 - 0.075) less a step's lag), at rest at 3 s; the
// truth ends within 1 cm of it (the wheels roll on their rims' edges, a
// turn tightens, physics 11.12). Two runs write the same bits.
TEST(Rbsim, RunsATimelineScenarioAndWritesItsOdometry) {
  const std::string cmd = "--urdf " + std::string(RBS_SOURCE_DIR) + "/urdf/diff_drive.urdf --config " +
                          std::string(RBS_SOURCE_DIR) + "/config/diff_drive_timeline.yaml --duration 3 --quiet --out ";
  const std::string a = tempPath(""), file = "/diff_drive.base_controller.odom.csv";
  const Result r = rbsim(cmd + a);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("config keys 'paused' are sim_node's own"), std::string::npos) << r.err;
  const std::vector<std::vector<double>> rows = csvRows(a + file, "t,x,y,heading,linear,lateral,angular");
  ASSERT_EQ(rows.size(), 151u);  // 0, 0.02, ..., 3
  const std::vector<double>& at2 = rows[100];
  EXPECT_DOUBLE_EQ(at2[0], 2.0);
  EXPECT_NEAR(at2[4], 0.5, 1e-6);
  EXPECT_NEAR(at2[6], 0.3, 1e-3);
  EXPECT_NEAR(at2[3], 0.3 * (2.0 - 0.075), 2e-3);
  EXPECT_NEAR(rows.back()[4], 0.0, 1e-9);
  EXPECT_NEAR(rows.back()[6], 0.0, 1e-9);
  const std::vector<double> truth = seq(YAML::Load(r.out)["final"]["position"]);
  EXPECT_NEAR(std::hypot(truth[0] - rows.back()[1], truth[1] - rows.back()[2]), 0.0, 0.01);
  // Its IMU at 100 Hz from the first period's end: at rest at the end, the
  // mean of its last 0.5 s reads g up (σ 0.01 m/s^2 a sample: 0.0014 for the mean).
  const std::vector<std::vector<double>> imu_rows =
      csvRows(a + "/diff_drive.imu.csv", "t,qx,qy,qz,qw,wx,wy,wz,ax,ay,az");
  ASSERT_EQ(imu_rows.size(), 300u);
  EXPECT_DOUBLE_EQ(imu_rows.front()[0], 0.01);
  double az = 0.0;
  for (std::size_t i = 250; i < 300; ++i) az += imu_rows[i][10] / 50.0;
  EXPECT_NEAR(az, 9.81, 0.006);
  // The noisy odometry and its truth, at publish_rate, the truth as the JSON's final state.
  const std::string odometry = "t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz";
  const std::vector<std::vector<double>> noisy = csvRows(a + "/diff_drive.odom.csv", odometry),
                                         exact = csvRows(a + "/diff_drive.ground_truth.csv", odometry);
  ASSERT_EQ(noisy.size(), 300u);
  ASSERT_EQ(exact.size(), 300u);
  EXPECT_EQ(exact.back()[1], truth[0]);
  EXPECT_EQ(exact.back()[2], truth[1]);
  EXPECT_NE(noisy.back()[1], truth[0]);
  EXPECT_NEAR(noisy.back()[1], truth[0], 0.05);  // σ 0.01 m
  // The same bits again.
  const std::string b = tempPath("again");
  ASSERT_EQ(std::system(("mkdir -p " + b).c_str()), 0);
  ASSERT_EQ(rbsim(cmd + b).code, 0);
  for (const std::string& f : {file, std::string("/diff_drive.imu.csv"), std::string("/diff_drive.odom.csv")}) {
    EXPECT_EQ(slurp(a + f), slurp(b + f)) << f;
  }
}

/// m from (x, y) along heading θ to the first wall of a room whose inner
/// faces are at x = ±h and y = ±h.
double toWall(double x, double y, double theta, double h) {
  const double c = std::cos(theta), s = std::sin(theta);
  const double along_x = c > 0 ? (h - x) / c : (-h - x) / c, along_y = s > 0 ? (h - y) / s : (-h - y) / s;
  return std::min(along_x, along_y);
}

// A body's own devices run as in the node (issue 57: rbsim named them and
// ran none): the box at rest on the ground with an IMU at 100 Hz reads g
// up from the first period's end, and its noisy odometry at publish_rate
// (100 Hz) from the start has the configured σ about its truth. A body
// given alone is named by its root link, as in the JSON.
TEST(Rbsim, RunsABodysImuAndNoisyOdometry) {
  const auto run = [](const std::string& dir) {
    EXPECT_EQ(std::system(("mkdir -p " + dir).c_str()), 0);
    return rbsim("--urdf " + kBox +
                 " --set initial.position=[0,0,0.05] --set 'imu={rate: 100}'"
                 " --set 'odom_noise={position: 0.01, seed: 3}' --duration 2 --quiet --out " +
                 dir);
  };
  const std::string a = tempPath("body_devices");
  const Result r = run(a);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("rbsim does not yet"), std::string::npos) << r.err;
  const std::vector<std::vector<double>> imu = csvRows(a + "/base_link.imu.csv", "t,qx,qy,qz,qw,wx,wy,wz,ax,ay,az");
  ASSERT_EQ(imu.size(), 200u);
  EXPECT_DOUBLE_EQ(imu.front()[0], 0.01);
  EXPECT_NEAR(imu.back()[10], 9.81, 0.01);  // at rest, no noise configured: +g up in its axes
  const std::string odometry = "t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz";
  const std::vector<std::vector<double>> noisy = csvRows(a + "/base_link.odom.csv", odometry),
                                         exact = csvRows(a + "/base_link.ground_truth.csv", odometry);
  ASSERT_EQ(noisy.size(), 201u);  // t 0, 0.01, ..., 2
  ASSERT_EQ(exact.size(), 201u);
  EXPECT_DOUBLE_EQ(noisy.back()[0], 2.0);
  std::vector<double> dx;
  for (std::size_t i = 0; i < noisy.size(); ++i) {
    EXPECT_EQ(noisy[i][0], exact[i][0]);
    dx.push_back(noisy[i][1] - exact[i][1]);
  }
  const auto [mean, sd] = meanAndSigma(dx);
  EXPECT_NEAR(mean, 0.0, 0.0025);  // 3.5 standard errors of 201 samples
  EXPECT_NEAR(sd, 0.01, 0.002);
  // Two runs write the same bits.
  const std::string b = tempPath("body_devices_again");
  const Result again = run(b);
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(slurp(a + "/base_link.odom.csv"), slurp(b + "/base_link.odom.csv"));
  EXPECT_EQ(slurp(a + "/base_link.imu.csv"), slurp(b + "/base_link.imu.csv"));
}

// The shipped lidar scenario (config/diff_drive_lidar_timeline.yaml): the
// same drive in a room of 4 m by 4 m, its Gazebo markup's lidar (360 rays
// from -pi to pi at 10 Hz, no noise, 0.1 m ahead of the base and 0.07 m
// up) written scan by scan: the first from the start, the last from where
// the base came to rest, each ray the distance to the wall it points at
// from the lidar's place; two runs write the same bits.
TEST(Rbsim, RunsTheLidarScenarioAndWritesItsScans) {
  const std::string cmd = "--urdf " + std::string(RBS_SOURCE_DIR) + "/urdf/diff_drive_lidar.urdf --config " +
                          std::string(RBS_SOURCE_DIR) +
                          "/config/diff_drive_lidar_timeline.yaml --duration 3 --quiet --out ";
  const std::string a = tempPath("lidar");
  ASSERT_EQ(std::system(("mkdir -p " + a).c_str()), 0);
  const Result r = rbsim(cmd + a);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("rbsim does not yet"), std::string::npos) << r.err;  // the lidar is run, not set aside
  std::string header = "t";
  for (int k = 0; k < 360; ++k) header += ",r" + std::to_string(k);
  const std::vector<std::vector<double>> scans = csvRows(a + "/diff_drive_lidar.scan.csv", header);
  ASSERT_EQ(scans.size(), 30u);  // 0.1, 0.2, ..., 3
  EXPECT_DOUBLE_EQ(scans.front()[0], 0.1);
  EXPECT_DOUBLE_EQ(scans.back()[0], 3.0);
  const double increment = 2 * M_PI / 359;
  const auto expectScan = [&](const std::vector<double>& scan, double x, double y, double heading, double tolerance) {
    ASSERT_EQ(scan.size(), 361u);
    const double lx = x + 0.1 * std::cos(heading), ly = y + 0.1 * std::sin(heading);
    for (int k = 0; k < 360; ++k) {
      EXPECT_NEAR(scan[k + 1], toWall(lx, ly, heading - M_PI + k * increment, 2.0), tolerance) << k;
    }
  };
  // At 0.1 s from where its odometry puts it (a few mm on and mrad turned; the wheels' estimate, near the truth).
  const std::vector<std::vector<double>> odom =
      csvRows(a + "/diff_drive_lidar.base_controller.odom.csv", "t,x,y,heading,linear,lateral,angular");
  ASSERT_GT(odom.size(), 5u);
  ASSERT_DOUBLE_EQ(odom[5][0], 0.1);
  EXPECT_GT(odom[5][1], 0.001);
  EXPECT_LT(odom[5][1], 0.005);  // 1/2 a t^2 at most
  expectScan(scans.front(), odom[5][1], odom[5][2], odom[5][3], 2e-3);
  const YAML::Node final_state = YAML::Load(r.out)["final"];
  const std::vector<double> p = seq(final_state["position"]), q = seq(final_state["quaternion"]);
  expectScan(scans.back(), p[0], p[1], 2.0 * std::atan2(q[2], q[3]), 1e-3);
  const std::string b = tempPath("lidar_again");
  ASSERT_EQ(std::system(("mkdir -p " + b).c_str()), 0);
  ASSERT_EQ(rbsim(cmd + b).code, 0);
  for (const char* f : {"/diff_drive_lidar.scan.csv", "/diff_drive_lidar.base_controller.odom.csv"}) {
    EXPECT_EQ(slurp(a + f), slurp(b + f)) << f;
  }
}

// A depth camera added to the lidar scenario, on the lidar's link: its
// images at 10 Hz as PFM files beside a CSV naming them, each pixel the
// depth along the optical axis; the wall ahead fills the rows about the
// horizon, each pixel at the depth where its ray from the camera's place
// at 0.1 s (as the base's odometry puts it) meets the wall at x = 2 m.
TEST(Rbsim, WritesADepthCamerasImagesAsPfm) {
  const std::string a = tempPath("depth");
  ASSERT_EQ(std::system(("mkdir -p " + a).c_str()), 0);
  const Result r = rbsim("--urdf " + std::string(RBS_SOURCE_DIR) + "/urdf/diff_drive_lidar.urdf --config " +
                         std::string(RBS_SOURCE_DIR) +
                         "/config/diff_drive_lidar_timeline.yaml --duration 0.2 --quiet --set "
                         "'depth_camera={link: laser_link, width: 8, height: 6, hfov: 1.0, rate: 10, max_depth: 5}' "
                         "--out " +
                         a);
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream index(slurp(a + "/diff_drive_lidar.camera.depth.image_raw.csv"));
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(index, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "t,image");
  EXPECT_EQ(lines[1], "0.10000000000000001,diff_drive_lidar.camera.depth.image_raw.100.pfm");
  EXPECT_EQ(lines[2], "0.20000000000000001,diff_drive_lidar.camera.depth.image_raw.200.pfm");
  const std::string pfm = slurp(a + "/diff_drive_lidar.camera.depth.image_raw.100.pfm");
  const std::string header = "Pf\n8 6\n-1.0\n";
  ASSERT_EQ(pfm.size(), header.size() + 8 * 6 * sizeof(float));
  EXPECT_EQ(pfm.substr(0, header.size()), header);
  std::vector<float> depth(48);
  std::memcpy(depth.data(), pfm.data() + header.size(), depth.size() * sizeof(float));
  const std::vector<std::vector<double>> odom = csvRows(a + "/diff_drive_lidar.base_controller.odom.csv");
  ASSERT_GT(odom.size(), 5u);
  ASSERT_DOUBLE_EQ(odom[5][0], 0.1);
  const double heading = odom[5][3], x = odom[5][1] + 0.1 * std::cos(heading);
  const double focal = 4.0 / std::tan(0.5);  // (width / 2) / tan(hfov / 2)
  for (const int v : {2, 3}) {               // image rows about the horizon: PFM's rows 3 and 2 from the bottom
    for (int u = 0; u < 8; ++u) {
      const double left = -(u - 3.5) / focal;  // the ray (1, left, up) in the camera's axes, x ahead
      const double expected = (2.0 - x) / (std::cos(heading) - left * std::sin(heading));
      EXPECT_NEAR(depth[static_cast<std::size_t>((5 - v) * 8 + u)], expected, 5e-4) << u << ", " << v;
    }
  }
}

// The force sensors of Gazebo markup, run as the node runs them. A bar
// held level on its shoulder by a JointPositionController
// (test/ros/ft_sensor.urdf's gazebo_ros_ft_sensor, 100 Hz): the joint
// carries its weight, 1 kg, and its moment, m g 0.3 m, in the bar's axes.
// A four-wheeled base at rest on the ground (test/ros/skid_steer.urdf's
// gazebo_ros_bumper on each wheel, 20 Hz, in the world's frame): the
// wheels' contacts bear its 7.01 kg; the chassis touches nothing.
TEST(Rbsim, WritesForceTorqueAndContactSensorsSamples) {
  const std::string src = RBS_SOURCE_DIR;
  const std::string a = tempPath("forces");
  ASSERT_EQ(std::system(("mkdir -p " + a).c_str()), 0);
  const Result held = rbsim("--urdf " + src +
                            "/test/ros/ft_sensor.urdf --duration 3 --quiet --set 'controllers={shoulder_hold: {type: "
                            "effort_controllers/JointPositionController, joint: shoulder, pid: {p: 400, i: 400, d: 20, "
                            "i_clamp: 50}}}' --out " +
                            a);
  ASSERT_EQ(held.code, 0) << held.err;
  const std::vector<std::vector<double>> ft = csvRows(a + "/ft_arm.ft.csv", "t,fx,fy,fz,tx,ty,tz");
  ASSERT_EQ(ft.size(), 300u);  // 100 Hz for 3 s
  EXPECT_DOUBLE_EQ(ft.front()[0], 0.01);
  EXPECT_NEAR(ft.back()[1], 0.0, 0.01);
  EXPECT_NEAR(ft.back()[3], 9.81, 0.01);
  EXPECT_NEAR(ft.back()[5], -9.81 * 0.3, 0.01);

  const Result rests = rbsim(
      "--urdf " + src + "/test/ros/skid_steer.urdf --set initial.position=[0,0,0.1] --duration 1 --quiet --out " + a);
  ASSERT_EQ(rests.code, 0) << rests.err;
  double bearing = 0.0;
  for (const char* wheel : {"front_left_wheel", "front_right_wheel", "rear_left_wheel", "rear_right_wheel"}) {
    std::istringstream lines(slurp(a + "/skid_steer." + wheel + ".contacts.jsonl"));
    std::string line, last;
    int samples = 0;
    while (std::getline(lines, line)) {
      last = line;
      ++samples;
    }
    EXPECT_EQ(samples, 20) << wheel;  // its <update_rate> of 20 Hz
    const YAML::Node at_end = YAML::Load(last);
    EXPECT_DOUBLE_EQ(at_end["t"].as<double>(), 1.0);
    ASSERT_EQ(at_end["contacts"].size(), 1u) << wheel << ": " << last;
    const YAML::Node c = at_end["contacts"][0];
    EXPECT_EQ(c["body"].as<std::string>(), std::string("skid_steer/") + wheel);
    EXPECT_TRUE(c["other"].IsNull());
    EXPECT_EQ(c["scene_item"].as<int>(), 0);  // the ground
    EXPECT_NEAR(seq(c["normal"])[2], 1.0, 1e-6);
    bearing += seq(c["normal_force"])[2];
  }
  EXPECT_NEAR(bearing, 7.01 * 9.81, 0.01 * 7.01 * 9.81);
  std::istringstream chassis(slurp(a + "/skid_steer.chassis.contacts.jsonl"));
  std::string first;
  ASSERT_TRUE(std::getline(chassis, first));
  EXPECT_EQ(YAML::Load(first)["contacts"].size(), 0u);
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

// A body's velocity driver among robots, commanded by the timeline: the
// box beside a pendulum, told 0.2 m/s ahead on the ground until 1 s and
// held to it for the driver's 0.5 s timeout, goes 0.3 m less its start
// (0.2959 m measured); without a command it stays where it was.
TEST(Rbsim, ATimelineDrivesABodyAmongRobots) {
  const std::string world = tempPath("driven_world.yaml");
  std::ofstream(world) << "bodies:\n  - {name: swing, urdf: " << RBS_SOURCE_DIR << "/urdf/pendulum.urdf}\n"
                       << "  - {name: crate, urdf: " << RBS_SOURCE_DIR
                       << "/urdf/box.urdf, initial: {position: [1, 0, 0.05]}, cmd_vel: {planar: true}}\n";
  const Result r = rbsim("--config " + world +
                         " --set 'timeline=[{t: 0, until: 1, body: crate, cmd_vel: {linear: [0.2, 0, 0]}}]'"
                         " --duration 2 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const YAML::Node crate = YAML::Load(r.out)["bodies"][1];
  ASSERT_EQ(crate["name"].as<std::string>(), "crate");
  EXPECT_NEAR(seq(crate["final"]["position"])[0], 1.3, 0.01);
  const Result idle = rbsim("--config " + world + " --duration 2 --quiet");
  ASSERT_EQ(idle.code, 0) << idle.err;
  EXPECT_NEAR(seq(YAML::Load(idle.out)["bodies"][1]["final"]["position"])[0], 1.0, 1e-9);
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
