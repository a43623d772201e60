// A controller in trouble (ros/controller_watch.h): saturated at the effort
// limit, or pressing hard against a position limit, for 1 s of sim time,
// said once per joint; a transient or an idle joint is not.
#include "rigid_body_sim/ros/controller_watch.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/controllers.h"

namespace rigid_body_sim::test {
namespace {

constexpr double kDt = 1e-3;

/// The two-link arm (urdf/arm2.urdf: effort limits 40 and 20 N·m, ±2.5 rad)
/// with a position controller on the elbow only.
struct Arm {
  core::ArticulationModel model = io::loadArticulationFile(std::string(RBS_SOURCE_DIR) + "/urdf/arm2.urdf");
  io::RobotControls controls = io::buildControls(
      io::parseConfig(YAML::Load("controllers: {elbow_controller: {type: effort_controllers/JointPositionController,"
                                 " joint: elbow, pid: {p: 100}}}"))
          .controllers,
      model);
  core::ArticulationState state = core::restState(model);
};

/// Steps of `effort` (shoulder, elbow) at the arm's state; all that was said.
std::vector<std::string> run(node::ControllerWatch& watch, const Arm& arm, const Eigen::Vector2d& effort, int steps) {
  std::vector<std::string> said;
  for (int k = 0; k < steps; ++k) {
    for (std::string& s : watch.observe(0, "arm2", arm.model, arm.controls.controllers, arm.state, effort, kDt)) {
      said.push_back(std::move(s));
    }
  }
  return said;
}

TEST(ControllerWatch, ASaturatedControllerIsSaidOnceAfterASecond) {
  const Arm arm;
  node::ControllerWatch watch;
  EXPECT_TRUE(run(watch, arm, Eigen::Vector2d(0.0, -20.0), 990).empty());  // 0.99 s at the limit
  const std::vector<std::string> said = run(watch, arm, Eigen::Vector2d(0.0, -20.0), 20);
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find("robot 'arm2': controller 'elbow_controller' has held joint 'elbow' at its URDF effort "
                         "limit (20) for 1 s"),
            std::string::npos)
      << said[0];
  EXPECT_TRUE(run(watch, arm, Eigen::Vector2d(0.0, 20.0), 3000).empty());  // said once for the node's life
}

TEST(ControllerWatch, TransientsAndJointsNoControllerOwnsAreNotSaid) {
  const Arm arm;
  node::ControllerWatch watch;
  for (int k = 0; k < 5; ++k) {  // 0.6 s saturated, 0.01 s not, again and again
    EXPECT_TRUE(run(watch, arm, Eigen::Vector2d(0.0, 20.0), 600).empty());
    EXPECT_TRUE(run(watch, arm, Eigen::Vector2d(0.0, 19.0), 10).empty());
  }
  // The shoulder has no controller: its effort is someone else's (apply_joint_effort).
  EXPECT_TRUE(run(watch, arm, Eigen::Vector2d(40.0, 0.0), 3000).empty());
  // A reset starts the time over.
  EXPECT_TRUE(run(watch, arm, Eigen::Vector2d(0.0, 20.0), 900).empty());
  watch.restart(0);
  EXPECT_TRUE(run(watch, arm, Eigen::Vector2d(0.0, 20.0), 900).empty());
}

// A robot deleted is forgotten: the robot after it, now at its index, keeps
// what was said of it, and a robot spawned in the freed place is watched afresh.
TEST(ControllerWatch, ARobotDeletedIsForgottenAndTheLaterOnesMoveDown) {
  const Arm arm;
  node::ControllerWatch watch;
  const auto saturate = [&](std::size_t r) {
    std::vector<std::string> said;
    for (int k = 0; k < 1100; ++k) {
      for (std::string& s :
           watch.observe(r, "arm2", arm.model, arm.controls.controllers, arm.state, Eigen::Vector2d(0.0, 20.0), kDt)) {
        said.push_back(std::move(s));
      }
    }
    return said.size();
  };
  EXPECT_EQ(saturate(0), 1u);
  EXPECT_EQ(saturate(1), 1u);
  watch.removeRobot(0);
  EXPECT_EQ(saturate(0), 0u);  // robot 1, now 0: said already
  EXPECT_EQ(saturate(1), 1u);  // a new robot
}

TEST(ControllerWatch, PressingHardAgainstALimitIsSaid) {
  Arm arm;
  arm.state.q(1) = 2.5;  // the elbow at its upper limit
  node::ControllerWatch watch;
  // Holding it there gently (a target at the limit) is no trouble.
  EXPECT_TRUE(run(watch, arm, Eigen::Vector2d(0.0, 5.0), 2000).empty());
  // Pushing outward with half the effort limit or more, for a second, is.
  const std::vector<std::string> said = run(watch, arm, Eigen::Vector2d(0.0, 12.0), 1001);
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find("has driven joint 'elbow' against its upper limit (2.5) for 1 s"), std::string::npos)
      << said[0];
}

}  // namespace
}  // namespace rigid_body_sim::test
