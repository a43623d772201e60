// A DiffDriveController from ros_controllers' YAML (io/controllers.h,
// drive_config.h): its keys, what it finds in the URDF, its refusals, and
// the shipped wheeled base (urdf/diff_drive.urdf) driven on the ground by it
// as the node steps a robot: the twist it is given, and its odometry against
// the ground truth.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/core/devices/velocity_driver.h"
#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/controllers.h"
#include "rigid_body_sim/io/scene_loader.h"

namespace rigid_body_sim::test {
namespace {

const std::string kUrdf = std::string(RBS_SOURCE_DIR) + "/urdf/";

/// The shipped base's config with `controllers` (a flow map).
io::SimConfig baseConfig(const std::string& controllers) {
  return io::parseConfig(
      YAML::Load("dt: 0.001\ncontact: {friction: 0.8}\ninitial: {position: [0, 0, 0.08]}\n"
                 "controllers: " +
                 controllers + "\n"));
}

io::RobotControls baseControls(const std::string& controllers) {
  return io::buildControls(baseConfig(controllers).controllers, io::loadArticulationFile(kUrdf + "diff_drive.urdf"));
}

std::string refusal(const std::string& controllers) {
  try {
    baseControls(controllers);
  } catch (const io::ConfigError& e) {
    return e.what();
  }
  return "";
}

constexpr const char* kDrive =
    "{base: {type: diff_drive_controller/DiffDriveController, left_wheel: left_wheel_joint, "
    "right_wheel: right_wheel_joint";

TEST(DiffDriveController, ReadsRosControllersYamlAndTheUrdfsWheels) {
  const io::RobotControls c = baseControls(std::string(kDrive) +
                                           ", publish_rate: 20, cmd_vel_timeout: 0.25, enable_odom_tf: false,"
                                           " base_frame_id: chassis, wheel_separation_multiplier: 2,"
                                           " pose_covariance_diagonal: [1, 2, 3, 4, 5, 6],"
                                           " linear: {x: {has_velocity_limits: true, max_velocity: 1.5}},"
                                           " angular: {z: {has_acceleration_limits: true, max_acceleration: 3,"
                                           " min_acceleration: -6}}}}");
  ASSERT_EQ(c.drives.size(), 1u);
  const core::DiffDrive& d = c.drives[0];
  EXPECT_EQ(d.spec().name, "base");
  EXPECT_EQ(d.wheels(), (std::vector<int>{1, 2}));  // the URDF's left_wheel_joint, right_wheel_joint
  // From the URDF, as ros_controllers: the joints 0.36 m apart, the left wheel's collision cylinder 0.06 m.
  EXPECT_DOUBLE_EQ(d.spec().wheel_separation, 0.36);
  EXPECT_DOUBLE_EQ(d.separation(), 0.72);
  EXPECT_DOUBLE_EQ(d.spec().wheel_radius, 0.06);
  EXPECT_EQ(d.spec().settings.cmd_vel_timeout, 0.25);
  const core::TwistLimiter& lin = d.spec().settings.linear;
  EXPECT_TRUE(lin.has_velocity_limits);
  EXPECT_EQ(lin.max_velocity, 1.5);
  EXPECT_EQ(lin.min_velocity, -1.5);  // ros_controllers: min defaults to -max
  EXPECT_FALSE(lin.has_acceleration_limits);
  const core::TwistLimiter& ang = d.spec().settings.angular;
  EXPECT_EQ(ang.min_acceleration, -6.0);
  ASSERT_EQ(c.drive_topics.size(), 1u);
  const io::DriveTopics& t = c.drive_topics[0];
  EXPECT_EQ(t.publish_rate, 20.0);
  EXPECT_FALSE(t.enable_odom_tf);
  EXPECT_EQ(t.base_frame_id, "chassis");
  EXPECT_EQ(t.odom_frame_id, "odom");
  EXPECT_EQ(t.pose_covariance_diagonal[5], 6.0);
  EXPECT_EQ(t.twist_covariance_diagonal[0], 0.0);
  EXPECT_TRUE(c.controllers.specs().empty());
}

TEST(DiffDriveController, JackalsKeysNoControllerReadsAreNamedNotRefused) {
  // Jackal's control.yaml carries k_l and k_r, which ros_controllers' drive
  // does not read (ROS lets them be): it was refused, one key per restart.
  const io::RobotControls c = baseControls(std::string(kDrive) +
                                           ", k_l: 0.1, k_r: 0.1, publish_wheel_joint_controller_state: true,"
                                           " publish_joint_trajectory_controller_state: false}}");
  ASSERT_EQ(c.drives.size(), 1u);
  ASSERT_EQ(c.notes.size(), 1u);
  for (const char* part : {"3 controller keys not read here",
                           "controllers.base.publish_wheel_joint_controller_state (its message is control_msgs'",
                           "controllers.base.k_l, controllers.base.k_r (diff_drive_controller/DiffDriveController "
                           "reads no such key)"}) {
    EXPECT_NE(c.notes[0].find(part), std::string::npos) << part << " not in: " << c.notes[0];
  }
  EXPECT_TRUE(baseControls(std::string(kDrive) + "}}").notes.empty());
}

TEST(DiffDriveController, RefusalsNameTheKey) {
  const std::string drive = kDrive;
  const auto refused = [](const std::string& yaml, const std::string& what) {
    const std::string why = refusal(yaml);
    EXPECT_NE(why.find(what), std::string::npos) << "'" << what << "' not in: " << (why.empty() ? "(accepted)" : why);
  };
  refused("{base: {type: diff_drive_controller/DiffDriveController, right_wheel: right_wheel_joint}}",
          "'controllers.base.left_wheel': is missing");
  refused(
      "{base: {type: diff_drive_controller/DiffDriveController, left_wheel: [left_wheel_joint],"
      " right_wheel: [right_wheel_joint, left_wheel_joint]}}",
      "'controllers.base.right_wheel': 2 wheels against left_wheel's 1");
  refused(
      "{base: {type: diff_drive_controller/DiffDriveController, left_wheel: caster,"
      " right_wheel: right_wheel_joint}}",
      "'controllers.base.left_wheel': robot 'diff_drive' has no moving joint 'caster'");
  refused(drive + ", linear: {x: {has_velocity_limits: true}}}}",
          "'controllers.base.linear.x.max_velocity': is missing: has_velocity_limits is true");
  refused(drive + ", linear: {y: {}}}}", "controllers.base.linear");
  refused(drive + ", wheel_radius: -1}}", "'controllers.base.wheel_radius'");
  // Limit pairs that do not hold 0 drove the base 2.5-5.3 m with no command.
  refused(drive + ", linear: {x: {has_velocity_limits: true, max_velocity: -0.5, min_velocity: -1}}}}",
          "'controllers.base.linear.x.max_velocity': must be >= 0: a zero command would drive the base");
  refused(drive + ", linear: {x: {has_velocity_limits: true, max_velocity: 2, min_velocity: 1}}}}",
          "'controllers.base.linear.x.min_velocity': must be <= 0");
  refused(drive + ", linear: {x: {has_acceleration_limits: true, max_acceleration: -1, min_acceleration: -2}}}}",
          "'controllers.base.linear.x.max_acceleration': must be >= 0");
  refused(drive + ", angular: {z: {has_jerk_limits: true, max_jerk: -1, min_jerk: -2}}}}",
          "'controllers.base.angular.z.max_jerk': must be >= 0");
  refused(drive + ", publish_rate: 1e300}}", "'controllers.base.publish_rate': must be within");
  refused(drive + ", pose_covariance_diagonal: [1, 2]}}", "'controllers.base.pose_covariance_diagonal'");
  refused(drive + ", odom_frame_id: base_link}}", "'controllers.base.odom_frame_id'");
  // Frame ids as tf2 takes them.
  refused(drive + ", base_frame_id: 'bad frame#!'}}",
          "'controllers.base.base_frame_id': 'bad frame#!' is no tf frame id: letters, digits");
  // One leading '/' is dropped, as tf2's buffer drops it (AgileX Hunter's
  // stock odom_frame_id has one); a second is refused.
  EXPECT_EQ(baseControls(drive + ", odom_frame_id: /odom}}").drive_topics.at(0).odom_frame_id, "odom");
  refused(drive + ", odom_frame_id: //odom}}", "'controllers.base.odom_frame_id': '/odom' starts with '/'");
  refused(drive + ", cmd_vel_timout: 1}}",
          "'controllers.base.cmd_vel_timout': unknown key: did you mean cmd_vel_timeout?");
  // A controller on a wheel is loaded stopped, but checked all the same.
  refused(drive + "}, spin: {type: velocity_controllers/JointVelocityController, joint: left_wheel_joint}}",
          "'controllers.spin.pid'");
}

TEST(DiffDriveController, AControllerOnItsWheelIsLoadedStoppedAndAPluginThereRefused) {
  const io::RobotControls c =
      baseControls(std::string(kDrive) +
                   "}, spin: {type: velocity_controllers/JointVelocityController, joint: left_wheel_joint,"
                   " pid: {p: 1}}}");
  EXPECT_EQ(c.drives.size(), 1u);
  EXPECT_EQ(c.controllers.specs().size(), 0u);
  ASSERT_EQ(c.notes.size(), 1u);
  EXPECT_NE(c.notes[0].find("'spin' (a joint of 'base')"), std::string::npos) << c.notes[0];
  // gazebo_ros_diff_drive always runs: on a controller's wheels it is refused.
  std::vector<io::ControllerEntry> entries = baseConfig(std::string(kDrive) + "}}").controllers;
  io::ControllerEntry plugin = entries.front();
  plugin.name = "diff_drive";
  plugin.key = "<gazebo> <plugin name=\"diff_drive\">";
  entries.push_back(plugin);
  try {
    io::buildControls(entries, io::loadArticulationFile(kUrdf + "diff_drive.urdf"));
    ADD_FAILURE() << "a plugin on a controller's wheels was accepted";
  } catch (const io::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("'<gazebo> <plugin name=\"diff_drive\">': its joints are already "
                                         "controller 'base''s"),
              std::string::npos)
        << e.what();
  }
}

TEST(DiffDriveController, TakesGazeboRosControlsPidGainsForItsWheels) {
  const io::SimConfig config = io::parseConfig(
      YAML::Load("controllers: " + std::string(kDrive) +
                 "}}\ngazebo_ros_control: {pid_gains: {right_wheel_joint: {p: 3, i: 1, i_clamp: 2}}}\n"));
  const core::ArticulationModel model = io::loadArticulationFile(kUrdf + "diff_drive.urdf");
  const io::RobotControls c = io::buildControls(config.controllers, model);
  ASSERT_EQ(c.drives.size(), 1u);
  const std::vector<core::PidGains>& gains = c.drives[0].spec().gains;
  ASSERT_EQ(gains.size(), 2u);
  EXPECT_EQ(gains[1].p, 3.0);
  EXPECT_EQ(gains[1].i_clamp, 2.0);
  // The left wheel, given none, gets the default.
  EXPECT_EQ(gains[0].p, core::defaultWheelGains(model, 1, 0.06, 2).p);
}

/// The shipped base on the ground under `controllers`, stepped as the node steps a robot.
struct DrivenBase {
  io::SceneSetup world;
  core::SceneWorkspace ws;
  core::SceneLoads loads;
  double t = 0.0;

