// gazebo_ros_planar_move and gazebo_ros_force_based_move in a robot's markup
// (io/base_plugins.h): a base drive on the plugin's command topic and the
// truth's odometry in its odometry frame, on tf; the refusals name the element.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/scene_loader.h"

namespace rigid_body_sim::test {
namespace {

const std::string kBase = std::string(RBS_SOURCE_DIR) + "/test/ros/planar_move.urdf";

io::SimConfig config(const std::string& yaml) { return io::parseConfig(YAML::Load(yaml), RBS_SOURCE_DIR); }

/// test/ros/planar_move.urdf with its plugin replaced by `plugin` (none: "").
io::UrdfText base(const std::string& plugin) {
  io::UrdfText text = io::readUrdfFile(kBase, "");
  const std::size_t from = text.xml.rfind("<gazebo>"), to = text.xml.rfind("</gazebo>") + 9;
  text.xml.replace(from, to - from, plugin);
  return text;
}

std::string refusal(const io::SimConfig& c, const io::UrdfText& urdf) {
  try {
    io::loadScene(c, [&] { return urdf; });
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(accepted)";
}

// The box of 20 kg and the 0.1 kg mast above its centre: the yaw inertia
// about the centre of mass, the URDF's 0.86666667 (20 (0.6² + 0.4²) / 12) + 0.001.
constexpr double kMass = 20.1, kYawInertia = 0.86666667 + 0.001;

TEST(BaseMovePlugins, PlanarMoveDrivesTheBaseOnItsTopicAndReportsTheTruthInItsOdometryFrame) {
  const io::SceneSetup s = io::loadScene(config(""), [] { return io::readUrdfFile(kBase, ""); });
  const io::RobotControls& c = s.controls.at(0);
  ASSERT_TRUE(c.base_driver.has_value());
  EXPECT_EQ(c.base_driver_topic, "cmd_vel");
  const core::DriverSettings& d = c.base_driver->settings();
  EXPECT_TRUE(d.planar);
  EXPECT_EQ(d.timeout, 0.0);  // held, as the plugin holds it
  EXPECT_NEAR(d.max_force, 2.0 * 9.81 * kMass, 1e-9);
  EXPECT_NEAR(d.max_torque, 40.0 * kYawInertia, 1e-9);
  EXPECT_EQ(d.linear_gain, core::DriverSettings().linear_gain);  // the driver's own PI
  ASSERT_EQ(s.sensors.at(0).odometry.size(), 1u);
  const io::OdometryEntry& o = s.sensors[0].odometry[0].entry;
  EXPECT_EQ(o.link, "base_footprint");
  EXPECT_EQ(o.frame_id, "odom");
  EXPECT_EQ(o.topic, "odom");
  EXPECT_EQ(o.rate, 50.0);
  EXPECT_TRUE(o.on_tf);
  // The elements as a user gives them: another topic, a timeout, no tf.
  const io::SceneSetup t = io::loadScene(config(""), [] {
    return base(
        "<gazebo><plugin name='m' filename='libgazebo_ros_planar_move.so'><commandTopic>/base/cmd</commandTopic>"
        "<cmdTimeout>0.5</cmdTimeout><publishOdometryTf>false</publishOdometryTf><odometryFrame>map</odometryFrame>"
        "<robotBaseFrame>base_link</robotBaseFrame></plugin></gazebo>");
  });
  EXPECT_EQ(t.controls.at(0).base_driver_topic, "/base/cmd");
  EXPECT_EQ(t.controls[0].base_driver->settings().timeout, 0.5);
  const io::OdometryEntry& p = t.sensors.at(0).odometry.at(0).entry;
  EXPECT_FALSE(p.on_tf);
  EXPECT_EQ(p.frame_id, "map");
  EXPECT_EQ(p.link, "base_link");
  EXPECT_EQ(p.rate, 20.0);  // the plugin's default
  // No speed limit of its own (it sets the velocity in Gazebo): whatever
  // limits.* are raised to hold (it clipped at 500 m/s and 100 rad/s).
  EXPECT_EQ(t.controls[0].base_driver->settings().max_linear_speed, core::ranges::kMaxSpeedLimit);
  EXPECT_EQ(t.controls[0].base_driver->settings().max_angular_speed, core::ranges::kMaxSpeedLimit);
}

TEST(BaseMovePlugins, ForceBasedMovePushesWithItsOwnGainsPerKilogram) {
  const io::SceneSetup s = io::loadScene(config(""), [] {
    return base(
        "<gazebo><plugin name='f' filename='libgazebo_ros_force_based_move.so'><x_velocity_p_gain>2000"
        "</x_velocity_p_gain><y_velocity_p_gain>2000</y_velocity_p_gain><yaw_velocity_p_gain>50"
        "</yaw_velocity_p_gain></plugin></gazebo>");
  });
  const core::DriverSettings& d = s.controls.at(0).base_driver->settings();
  EXPECT_NEAR(d.linear_gain, 2000.0 / kMass, 1e-9);  // N per m/s over the mass: F = m k e
  EXPECT_NEAR(d.angular_gain, 50.0 / kYawInertia, 1e-9);
  EXPECT_EQ(d.linear_integral_gain, 0.0);  // its P law alone
  EXPECT_EQ(d.angular_integral_gain, 0.0);
  // Unequal x and y gains: the larger for both, and said.
  const io::SceneSetup u = io::loadScene(config(""), [] {
    return base(
        "<gazebo><plugin name='f' filename='libgazebo_ros_force_based_move.so'><x_velocity_p_gain>3000"
        "</x_velocity_p_gain></plugin></gazebo>");
  });
  EXPECT_NEAR(u.controls.at(0).base_driver->settings().linear_gain, 10000.0 / kMass, 1e-9);
  // Clearpath's copy (Ridgeback's, Dingo's): the same, its timeout cmdVelTimeOut.
  const io::SceneSetup r = io::loadScene(config(""), [] {
    return base(
        "<gazebo><plugin name='r' filename='libridgeback_ros_force_based_move.so'><cmdVelTimeOut>0.25"
        "</cmdVelTimeOut><yaw_velocity_p_gain>500</yaw_velocity_p_gain><publishOdometryTf>0</publishOdometryTf>"
        "</plugin></gazebo>");
  });
  EXPECT_EQ(r.controls.at(0).base_driver->settings().timeout, 0.25);
  EXPECT_NEAR(r.controls[0].base_driver->settings().angular_gain, 500.0 / kYawInertia, 1e-9);
  EXPECT_FALSE(r.sensors.at(0).odometry.at(0).entry.on_tf);
  std::string notes;
  for (const std::string& n : u.notes) notes += n;
  EXPECT_NE(notes.find("<x_velocity_p_gain> unlike <y_velocity_p_gain> (the larger for both) ('f')"), std::string::npos)
      << notes;
}

TEST(BaseMovePlugins, WhatNoBaseDriveCanHaveIsRefusedNamingIt) {
  const std::string planar = "<gazebo><plugin name='m' filename='libgazebo_ros_planar_move.so'/></gazebo>";
  EXPECT_NE(refusal(config(""), base(planar + planar)).find("<plugin name=\"m\">: a second plugin driving the base"),
            std::string::npos);
  EXPECT_NE(refusal(config("cmd_vel: {}"), base(planar))
                .find("config key 'cmd_vel': robot 'holonomic''s markup drives its base already"),
            std::string::npos)
      << refusal(config("cmd_vel: {}"), base(planar));
  EXPECT_NE(refusal(config(""), base("<gazebo><plugin name='f' filename='libgazebo_ros_force_based_move.so'>"
                                     "<yaw_velocity_p_gain>-1</yaw_velocity_p_gain></plugin></gazebo>"))
                .find("yaw_velocity_p_gain"),
            std::string::npos);
  EXPECT_NE(refusal(config(""), base("<gazebo><plugin name='m' filename='libgazebo_ros_planar_move.so'>"
                                     "<robotBaseFrame>chassis</robotBaseFrame></plugin></gazebo>"))
                .find("has no link 'chassis'"),
            std::string::npos);
  // Fixed to the world, nothing to drive.
  io::UrdfText fixed = base(planar);
  fixed.xml.replace(fixed.xml.find("<link name=\"base_footprint\"/>"), 29,
                    "<link name=\"world\"/><joint name=\"anchor\" type=\"fixed\"><parent link=\"world\"/>"
                    "<child link=\"base_footprint\"/></joint><link name=\"base_footprint\"/>");
  EXPECT_NE(refusal(config(""), fixed).find("is fixed to the world"), std::string::npos) << refusal(config(""), fixed);
}

}  // namespace
}  // namespace rigid_body_sim::test
