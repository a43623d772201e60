// gazebo_ros_ft_sensor in a robot's markup (io/gazebo_plugins.h,
// io/sensor_mount.h): a force-torque sensor on the moving joint it names;
// the refusals name the element, and one Gazebo would not load is said.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/scene_loader.h"

namespace rigid_body_sim::test {
namespace {

const std::string kArm = std::string(RBS_SOURCE_DIR) + "/test/ros/ft_sensor.urdf";

io::SimConfig config() { return io::parseConfig(YAML::Load(""), RBS_SOURCE_DIR); }

/// test/ros/ft_sensor.urdf with its plugin's elements replaced by `elements`.
io::UrdfText arm(const std::string& elements) {
  io::UrdfText text = io::readUrdfFile(kArm, "");
  const std::size_t from = text.xml.find("<updateRate>"), to = text.xml.find("</plugin>");
  text.xml.replace(from, to - from, elements);
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

}  // namespace
}  // namespace rigid_body_sim::test