  explicit DrivenBase(const std::string& controllers)
      : world(io::loadScene(baseConfig(controllers), [] { return io::readUrdfFile(kUrdf + "diff_drive.urdf", ""); })) {
    loads.robots.resize(1);
    drive().restart(robot(), true);
  }
  core::DiffDrive& drive() { return world.controls.at(0).drives.at(0); }
  core::ArticulationState& robot() { return world.state.robots.at(0); }
  /// `seconds` of sim time with (v, ω) sent every 0.1 s; the base's own
  /// forward speed and yaw rate averaged over the last `span` s.
  void run(double seconds, double v, double w, double span, double& speed, double& yaw_rate) {
    const double dt = world.scene.model().dt();
    const int steps = static_cast<int>(std::lround(seconds / dt));
    const int from = steps - static_cast<int>(std::lround(span / dt));
    speed = yaw_rate = 0.0;
    for (int n = 0; n < steps; ++n) {
      if (n % 100 == 0) {
        ASSERT_TRUE(drive().command(v, w, t));
      }
      Eigen::VectorXd& effort = loads.robots[0].effort;
      effort.setZero(2);
      drive().efforts(robot(), t, dt, effort);
      core::stepScene(world.scene, world.state, loads, ws);
      drive().observe(robot(), dt);
      t += dt;
      if (n >= from) {
        speed += robot().V_B(3) / (steps - from);  // the base's origin is on the axle: its x is forward
        yaw_rate += (robot().X_WB.rotation * robot().V_B.head<3>()).z() / (steps - from);
      }
    }
  }
  double yaw() const {
    const core::Vec3 x = world.state.robots[0].X_WB.rotation * core::Vec3::UnitX();
    return std::atan2(x.y(), x.x());
  }
};

// Accelerations the wheels' grip allows (each carries about 2 kg at mu = 0.8):
// the wheels roll without slipping, as ros_controllers' users set limits for.
constexpr const char* kGentle =
    ", linear: {x: {has_acceleration_limits: true, max_acceleration: 1.0}},"
    " angular: {z: {has_acceleration_limits: true, max_acceleration: 2.0}}}}";

TEST(DiffDriveController, DrivesTheBaseAtItsTwistAndItsOdometryFollows) {
  DrivenBase base(std::string(kDrive) + kGentle);
  const core::Vec3 start = base.robot().X_WB.translation;
  double speed = 0.0, yaw_rate = 0.0;
  base.run(4.0, 0.5, 0.3, 2.0, speed, yaw_rate);
  // Within 1 %: in a turn the wheels' rigid rims bear on their outer edges (the load moves out of
  // the turn), 15 mm off their mid-planes, so the base's origin runs ω · 15 mm = 4.5 mm/s faster.
  EXPECT_NEAR(speed, 0.5, 0.01 * 0.5);
  EXPECT_NEAR(yaw_rate, 0.3, 0.001 * 0.3);
  // The odometry against the ground truth, from where the base started (it faced world x).
  const core::PlanarOdometry& o = base.drive().odometry();
  const core::Vec3 moved = base.robot().X_WB.translation - start;
  const double travelled = 0.5 * 4.0;
  EXPECT_NEAR(o.x, moved.x(), 0.01 * travelled);
  EXPECT_NEAR(o.y, moved.y(), 0.01 * travelled);
  EXPECT_NEAR(std::remainder(o.heading - base.yaw(), 2.0 * M_PI), 0.0, 0.001);
  EXPECT_NEAR(o.linear, 0.5, 0.001 * 0.5);  // the wheels' own speed: what they were asked
  EXPECT_NEAR(o.angular, yaw_rate, 0.001 * 0.3);
  // No command for longer than cmd_vel_timeout: it brakes to a stop (within the acceleration limits).
  base.t += 1.0;  // the last command is 1 s old
  for (int k = 0; k < 2000; ++k) {
    Eigen::VectorXd& effort = base.loads.robots[0].effort;
    effort.setZero(2);
    base.drive().efforts(base.robot(), base.t, 1e-3, effort);
    core::stepScene(base.world.scene, base.world.state, base.loads, base.ws);
    base.drive().observe(base.robot(), 1e-3);
    base.t += 1e-3;
  }
  EXPECT_NEAR(base.robot().V_B(3), 0.0, 0.005);
  EXPECT_NEAR(base.robot().V_B(2), 0.0, 0.005);
}

TEST(DiffDriveController, ItsOdometryDriftsWhenAStepCommandSpinsTheWheels) {
  // No limits: a step to 0.6 rad/s asks the wheels for more torque than friction holds,
  // so they slip at the start, and the odometry, which counts wheel turns, turns further than the base.
  DrivenBase base(std::string(kDrive) + "}}");
  double speed = 0.0, yaw_rate = 0.0;
  base.run(4.0, 0.5, 0.6, 2.0, speed, yaw_rate);
  const double drift = base.drive().odometry().heading - base.yaw();
  EXPECT_GT(drift, 0.05);
  EXPECT_LT(drift, 0.2);
  EXPECT_NEAR(yaw_rate, 0.6, 0.001 * 0.6);  // once the wheels grip, the base turns at the rate asked
}

// cmd_vel on a robot (a body's key): the whole robot, wheels and all, driven
// as one body toward the commanded twist by a wrench on its base. Floating
// in zero gravity, it reaches a twist of all six components, which its
// momentum then holds (the wrench falls to nothing).
TEST(BaseDriver, DrivesAFloatingRobotToTheCommandedTwist) {
  const io::SimConfig c =
      io::parseConfig(YAML::Load("dt: 0.001\ngravity: [0, 0, 0]\nscene: []\n"
                                 "cmd_vel: {max_force: 100, max_torque: 50, timeout: 0}\n"));
  io::SceneSetup world = io::loadScene(c, [] { return io::readUrdfFile(kUrdf + "diff_drive.urdf", ""); });
  ASSERT_TRUE(world.controls.at(0).base_driver.has_value());
  core::VelocityDriver& driver = *world.controls[0].base_driver;
  const core::Vec3 v_L(0.3, 0.1, -0.05), w_L(0.1, -0.2, 0.5);
  ASSERT_FALSE(driver.command(v_L, w_L, 0.0));
  const core::ArticulationModel& model = world.scene.robots().at(0).model;
  core::SceneWorkspace ws;
  core::SceneLoads loads;
  loads.robots.resize(1);
  core::ArticulationKinematics kin;
  core::Vec6 last = core::Vec6::Zero();
  for (int n = 0; n < 2000; ++n) {
    core::kinematics(model, world.state.robots[0], kin);
    last = core::baseLoad(driver, model, kin, n * 1e-3, 1e-3);
    loads.robots[0].wrench_L.assign(model.links.size(), core::Vec6::Zero());
    loads.robots[0].wrench_L[0] = last;
    core::stepScene(world.scene, world.state, loads, ws);
  }
  const core::LinkState base = core::baseLinkState(world.state.robots[0]);
  const core::Vec3 v = base.q_WL.conjugate() * base.v_WL, w = base.q_WL.conjugate() * base.w_W;
  EXPECT_LT((v - v_L).norm(), 1e-3 * v_L.norm()) << v.transpose();
  EXPECT_LT((w - w_L).norm(), 1e-3 * w_L.norm()) << w.transpose();
  // Held there by momentum: what it still pushes is the wheels' spin-up, a
  // small share of the force 100 N and torque 50 N·m it may give.
  EXPECT_LT(last.tail<3>().norm(), 1.0);
  EXPECT_LT(last.head<3>().norm(), 1.0);
}

TEST(BaseDriver, ARobotFixedToTheWorldHasNoBaseToDrive) {
  const io::SimConfig c = io::parseConfig(YAML::Load("cmd_vel: {}\n"));
  try {
    io::loadScene(c, [] { return io::readUrdfFile(kUrdf + "arm2.urdf", ""); });
    ADD_FAILURE() << "cmd_vel on a fixed robot was accepted";
  } catch (const io::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("config key 'cmd_vel': robot 'arm2' is fixed to the world"), std::string::npos)
        << e.what();
  }
}

