// Model plugins of a robot's markup (io/gazebo_plugins.h, io/sensor_mount.h):
// gazebo_ros_ft_sensor, a force-torque sensor on the moving joint it names,
// and Kobuki's gazebo_ros_kobuki, a DiffDriveController on its topics with
// the IMU it names; the refusals name the element, and what Gazebo would
// not load, or what is not run, is said.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/scene_loader.h"

namespace rigid_body_sim::test {
namespace {

const std::string kArm = std::string(RBS_SOURCE_DIR) + "/test/ros/ft_sensor.urdf";
const std::string kKobuki = std::string(RBS_SOURCE_DIR) + "/test/ros/kobuki_base.urdf";

io::SimConfig config() { return io::parseConfig(YAML::Load(""), RBS_SOURCE_DIR); }

/// test/ros/ft_sensor.urdf with its plugin's elements replaced by `elements`.
io::UrdfText arm(const std::string& elements) {
  io::UrdfText text = io::readUrdfFile(kArm, "");
  const std::size_t from = text.xml.find("<updateRate>"), to = text.xml.find("</plugin>");
  text.xml.replace(from, to - from, elements);
  return text;
}

/// `file` with the text `from` replaced by `to`.
io::UrdfText edited(const std::string& file, const std::string& from, const std::string& to) {
  io::UrdfText text = io::readUrdfFile(file, "");
  text.xml.replace(text.xml.find(from), from.size(), to);
  return text;
}

std::string refusal(const io::UrdfText& urdf) {
  try {
    io::loadScene(config(), [&] { return urdf; });
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(GazeboForceTorque, TheFtSensorPluginIsASensorOnTheJointItNames) {
  const io::SceneSetup s = io::loadScene(config(), [] { return io::readUrdfFile(kArm, ""); });
  ASSERT_EQ(s.sensors.at(0).force_torques.size(), 1u);
  const io::RobotForceTorque& f = s.sensors[0].force_torques[0];
  EXPECT_EQ(f.link, 1);  // the bar, the shoulder's child
  EXPECT_EQ(f.entry.joint, "shoulder");
  EXPECT_EQ(f.entry.topic, "ft");
  EXPECT_EQ(f.entry.rate, 100.0);
  EXPECT_EQ(f.entry.settings.noise, 0.0);
  // Every step without a rate; its noise as given.
  const io::SceneSetup t = io::loadScene(config(), [] {
    return arm("<topicName>/wrist/ft</topicName><jointName>shoulder</jointName><gaussianNoise>0.2</gaussianNoise>");
  });
  EXPECT_EQ(t.sensors.at(0).force_torques.at(0).entry.rate, 0.0);
  EXPECT_EQ(t.sensors[0].force_torques[0].entry.settings.noise, 0.2);
  EXPECT_EQ(t.sensors[0].force_torques[0].entry.topic, "/wrist/ft");
}

TEST(GazeboForceTorque, WhatTheSensorCannotHaveIsRefusedNamingItAndAJointGazeboLumpsIsSaid) {
  EXPECT_NE(refusal(arm("<topicName>ft</topicName>")).find("<plugin name=\"ft_sensor\">: <jointName> is required"),
            std::string::npos);
  EXPECT_NE(refusal(arm("<jointName>shoulder</jointName>")).find("<topicName> is required"), std::string::npos);
  EXPECT_NE(refusal(arm("<topicName>ft</topicName><jointName>shoulder</jointName><gaussianNoise>-1</gaussianNoise>"))
                .find("gaussianNoise"),
            std::string::npos);
  EXPECT_NE(refusal(arm("<topicName>ft</topicName><jointName>shoulder</jointName><updateRate>nan</updateRate>"))
                .find("updateRate"),
            std::string::npos);
  // No moving joint of that name (a fixed one is lumped away, as Gazebo
  // lumps it): said, and not run.
  const io::SceneSetup s =
      io::loadScene(config(), [] { return arm("<topicName>ft</topicName><jointName>wrist_ft</jointName>"); });
  EXPECT_TRUE(s.sensors.at(0).force_torques.empty());
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("has no moving joint 'wrist_ft'"), std::string::npos) << notes;
  EXPECT_NE(notes.find("its moving joints: 'shoulder'"), std::string::npos) << notes;
}

TEST(GazeboKobuki, KobukisPluginIsADiffDriveControllerOnItsTopicsWithTheImuItNames) {
  const io::SceneSetup s = io::loadScene(config(), [] { return io::readUrdfFile(kKobuki, ""); });
  ASSERT_EQ(s.controls.at(0).drives.size(), 1u);
  const core::DiffDriveSpec& d = s.controls[0].drives[0].spec();
  EXPECT_EQ(d.name, "kobuki_controller");
  EXPECT_EQ(d.wheel_separation, 0.36);
  EXPECT_EQ(d.wheel_radius, 0.06);
  EXPECT_EQ(d.settings.max_wheel_torque, 5.0);
  EXPECT_EQ(d.settings.cmd_vel_timeout, 0.6);
  const io::DriveTopics& t = s.controls[0].drive_topics.at(0);
  EXPECT_FALSE(t.under_controller);
  EXPECT_EQ(t.cmd_vel_topic, "mobile_base/commands/velocity");
  EXPECT_EQ(t.odom_topic, "odom");
  EXPECT_EQ(t.base_frame_id, "base_footprint");
  EXPECT_TRUE(t.enable_odom_tf);  // <publish_tf>1
  ASSERT_EQ(s.sensors.at(0).imus.size(), 1u);
  const io::RobotImu& imu = s.sensors[0].imus[0];
  EXPECT_EQ(imu.entry.topic, "mobile_base/sensors/imu_data");
  EXPECT_EQ(imu.entry.frame_id, "base_link");
  EXPECT_EQ(imu.entry.settings.accel_noise, 1.7e-2);
  EXPECT_EQ(imu.entry.settings.gyro_noise, 1.96e-6);
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("cliff, bumper and wheel-drop events"), std::string::npos) << notes;
  EXPECT_NE(notes.find("odometry heading from its gyro"), std::string::npos) << notes;
}

TEST(GazeboKobuki, WhatItsPluginRequiresIsRefusedNamingIt) {
  EXPECT_NE(refusal(edited(kKobuki, "<wheel_separation>0.36</wheel_separation>", ""))
                .find("<plugin name=\"kobuki_controller\">: <wheel_separation> is required"),
            std::string::npos);
  EXPECT_NE(refusal(edited(kKobuki, "<imu_name>imu</imu_name>", "<imu_name>gyro</imu_name>"))
                .find("the robot has no <sensor type=\"imu\" name=\"gyro\">"),
            std::string::npos);
  EXPECT_NE(refusal(edited(kKobuki, "<torque>5.0</torque>", "<torque>-1</torque>")).find("torque"), std::string::npos);
  EXPECT_NE(refusal(edited(kKobuki, "<publish_tf>1</publish_tf>", "<publish_tf>maybe</publish_tf>")).find("publish_tf"),
            std::string::npos);
}

}  // namespace
}  // namespace rigid_body_sim::test
