// A robot's controllers from the config (io/controllers.h): ros_controllers'
// types and YAML as a Gazebo user loads them, each refusal naming the key.
#include "rigid_body_sim/io/controllers.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/scene_loader.h"

namespace rigid_body_sim::test {
namespace {

const std::string kUrdf = std::string(RBS_SOURCE_DIR) + "/urdf/";

io::RobotControls controls(const std::string& yaml) {
  const io::SimConfig c = io::parseConfig(io::loadYamlText(yaml, "test"));  // as a config file is read
  return io::buildControls(c.controllers, io::loadArticulationFile(kUrdf + "arm2.urdf"));
}

/// The message controls(yaml) is refused with ("" if accepted).
std::string refusal(const std::string& yaml) {
  try {
    controls(yaml);
  } catch (const io::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Controllers, ReadsRosControllersYaml) {
  const io::RobotControls c = controls(R"(
controllers:
  joint_state_controller: {type: joint_state_controller/JointStateController, publish_rate: 25}
  shoulder_effort: {type: effort_controllers/JointEffortController, joint: shoulder}
  elbow_velocity:
    type: velocity_controllers/JointVelocityController
    joint: elbow
    pid: {p: 2.0, i: 0.5, d: 0.1, i_clamp: 1.0}
)");
  EXPECT_EQ(c.joint_state_rate, 25.0);
  ASSERT_EQ(c.controllers.specs().size(), 2u);
  const core::JointControllerSpec& effort = c.controllers.specs()[0];
  EXPECT_EQ(effort.name, "shoulder_effort");
  EXPECT_EQ(effort.mode, core::ControlMode::kEffort);
  EXPECT_EQ(effort.joints, std::vector<int>{1});
  const core::JointControllerSpec& velocity = c.controllers.specs()[1];
  EXPECT_EQ(velocity.mode, core::ControlMode::kVelocity);
  EXPECT_EQ(velocity.joints, std::vector<int>{2});
  ASSERT_EQ(velocity.gains.size(), 1u);
  EXPECT_EQ(velocity.gains[0].p, 2.0);
  EXPECT_EQ(velocity.gains[0].i, 0.5);
  EXPECT_EQ(velocity.gains[0].d, 0.1);
  EXPECT_EQ(velocity.gains[0].i_clamp, 1.0);
  EXPECT_EQ(c.group, (std::vector<char>{0, 0}));
}

TEST(Controllers, GroupsTakeJointsAndPerJointGains) {
  const io::RobotControls c = controls(R"(
controllers:
  arm:
    type: effort_controllers/JointGroupPositionController
    joints: [elbow, shoulder]
    gains:
      shoulder: {p: 100, d: 10}
      elbow: {p: 50, i: 1, i_clamp: 2}
)");
  ASSERT_EQ(c.controllers.specs().size(), 1u);
  const core::JointControllerSpec& arm = c.controllers.specs()[0];
  EXPECT_EQ(arm.joints, (std::vector<int>{2, 1}));  // in the command's order
  EXPECT_EQ(arm.gains[0].p, 50.0);
  EXPECT_EQ(arm.gains[1].d, 10.0);
  EXPECT_EQ(c.group, std::vector<char>{1});
}

TEST(Controllers, TrajectoryControllersTakeAGroupsYaml) {
  // As a Gazebo user's YAML gives one (without the action's constraints).
  const io::RobotControls c = controls(R"(
controllers:
  arm_controller:
    type: effort_controllers/JointTrajectoryController
    joints: [shoulder, elbow]
    gains:
      shoulder: {p: 200, i: 10, d: 20, i_clamp: 5}
      elbow: {p: 100, d: 10}
)");
  ASSERT_EQ(c.controllers.specs().size(), 1u);
  const core::JointControllerSpec& arm = c.controllers.specs()[0];
  EXPECT_EQ(arm.mode, core::ControlMode::kTrajectory);
  EXPECT_EQ(arm.joints, (std::vector<int>{1, 2}));
  EXPECT_EQ(arm.gains[0].i_clamp, 5.0);
  EXPECT_EQ(arm.gains[1].d, 10.0);
  for (const char* type : {"position_controllers", "velocity_controllers"}) {
    const io::RobotControls other = controls(std::string("controllers: {t: {type: ") + type +
                                             "/JointTrajectoryController, joints: [elbow], gains: {elbow: {p: 1}}}}");
    EXPECT_EQ(other.controllers.specs()[0].mode, core::ControlMode::kTrajectory) << type;
  }
}

// gazebo_ros_control's pid_gains, as a Gazebo user's YAML gives them for
// position_controllers and velocity_controllers: the gains of those joints.
TEST(Controllers, GazeboRosControlPidGainsGiveInterfaceControllersTheirGains) {
  const io::RobotControls c = controls(R"(
controllers:
  shoulder: {type: position_controllers/JointPositionController, joint: shoulder}
  elbow: {type: velocity_controllers/JointVelocityController, joint: elbow}
gazebo_ros_control:
  pid_gains:
    shoulder: {p: 100.0, i: 0.01, d: 10.0}
    elbow: {p: 5.0}
)");
  ASSERT_EQ(c.controllers.specs().size(), 2u);
  EXPECT_EQ(c.controllers.specs()[0].gains[0].p, 100.0);
  EXPECT_EQ(c.controllers.specs()[0].gains[0].i, 0.01);
  EXPECT_EQ(c.controllers.specs()[0].gains[0].d, 10.0);
  EXPECT_EQ(c.controllers.specs()[1].gains[0].p, 5.0);
  const struct {
    std::string yaml, expected;
  } cases[] = {
      {"controllers: {a: {type: position_controllers/JointPositionController, joint: elbow}}\n"
       "gazebo_ros_control: {pid_gains: {shoulder: {p: 1}}}",
       "'gazebo_ros_control.pid_gains.shoulder': no controller in `controllers` names joint 'shoulder'"},
      {"controllers: {a: {type: effort_controllers/JointPositionController, joint: elbow, pid: {p: 1}}}\n"
       "gazebo_ros_control: {pid_gains: {elbow: {p: 1}}}",
       "is controller 'a''s, a effort_controllers/JointPositionController: it takes its own gains"},
      {"controllers: {a: {type: position_controllers/JointPositionController, joint: elbow, pid: {p: 1}}}\n"
       "gazebo_ros_control: {pid_gains: {elbow: {p: 1}}}",
       "'gazebo_ros_control.pid_gains.elbow': joint 'elbow' has gains already, in controllers.a"},
      {"controllers: {a: {type: position_controllers/JointPositionController, joint: elbow}}\n"
       "gazebo_ros_control: {robotNamespace: /arm}",
       "robotNamespace"},
      {"controllers: {a: {type: position_controllers/JointPositionController, joint: elbow}}",
       "(here, or as gazebo_ros_control: {pid_gains: {elbow: ...}})"},
  };
  for (const auto& k : cases) {
    const std::string message = refusal(k.yaml);
    EXPECT_NE(message.find(k.expected), std::string::npos) << k.yaml << "\n  -> " << message;
  }
}

// A spawned robot's namespace as `rosparam load FILE /NAME` fills it for
// gazebo_ros_control: every map with a type is a controller, its
// gazebo_ros_control map gives pid_gains, other parameters are not read;
// a controller's problem is refused as the config's, under the namespace.
TEST(Controllers, ARobotsNamespaceGivesTheMapsWithATypeAndTheirPidGains) {
  const core::ArticulationModel arm = io::loadArticulationFile(kUrdf + "arm2.urdf");
  const io::RobotControls c = io::controlsOf(YAML::Load(R"(
robot_description: "<robot name='x'/>"
tf_prefix: left
joint_state_controller: {type: joint_state_controller/JointStateController, publish_rate: 40}
shoulder: {type: position_controllers/JointPositionController, joint: shoulder}
elbow: {type: effort_controllers/JointEffortController, joint: elbow}
some_node: {rate: 3}
gazebo_ros_control: {pid_gains: {shoulder: {p: 50.0, d: 2.0}}}
)"),
                                             "/arm", arm, true);
  EXPECT_EQ(c.joint_state_rate, 40.0);
  ASSERT_EQ(c.controllers.specs().size(), 2u);
  EXPECT_EQ(c.controllers.specs()[0].name, "shoulder");
  EXPECT_EQ(c.controllers.specs()[0].gains[0].p, 50.0);
  EXPECT_EQ(c.controllers.specs()[1].mode, core::ControlMode::kEffort);
  // Nothing with a type: no controllers, and nothing refused.
  EXPECT_TRUE(io::controlsOf(YAML::Load("{robot_description: x}"), "/arm", arm, true).controllers.specs().empty());
  try {
    io::controlsOf(YAML::Load("{a: {type: effort_controllers/JointPositionController, joint: elbow}}"), "/arm", arm,
                   true);
    ADD_FAILURE() << "a position controller without gains was taken";
  } catch (const io::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("'/arm.a.pid'"), std::string::npos) << e.what();
  }
  // The request's map is the config's `controllers`: every entry must be one.
  EXPECT_THROW(io::controlsOf(YAML::Load("{tf_prefix: left}"), "controllers", arm, false), io::ConfigError);
}

/// UR5's trajectory controller (ur_gazebo's ur5_controllers.yaml) on this arm's two joints.
constexpr const char* kUr5Trajectory = R"(
  eff_joint_traj_controller:
    type: effort_controllers/JointTrajectoryController
    joints: &robot_joints [shoulder, elbow]
    gains:
      shoulder: {p: 4000, d: 200, i: 1, i_clamp: 1}
      elbow: {p: 2000, d: 20, i: 1, i_clamp: 1})";

TEST(Controllers, OfTwoOnAJointTheFirstRunsAndTheOtherIsLoadedStoppedAndSaid) {
  // UR5's ur5_controllers.yaml declares a trajectory controller and a group
  // effort controller on the same joints (its launch starts the first and
  // loads the second --stopped); it was refused.
  const io::RobotControls c = controls("controllers:\n" + std::string(kUr5Trajectory) + R"(
  joint_group_eff_controller:
    type: effort_controllers/JointGroupEffortController
    joints: *robot_joints
  elbow_only:
    type: effort_controllers/JointEffortController
    joint: elbow
)");
  ASSERT_EQ(c.controllers.specs().size(), 1u);
  EXPECT_EQ(c.controllers.specs()[0].name, "eff_joint_traj_controller");
  EXPECT_EQ(c.group, (std::vector<char>{1}));
  ASSERT_EQ(c.notes.size(), 1u) << c.notes[0];
  EXPECT_NE(c.notes[0].find("2 controllers loaded stopped, as controller_manager's spawner leaves a controller "
                            "whose joints another has: 'joint_group_eff_controller' (a joint of "
                            "'eff_joint_traj_controller'), 'elbow_only' (a joint of 'eff_joint_traj_controller'); "
                            "the first in the file runs"),
            std::string::npos)
      << c.notes[0];
  // Apart, each runs: the rule is about shared joints, not types.
  const io::RobotControls apart = controls(
      "controllers: {a: {type: effort_controllers/JointEffortController, joint: elbow},"
      " b: {type: effort_controllers/JointEffortController, joint: shoulder}}");
  EXPECT_EQ(apart.controllers.specs().size(), 2u);
  EXPECT_TRUE(apart.notes.empty());
}

TEST(Controllers, UR5sActionKeysAndKeysNoControllerReadsAreNamedInOneNote) {
  // UR5's ur5_controllers.yaml (anchors, aliases and the action's keys) was
  // refused, one key per restart.
  const io::RobotControls c = controls(R"(
controllers:
  joint_state_controller:
    type: joint_state_controller/JointStateController
    publish_rate: &loop_hz 125
)" + std::string(kUr5Trajectory) + R"(
    constraints:
      goal_time: 0.6
      shoulder: {trajectory: 0.1, goal: 0.1}
    stop_trajectory_duration: 0.5
    state_publish_rate: *loop_hz
    action_monitor_rate: 10
    hold_still: 1
)");
  EXPECT_EQ(c.joint_state_rate, 125.0);
  ASSERT_EQ(c.controllers.specs().size(), 1u);
  EXPECT_EQ(c.controllers.specs()[0].joints, (std::vector<int>{1, 2}));
  ASSERT_EQ(c.notes.size(), 1u);
  const std::string& note = c.notes[0];
  for (const char* part :
       {"5 controller keys not read here", "controllers.eff_joint_traj_controller.action_monitor_rate",
        "controllers.eff_joint_traj_controller.constraints", "controllers.eff_joint_traj_controller.state_publish_rate",
        "controllers.eff_joint_traj_controller.stop_trajectory_duration (the trajectory controller runs its command "
        "topic only",
        "controllers.eff_joint_traj_controller.hold_still (no ros_controllers controller of type "
        "effort_controllers/JointTrajectoryController reads it)"}) {
    EXPECT_NE(note.find(part), std::string::npos) << part << " not in: " << note;
  }
  // A trajectory key on another type is no trajectory key.
  const io::RobotControls effort = controls(
      "controllers: {a: {type: effort_controllers/JointEffortController, joint: elbow, constraints: {goal_time: 1}}}");
  ASSERT_EQ(effort.notes.size(), 1u);
  EXPECT_NE(effort.notes[0].find("controllers.a.constraints (no ros_controllers controller of type "
                                 "effort_controllers/JointEffortController reads it)"),
            std::string::npos)
      << effort.notes[0];
}

TEST(Controllers, RefusalsNameTheKey) {
  const struct {
    std::string yaml, expected;
  } cases[] = {
      {"controllers: {a: {type: effort_controllers/JointFooController, joint: elbow}}",
       "'controllers.a.type': 'effort_controllers/JointFooController' is not a controller type this project runs; "
       "the types: joint_state_controller/JointStateController, diff_drive_controller/DiffDriveController, "
       "mecanum_drive_controller/MecanumDriveController, "
       "ackermann_steering_controller/AckermannSteeringController, effort_controllers/JointEffortController"},
      {"controllers: {a: {type: effort_controllers/JointTrajectoryController, joints: [elbow]}}",
       "'controllers.a.gains.elbow': 'effort_controllers/JointTrajectoryController' acts here through a PID"},
      {"controllers: {a: {type: effort_controllers/JointTrajectoryController, joint: elbow}}", "takes joints:"},
      {"controllers: {a: {type: effort_controllers/JointEffortController, joint: wrist}}",
       "'controllers.a.joint': robot 'arm2' has no moving joint 'wrist' (its joints: 'shoulder', 'elbow')"},
      {"controllers: {a: {type: position_controllers/JointPositionController, joint: elbow}}",
       "'controllers.a.pid': 'position_controllers/JointPositionController' acts here through a PID on effort"},
      {"controllers: {a: {type: effort_controllers/JointGroupPositionController, joints: [elbow], gains: {}}}",
       "'controllers.a.gains.elbow'"},
      {"controllers: {a: {type: effort_controllers/JointGroupEffortController, joint: elbow}}",
       "'controllers.a': 'effort_controllers/JointGroupEffortController' takes joints: [NAME, ...]"},
      {"controllers: {a: {type: effort_controllers/JointEffortController, joints: [elbow]}}", "takes joint: NAME"},
      {"controllers: {a: {type: effort_controllers/JointEffortController, joint: elbow, jiont: elbow}}",
       "'controllers.a.jiont': unknown key: did you mean joint?"},
      {"controllers: {a: {type: effort_controllers/JointPositionController, joint: elbow, pid: {p: -1}}}",
       "'controllers.a.pid.p'"},
      // A controller loaded stopped is checked as a running one.
      {"controllers: {a: {type: effort_controllers/JointEffortController, joint: elbow},"
       " b: {type: effort_controllers/JointPositionController, joint: elbow}}",
       "'controllers.b.pid': 'effort_controllers/JointPositionController' acts here through a PID"},
      {"controllers: {a: {type: effort_controllers/JointEffortController, joint: elbow, publish_rate: 10}}",
       "'controllers.a.publish_rate'"},
      {"controllers: {a: {joint: elbow}}", "'controllers.a.type'"},
      // Both started silently through roslaunch (issue 45): gains without p
      // (control_toolbox refuses them), and a rate that published every step.
      {"controllers: {a: {type: effort_controllers/JointPositionController, joint: elbow, pid: {i: 1, d: 2}}}",
       "'controllers.a.pid.p': is missing: control_toolbox's Pid needs p"},
      {"controllers: {a: {type: effort_controllers/JointGroupPositionController, joints: [elbow],"
       " gains: {elbow: {d: 1}}}}",
       "'controllers.a.gains.elbow.p': is missing"},
      {"controllers: {j: {type: joint_state_controller/JointStateController, publish_rate: 1e300}}",
       "'controllers.j.publish_rate': must be within [0.01, 10000] Hz, got 1e300"},
      {"controllers: {j: {type: joint_state_controller/JointStateController, publish_rate: 0}}",
       "'controllers.j.publish_rate': must be within"},
  };
  for (const auto& c : cases) {
    const std::string message = refusal(c.yaml);
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.yaml << "\n  -> " << message;
  }
}

TEST(Controllers, EveryControllersProblemIsNamedInOneRefusal) {
  // Two controllers wrong in their YAML (an unknown key, a negative gain),
  // and, once they are read, two wrong for the robot (an unknown joint, no
  // gains): each pair in one refusal, so a user fixes them in one launch.
  const std::string parse = refusal(
      "controllers: {a: {type: effort_controllers/JointEffortController, joint: elbow, pubish_rate: 1},"
      " b: {type: effort_controllers/JointPositionController, joint: shoulder, pid: {p: -1}}}");
  for (const char* part : {"2 problems", "pubish_rate", "'controllers.b.pid.p'"}) {
    EXPECT_NE(parse.find(part), std::string::npos) << part << " not in: " << parse;
  }
  const std::string build = refusal(
      "controllers: {a: {type: effort_controllers/JointEffortController, joint: wrist},"
      " b: {type: position_controllers/JointPositionController, joint: shoulder}}");
  for (const char* part : {"2 problems", "'controllers.a.joint': robot 'arm2' has no moving joint 'wrist'",
                           "'controllers.b.pid': 'position_controllers/JointPositionController' acts here"}) {
    EXPECT_NE(build.find(part), std::string::npos) << part << " not in: " << build;
  }
}

TEST(Controllers, ABodyTakesNoneAndARobotEntryItsOwn) {
  const std::string box = kUrdf + "box.urdf", arm = kUrdf + "arm2.urdf";
  try {
    io::buildScene(io::parseConfig(YAML::Load("bodies:\n  - {name: crate, urdf: " + box +
                                              ", controllers: {a: {type: effort_controllers/JointEffortController,"
                                              " joint: x}}}\n")));
    ADD_FAILURE() << "a body took controllers";
  } catch (const io::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("'bodies[0].controllers': body 'crate' has no moving joints"),
              std::string::npos)
        << e.what();
  }
  const io::SceneSetup s = io::buildScene(io::parseConfig(
      YAML::Load("bodies:\n  - {name: crate, urdf: " + box + "}\n  - {name: arm, urdf: " + arm +
                 ", controllers: {e: {type: effort_controllers/JointEffortController, joint: elbow}}}\n")));
  ASSERT_EQ(s.controls.size(), 1u);
  ASSERT_EQ(s.controls[0].controllers.specs().size(), 1u);
  EXPECT_EQ(s.controls[0].controllers.specs()[0].joints, std::vector<int>{2});
}

}  // namespace
}  // namespace rigid_body_sim::test