// A MecanumDriveController (Ridgeback's, Dingo-O's) on test/ros/mecanum_base.urdf's four wheels.
io::RobotControls mecanumControls(const std::string& keys) {
  return io::buildControls(
      baseConfig(
          "{omni: {type: mecanum_drive_controller/MecanumDriveController, front_left_wheel_joint: "
          "front_left_wheel, back_left_wheel_joint: back_left_wheel, front_right_wheel_joint: front_right_wheel, "
          "back_right_wheel_joint: back_right_wheel" +
          keys + "}}")
          .controllers,
      io::loadArticulationFile(std::string(RBS_SOURCE_DIR) + "/test/ros/mecanum_base.urdf"));
}

TEST(MecanumDriveController, ReadsItsWheelsKeysAndTheUrdfsSpans) {
  const io::RobotControls c = mecanumControls(
      ", linear: {x: {has_velocity_limits: true, max_velocity: 1.1}, y: {has_velocity_limits: true, max_velocity: "
      "0.8}}, cmd_vel_timeout: 0.25, enable_odom_tf: false, k_x: 2");
  ASSERT_EQ(c.drives.size(), 1u);
  const core::DiffDriveSpec& d = c.drives[0].spec();
  EXPECT_TRUE(d.mecanum);
  EXPECT_EQ(d.left.size(), 2u);
  // As mecanum_drive_controller: each wheel's |x| + |y| (0.3 + 0.25), their mean twice.
  EXPECT_NEAR(d.wheel_separation, 2.0 * 0.55, 1e-12);
  EXPECT_EQ(d.wheel_radius, 0.08);  // its front left wheel's cylinder
  EXPECT_EQ(d.settings.lateral.max_velocity, 0.8);
  EXPECT_EQ(d.settings.linear.max_velocity, 1.1);
  EXPECT_EQ(d.settings.cmd_vel_timeout, 0.25);
  EXPECT_FALSE(c.drive_topics.at(0).enable_odom_tf);
  std::string notes;
  for (const std::string& n : c.notes) notes += n;
  EXPECT_NE(notes.find("omni.k_x"), std::string::npos) << notes;  // a key no such controller reads: named
  // Given spans: their sum.
  EXPECT_NEAR(
      mecanumControls(", wheel_separation_x: 0.638, wheel_separation_y: 0.551").drives.at(0).spec().wheel_separation,
      0.638 + 0.551, 1e-12);
}

TEST(MecanumDriveController, RefusalsNameTheKey) {
  const auto refused = [](const std::string& keys) {
    try {
      mecanumControls(keys);
    } catch (const io::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refused(", wheel_separation_x: 0.6").find("controllers.omni.wheel_separation_y': is missing"),
            std::string::npos)
      << refused(", wheel_separation_x: 0.6");
  EXPECT_NE(refused(", linear: {y: {has_velocity_limits: true, max_velocity: -1}}")
                .find("controllers.omni.linear.y.min_velocity': must be <= max_velocity"),
            std::string::npos);
  EXPECT_NE(refused(", linear: {z: {}}").find("linear"), std::string::npos);
  EXPECT_NE(refusal("{omni: {type: mecanum_drive_controller/MecanumDriveController, front_left_wheel_joint: "
                    "left_wheel_joint}}")
                .find("controllers.omni.back_left_wheel_joint': is missing"),
            std::string::npos);
}

}  // namespace
}  // namespace rigid_body_sim::test
