// Steered bases from their config and markup (docs/physics.md §11.14): an
// ackermann_steering_controller/AckermannSteeringController's keys and the
// geometry read from test/ros/ackermann_base.urdf, gazebo_ros_tricycle_drive's
// markup on test/ros/tricycle_base.urdf, and the refusals naming their keys.
// Driving on the ground is the node's ackermann.test and tricycle.test.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <limits>
#include <string>

#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/controllers.h"
#include "rigid_body_sim/io/scene_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"

namespace rigid_body_sim::test {
namespace {

const std::string kTestUrdf = std::string(RBS_SOURCE_DIR) + "/test/ros/";

io::RobotControls carControls(const std::string& keys) {
  const io::SimConfig c = io::parseConfig(
      YAML::Load("controllers: {car: {type: ackermann_steering_controller/AckermannSteeringController" + keys + "}}"));
  return io::buildControls(c.controllers, io::loadArticulationFile(kTestUrdf + "ackermann_base.urdf"));
}

std::string refusal(const std::string& keys) {
  try {
    carControls(keys);
  } catch (const io::ConfigError& e) {
    return e.what();
  }
  return "";
}

constexpr const char* kLists =
    ", rear_wheel: [rear_left_wheel_joint, rear_right_wheel_joint], front_steer: [front_left_steer_joint, "
    "front_right_steer_joint]";

TEST(AckermannSteeringController, ReadsItsJointsAndTheCarsGeometryFromTheUrdf) {
  const io::RobotControls c = carControls(std::string(kLists) + ", cmd_vel_timeout: 0.25, k_x: 1");
  ASSERT_EQ(c.drives.size(), 1u);
  const core::DiffDriveSpec& d = c.drives[0].spec();
  ASSERT_TRUE(d.steering.has_value());
  const core::SteeringSpec& s = *d.steering;
  EXPECT_EQ(d.left.size(), 2u);
  EXPECT_TRUE(d.right.empty());
  EXPECT_EQ(d.wheel_radius, 0.1);  // the rear left wheel's cylinder
  // From the rear axle's centre (x = -0.3 m in the base): the knuckles 0.6 m ahead, 0.25 m aside.
  EXPECT_NEAR(s.wheelbase, 0.6, 1e-12);
  ASSERT_EQ(s.joints.size(), 2u);
  EXPECT_NEAR(s.joint_x[0], 0.6, 1e-12);
  EXPECT_NEAR(s.joint_y[0], 0.25, 1e-12);
  EXPECT_NEAR(s.joint_y[1], -0.25, 1e-12);
  EXPECT_EQ(s.joint_sign[0], 1.0);
  EXPECT_NEAR(s.wheel_x[0], 0.0, 1e-12);
  EXPECT_NEAR(s.wheel_y[1], -0.25, 1e-12);
  EXPECT_EQ(s.wheel_steer[0], -1);
  EXPECT_FALSE(s.speed_at_steered_wheel);
  EXPECT_EQ(d.settings.cmd_vel_timeout, 0.25);
  std::string notes;
  for (const std::string& n : c.notes) notes += n;
  EXPECT_NE(notes.find("car.k_x"), std::string::npos) << notes;
  // ros_controllers' own form, one joint each, and a given wheelbase with its multiplier.
  const core::SteeringSpec one =
      *carControls(
           ", rear_wheel: rear_left_wheel_joint, front_steer: front_left_steer_joint, wheel_separation_h: 0.5, "
           "wheel_separation_h_multiplier: 1.1")
           .drives.at(0)
           .spec()
           .steering;
  EXPECT_NEAR(one.wheelbase, 0.55, 1e-12);
  EXPECT_NEAR(one.joint_y[0], 0.0, 1e-12);  // from the one rear wheel, 0.25 m aside
  EXPECT_NEAR(one.wheel_y[0], 0.0, 1e-12);
}

TEST(AckermannSteeringController, RefusalsNameTheKey) {
  // ros_controllers' defaults name joints this car does not have.
  EXPECT_NE(refusal("").find("controllers.car.rear_wheel': robot 'ackermann_base' has no moving joint "
                             "'rear_wheel_joint'"),
            std::string::npos)
      << refusal("");
  EXPECT_NE(refusal(", rear_wheel: rear_left_wheel_joint, front_steer: front_left_wheel_joint")
                .find("controllers.car.front_steer': joint 'front_left_wheel_joint''s axis is not within 25 degrees"),
            std::string::npos)
      << refusal(", rear_wheel: rear_left_wheel_joint, front_steer: front_left_wheel_joint");
  EXPECT_NE(refusal(", rear_wheel: front_left_wheel_joint, front_steer: front_left_steer_joint")
                .find("controllers.car.rear_wheel': every driven wheel steers"),
            std::string::npos);
  EXPECT_NE(refusal(std::string(kLists) + ", wheel_separation_h: -1").find("controllers.car.wheel_separation_h"),
            std::string::npos);
  EXPECT_NE(refusal(", rear_wheel: [], front_steer: front_left_steer_joint").find("controllers.car.rear_wheel"),
            std::string::npos);
}

TEST(GazeboTricycleDrive, IsASteeredDriveOfItsMarkupsJoints) {
  const io::UrdfText text = io::readUrdfFile("tricycle_base.urdf", kTestUrdf);
  const io::SceneSetup s = io::loadScene(io::parseConfig(YAML::Load("{}")), [&] { return text; });
  ASSERT_EQ(s.controls.at(0).drives.size(), 1u);
  const core::DiffDriveSpec& d = s.controls[0].drives[0].spec();
  ASSERT_TRUE(d.steering.has_value());
  const core::SteeringSpec& st = *d.steering;
  EXPECT_EQ(d.name, "tricycle_drive");
  EXPECT_EQ(d.left.size(), 1u);
  EXPECT_EQ(d.wheel_radius, 0.1);  // actuatedWheelDiameter 0.2
  EXPECT_TRUE(st.speed_at_steered_wheel);
  EXPECT_EQ(st.steering_speed, 2.0);
  EXPECT_NEAR(st.wheelbase, 0.6, 1e-12);  // from the encoder wheels' axle
  EXPECT_NEAR(st.wheel_x.at(0), 0.6, 1e-12);
  EXPECT_EQ(st.wheel_steer.at(0), 0);
  EXPECT_EQ(d.settings.max_wheel_torque, 20.0);
  EXPECT_EQ(d.settings.linear.max_acceleration, 2.0);
  EXPECT_EQ(d.settings.linear.min_acceleration, -2.0);
  const io::DriveTopics& t = s.controls[0].drive_topics.at(0);
  EXPECT_FALSE(t.under_controller);
  EXPECT_EQ(t.cmd_vel_topic, "cmd_vel");
  EXPECT_EQ(t.base_frame_id, "base_link");
  EXPECT_EQ(t.publish_rate, 50.0);
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("<odometrySource> encoder (odometry from the driven wheel and the steering here)"),
            std::string::npos)
      << notes;
  EXPECT_NE(notes.find("<encoderWheelSeparation>"), std::string::npos) << notes;
}

// AgileX Hunter's way (test/ros/steer_bot_base.urdf): the controller on
// virtual joints, steer_bot_hardware_gazebo's map naming the real ones, and
// the knuckles' limits 0, which that plugin's robotSimType sets past.
constexpr const char* kSteerBot =
    "steer_bot_hardware_gazebo: {rear_wheel: rear_wheel_joint, front_steer: front_steer_joint, "
    "virtual_rear_wheels: [rear_left_wheel_joint, rear_right_wheel_joint], "
    "virtual_front_wheels: [front_left_wheel_joint, front_right_wheel_joint], "
    "virtual_front_steers: [front_left_steer_joint, front_right_steer_joint], wheel_separation_h: 0.6";
constexpr const char* kVirtualController =
    "controllers: {car: {type: ackermann_steering_controller/AckermannSteeringController, rear_wheel: "
    "rear_wheel_joint, front_steer: front_steer_joint, wheel_radius: 0.1}}";

io::SceneSetup steerBot(const std::string& map) {
  const io::UrdfText text = io::readUrdfFile("steer_bot_base.urdf", kTestUrdf);
  return io::loadScene(io::parseConfig(YAML::Load(map + "\n" + kVirtualController)), [&] { return text; });
}

TEST(SteerBotHardwareGazebo, ItsMapPutsTheAckermannControllerOnTheRealJoints) {
  const io::SceneSetup s =
      steerBot(std::string(kSteerBot) + ", enable_ackermann_link: false, wheel_separation_w: 0.5}");
  const core::DiffDriveSpec& d = s.controls.at(0).drives.at(0).spec();
  EXPECT_EQ(d.left.size(), 4u);  // the rear and the front wheels, all driven
  ASSERT_TRUE(d.steering.has_value());
  EXPECT_EQ(d.steering->joints.size(), 2u);
  EXPECT_NEAR(d.steering->wheelbase, 0.6, 1e-12);
  EXPECT_NEAR(d.steering->joint_y.at(0), 0.25, 1e-12);
  EXPECT_EQ(d.steering->wheel_steer.at(2), 0);  // the front left wheel turns with the left knuckle
  // The knuckles' effort and speed limits 0: none, said; the URDF's others kept.
  const core::ArticulationModel& model = s.scene.robots().at(0).model;
  for (const int j : d.steering->joints) {
    EXPECT_EQ(model.links[j].limits.effort, std::numeric_limits<double>::infinity());
    EXPECT_EQ(model.links[j].limits.upper, 0.6);
  }
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("the effort or speed limit 0 of 3 joints are read as none"), std::string::npos) << notes;
  EXPECT_NE(notes.find("steer_bot_hardware_gazebo.wheel_separation_w (the track is the URDF's knuckles' here)"),
            std::string::npos)
      << notes;
  EXPECT_NE(notes.find("steer_bot_hardware_gazebo.enable_ackermann_link (false, a parallel linkage"), std::string::npos)
      << notes;
}

TEST(SteerBotHardwareGazebo, RefusalsNameTheKey) {
  const auto refused = [](const std::string& map) {
    try {
      steerBot(map);
    } catch (const io::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::string m = refused("steer_bot_hardware_gazebo: {rear_wheel: rear_axle}");
  EXPECT_NE(m.find("'steer_bot_hardware_gazebo.virtual_rear_wheels': is missing"), std::string::npos) << m;
  m = refused(
      "steer_bot_hardware_gazebo: {front_steer: wheel, virtual_rear_wheels: [rear_left_wheel_joint], "
      "virtual_front_steers: [front_left_steer_joint]}");
  EXPECT_NE(m.find("'steer_bot_hardware_gazebo': no ackermann_steering_controller/AckermannSteeringController has "
                   "rear_wheel 'rear_wheel_joint' and front_steer 'wheel'"),
            std::string::npos)
      << m;
  m = refused(std::string(kSteerBot) + ", gains: {}}");
  EXPECT_NE(m.find("'steer_bot_hardware_gazebo.gains'"), std::string::npos) << m;
}

}  // namespace
}  // namespace rigid_body_sim::test
