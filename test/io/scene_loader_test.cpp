// A world of bodies and robots from a config (io/scene_loader.h): each entry
// a body or a robot by its URDF, in the config's order; a robot's start and
// surface from its entry; the refusals name the key.
#include "rigid_body_sim/io/scene_loader.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <limits>
#include <string>
#include <vector>

#include "../test_util.h"
#include "rigid_body_sim/core/devices/depth_camera.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/transmissions.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/io/world.h"

namespace rigid_body_sim::test {
namespace {

const std::string kUrdf = std::string(RBS_SOURCE_DIR) + "/urdf/";

io::SimConfig config(const std::string& yaml) { return io::parseConfig(YAML::Load(yaml), kUrdf); }

TEST(SceneLoader, TellsRobotsFromBodiesAndKeepsTheConfigsOrder) {
  const io::SimConfig c = config(R"(
bodies:
  - {name: a, urdf: box.urdf, initial: {position: [1, 0, 0.05]}}
  - name: swing
    urdf: pendulum.urdf
    contact: {friction: 0.9}
    initial: {position: [0, 0, -0.4], joint_positions: {pivot: 0.5}, joint_velocities: {pivot: -1}}
  - {name: b, urdf: box.urdf, initial: {position: [2, 0, 0.05]}}
)");
  EXPECT_TRUE(io::listsRobots(c));
  EXPECT_FALSE(io::listsRobots(config("bodies: [{name: a, urdf: box.urdf}]")));
  const io::SceneSetup s = io::buildScene(c);
  EXPECT_EQ(s.entry, (std::vector<int>{0, -1, 1}));
  ASSERT_EQ(s.scene.freeBodyCount(), 2u);
  EXPECT_EQ(s.scene.model().body(1).name, "b");
  EXPECT_EQ(s.state.bodies.bodies[1].p_WB.x(), 2.0);
  ASSERT_EQ(s.scene.robots().size(), 1u);
  const core::SceneRobot& swing = s.scene.robots()[0];
  EXPECT_EQ(swing.name, "swing");
  EXPECT_EQ(s.state.robots[0].X_WB.translation, Vec3(0, 0, -0.4));
  EXPECT_EQ(s.state.robots[0].q(0), 0.5);
  EXPECT_EQ(s.state.robots[0].v(0), -1.0);
  // Its rod is a body after the free ones, with the entry's surface, placed
  // where the joint puts it.
  ASSERT_EQ(swing.link.size(), 1u);
  EXPECT_EQ(swing.first_body, 2);
  EXPECT_EQ(s.scene.robotOf(2), 0);
  EXPECT_EQ(s.scene.model().body(2).name, "swing/rod");  // two robots of one URDF do not clash
  EXPECT_EQ(s.scene.model().body(2).friction, 0.9);
  const Vec3 rod = s.state.bodies.bodies[2].p_WB;  // 0.25 m down the rod from the pivot at z = 0.6
  EXPECT_LT((rod - Vec3(-0.25 * std::sin(0.5), 0.0, 0.6 - 0.25 * std::cos(0.5))).norm(), 1e-12);
}

// A body's URDF with Gazebo markup (<gazebo reference="ROOT"><mu1>, <mu2>)
// gives the body its surface as it gives a robot's link one (the smaller);
// an entry's own contact.friction wins over it; without either, the scene's.
TEST(SceneLoader, ABodysGazeboFrictionIsItsSurfaceUnlessItsEntryGivesOne) {
  const std::string slippery =
      "<robot name='puck'><link name='puck'><inertial><mass value='1'/><inertia ixx='0.01' iyy='0.01' izz='0.01' "
      "ixy='0' ixz='0' iyz='0'/></inertial><collision><geometry><box size='0.2 0.2 0.1'/></geometry></collision>"
      "</link><gazebo reference='puck'><mu1>0.3</mu1><mu2>0.2</mu2></gazebo></robot>";
  EXPECT_EQ(io::loadUrdfString(slippery, "puck.urdf").friction, 0.2);
  const io::SimConfig c = config(R"(
contact: {friction: 0.6}
bodies:
  - {name: a, urdf: puck.urdf}
  - {name: b, urdf: puck.urdf, contact: {friction: 0.9}}
  - {name: c, urdf: box.urdf}
)");
  const io::UrdfReader read = [&](const io::BodyEntry& e) -> io::UrdfText {
    if (e.urdf.find("puck.urdf") != std::string::npos) return {slippery, e.urdf, ""};
    return io::readUrdfFile(e.urdf, kUrdf);
  };
  const io::SceneSetup s = io::buildScene(c, read);
  ASSERT_EQ(s.scene.freeBodyCount(), 3u);
  EXPECT_EQ(s.scene.model().body(0).friction, 0.2);
  EXPECT_EQ(s.scene.model().body(1).friction, 0.9);
  EXPECT_EQ(s.scene.model().body(2).friction, 0.6);
  // The world of bodies alone (io::buildWorld, the node's path without
  // robots) reads it alike.
  const io::World w =
      io::loadWorld(c, {}, [&](const io::BodyEntry& e) { return io::loadUrdfString(read(e).xml, e.urdf); });
  EXPECT_EQ(w.model.body(0).friction, 0.2);
  EXPECT_EQ(w.model.body(1).friction, 0.9);
  EXPECT_EQ(w.model.body(2).friction, 0.6);
}

// A link lumped into a body keeps its own surface on its shapes (TurtleBot3's
// caster, a box on a fixed link with <mu1>0.1</mu1>, took its base's before):
// a sled whose root link (mu 1) rides on a runner link's box (mu 0.1) slides
// at the runner's mu, slowing by mu g; an entry's own friction is the whole
// body's.
TEST(SceneLoader, ALumpedLinkKeepsItsOwnFrictionOnItsShapes) {
  const std::string sled =
      "<robot name='sled'><link name='seat'><inertial><mass value='1'/><inertia ixx='0.01' iyy='0.01' izz='0.01' "
      "ixy='0' ixz='0' iyz='0'/></inertial><collision><origin xyz='0 0 0.2'/><geometry><box size='0.2 0.2 0.2'/>"
      "</geometry></collision></link><joint name='fix' type='fixed'><parent link='seat'/><child link='runner'/>"
      "</joint><link name='runner'><collision><origin xyz='0 0 0.01'/><geometry><box size='0.4 0.2 0.02'/>"
      "</geometry></collision></link><gazebo reference='seat'><mu1>1</mu1><mu2>1</mu2></gazebo>"
      "<gazebo reference='runner'><mu1>0.1</mu1><mu2>0.1</mu2></gazebo></robot>";
  const io::SimConfig c = config(R"(
contact: {friction: 1.0}
bodies:
  - {name: a, urdf: sled.urdf, initial: {linear_velocity: [1, 0, 0]}}
  - {name: b, urdf: sled.urdf, initial: {position: [0, 2, 0], linear_velocity: [1, 0, 0]}, contact: {friction: 0.8}}
)");
  io::SceneSetup s = io::buildScene(c, [&](const io::BodyEntry& e) -> io::UrdfText { return {sled, e.urdf, ""}; });
  const core::BodyModel& a = s.scene.model().body(0);
  EXPECT_EQ(a.friction, 1.0);
  EXPECT_EQ(std::vector<double>(a.surface_friction), std::vector<double>{0.1});
  EXPECT_TRUE(s.scene.model().body(1).surface_friction.empty());
  core::SceneWorkspace ws;
  core::SceneLoads loads;
  for (int n = 0; n < 500; ++n) core::stepScene(s.scene, s.state, loads, ws);
  // v = 1 - mu g t at t = 0.5 s: 0.5095 m/s on the runner's 0.1; the entry's 0.8 stops it at 0.13 s.
  EXPECT_NEAR(s.state.bodies.bodies[0].v_WB.x(), 1.0 - 0.1 * 9.81 * 0.5, 0.005);
  EXPECT_NEAR(s.state.bodies.bodies[1].v_WB.x(), 0.0, 1e-3);
}

TEST(SceneLoader, RefusesWhatAnEntryWouldNotRead) {
  const auto refused = [](const std::string& yaml, const std::string& what) {
    try {
      io::buildScene(config(yaml));
      ADD_FAILURE() << "accepted: " << yaml;
    } catch (const io::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  const std::string swing = "  - {name: swing, urdf: pendulum.urdf}\n";
  refused("bodies:\n" + swing + "  - {name: a, urdf: box.urdf, initial: {joint_positions: {pivot: 1}}}\n",
          "'bodies[1].initial.joint_positions' / '.joint_velocities': body 'a' has no moving joints");
  refused("bodies:\n  - {name: swing, urdf: pendulum.urdf, initial: {linear_velocity: [1, 0, 0]}}\n",
          "'bodies[0].initial.linear_velocity'");
  refused("bodies:\n  - {name: swing, urdf: pendulum.urdf, initial: {joint_positions: {elbow: 1}}}\n", "elbow");
  refused("bodies:\n  - {name: swing, urdf: pendulum.urdf, cmd_vel: {}}\n", "'bodies[0].cmd_vel': robot 'swing'");
  refused("bodies:\n  - {name: rover, urdf: diff_drive.urdf, imu: {link: mast}}\n",
          "'bodies[0].imu.link': robot 'rover' has no link 'mast'");
  refused("bodies:\n  - {name: rover, urdf: diff_drive.urdf, imu: {topic: 'a b'}}\n",
          "bodies[0].imu: topic 'a b' is no ROS name");
  refused("damping: {linear: 0.1}\nbodies:\n" + swing, "'damping': robot 'swing'");
  // A lidar goes on a link the robot has, with settings a lidar can have.
  refused("bodies:\n  - {name: a, urdf: box.urdf, lidar: {link: base_link}}\n",
          "'bodies[0].lidar': body 'a' has no moving joints");
  refused("bodies:\n  - {name: rover, urdf: diff_drive.urdf, lidar: {link: laser}}\n",
          "'bodies[0].lidar.link': robot 'rover' has no link 'laser' (its links: 'base_link', 'caster', ");
  refused("bodies:\n  - {name: rover, urdf: diff_drive.urdf, lidar: [{link: caster}, {samples: 3}]}\n",
          "'bodies[0].lidar[1].link': is missing");
  refused("bodies:\n  - {name: rover, urdf: diff_drive.urdf, lidar: {link: caster, min_range: 3, max_range: 2}}\n",
          "'bodies[0].lidar': ranges must be 0 <= min_range < max_range");
  refused("bodies:\n  - {name: rover, urdf: diff_drive.urdf, lidar: {link: caster, samples: 1.5}}\n",
          "'bodies[0].lidar.samples'");
  refused("bodies:\n  - {name: rover, urdf: diff_drive.urdf, lidar: {link: caster, beams: 3}}\n", "beams");
  refused("bodies:\n  - {name: rover, urdf: diff_drive.urdf, depth_camera: {link: caster, hfov: 3.2}}\n",
          "'bodies[0].depth_camera': hfov must be within [0.001, pi) rad");
  refused("bodies:\n  - {name: rover, urdf: diff_drive.urdf, depth_camera: {link: caster, encoding: rgb8}}\n",
          "'bodies[0].depth_camera.encoding': 'rgb8': 32FC1 (m) or 16UC1 (mm)");
  refused("bodies:\n  - {name: rover, urdf: diff_drive.urdf, depth_camera: {link: lens}}\n",
          "'bodies[0].depth_camera.link': robot 'rover' has no link 'lens'");
}

TEST(SceneLoader, ALidarSitsOnItsLinkOrWhereAFixedJointPutsIt) {
  const io::SceneSetup s = io::buildScene(
      config("bodies:\n  - {name: rover, urdf: diff_drive.urdf, lidar: [{link: left_wheel, topic: wheel_scan},"
             " {link: caster, samples: 10, vertical_samples: 2, rate: 5}]}\n"));
  ASSERT_EQ(s.sensors.size(), 1u);
  ASSERT_EQ(s.sensors[0].lidars.size(), 2u);
  const io::RobotLidar& wheel = s.sensors[0].lidars[0];
  EXPECT_EQ(s.scene.robots()[0].model.links.at(static_cast<std::size_t>(wheel.link)).name, "left_wheel");
  EXPECT_EQ(wheel.X_LS.translation, Vec3::Zero());
  EXPECT_EQ(wheel.entry.topic, "wheel_scan");
  // The caster is fixed to base_link 0.15 m behind and 0.04 m below its origin (urdf/diff_drive.urdf).
  const io::RobotLidar& caster = s.sensors[0].lidars[1];
  EXPECT_EQ(caster.link, 0);
  EXPECT_EQ(caster.X_LS.translation, Vec3(-0.15, 0.0, -0.04));
  EXPECT_EQ(caster.entry.rate, 5.0);
  EXPECT_EQ(caster.entry.settings.vertical_samples, 2);
  EXPECT_EQ(caster.entry.topic, "scan");
  const io::SceneSetup c = io::buildScene(
      config("bodies:\n  - {name: rover, urdf: diff_drive.urdf, depth_camera: {link: caster, width: 8, height: 6,"
             " encoding: 16UC1, pose: {position: [0, 0, 0.1]}}}\n"));
  ASSERT_EQ(c.sensors.at(0).cameras.size(), 1u);
  EXPECT_EQ(c.sensors[0].cameras[0].link, 0);
  EXPECT_LT((c.sensors[0].cameras[0].X_LS.translation - Vec3(-0.15, 0.0, 0.06)).norm(),
            1e-15);  // its pose in the caster
  EXPECT_TRUE(c.sensors[0].cameras[0].entry.millimetres);
  EXPECT_EQ(c.sensors[0].cameras[0].entry.settings.width, 8);
}

TEST(SceneLoader, ARobotsOdomNoiseIsItsBasesOdometry) {
  const io::SceneSetup s = io::buildScene(
      config("bodies:\n  - {name: rover, urdf: diff_drive.urdf, odom_noise: {position: 0.02, drift: {x: 0.1}}}\n"));
  ASSERT_EQ(s.sensors.at(0).odometry.size(), 1u);
  const io::RobotOdometry& o = s.sensors[0].odometry[0];
  EXPECT_EQ(o.link, 0);
  EXPECT_EQ(o.entry.link, "base_link");
  EXPECT_EQ(o.entry.topic, "odom");
  EXPECT_EQ(o.entry.ground_truth, "ground_truth");
  EXPECT_EQ(o.entry.rate, 0.0);  // the node's publish rate
  ASSERT_TRUE(o.entry.noise.has_value());
  EXPECT_EQ(o.entry.noise->position, 0.02);
  EXPECT_EQ(o.entry.noise->drift_x, 0.1);
}

TEST(SceneLoader, AnImuSitsOnAnyLinkOfARobot) {
  const io::SceneSetup s = io::buildScene(
      config("bodies:\n  - {name: rover, urdf: diff_drive.urdf, imu: {link: left_wheel, topic: wheel_imu,"
             " pose: {position: [0, 0.02, 0], rpy: [1.5707963267948966, 0, 0]}, rate: 50}}\n"
             "  - {name: other, urdf: diff_drive.urdf, imu: {frame_id: caster}}\n"
             "  - {name: third, urdf: diff_drive.urdf, imu: {}}\n"));
  ASSERT_EQ(s.sensors.size(), 3u);
  const io::RobotImu& wheel = s.sensors[0].imus.at(0);
  EXPECT_EQ(s.scene.robots()[0].model.links.at(static_cast<std::size_t>(wheel.link)).name, "left_wheel");
  EXPECT_EQ(wheel.entry.settings.X_LS.translation, Vec3(0, 0.02, 0));
  EXPECT_LT((wheel.entry.settings.X_LS.rotation * Vec3::UnitZ() + Vec3::UnitY()).norm(), 1e-15);  // rolled a quarter
  EXPECT_EQ(wheel.entry.frame_id, "left_wheel");  // no frame_id: the link's
  EXPECT_EQ(wheel.entry.topic, "wheel_imu");
  EXPECT_EQ(wheel.entry.settings.rate, 50.0);
  // frame_id naming a frame of the robot and no link: it sits there (the
  // caster, fixed 0.15 m behind and 0.04 m below base_link's origin).
  const io::RobotImu& caster = s.sensors[1].imus.at(0);
  EXPECT_EQ(caster.link, 0);
  EXPECT_EQ(caster.entry.settings.X_LS.translation, Vec3(-0.15, 0.0, -0.04));
  EXPECT_EQ(caster.entry.frame_id, "caster");
  const io::RobotImu& base = s.sensors[2].imus.at(0);  // neither: the base, its frame
  EXPECT_EQ(base.link, 0);
  EXPECT_EQ(base.entry.frame_id, "base_link");
  EXPECT_EQ(base.entry.topic, "imu");
}

}  // namespace
}  // namespace rigid_body_sim::test

namespace rigid_body_sim::test {
namespace {

/// A base with a wheel and a laser_link fixed 0.1 m ahead and 0.2 m up, with `markup` inside its <robot>.
io::UrdfText laserRobot(const std::string& markup) {
  const std::string inertial =
      "<inertial><mass value='1'/><inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial>";
  return {"<robot name='scout'><link name='base_link'>" + inertial +
              "<collision><geometry><box size='0.4 0.3 0.1'/></geometry></collision></link>"
              "<joint name='axle' type='continuous'><parent link='base_link'/><child link='wheel'/>"
              "<origin xyz='0 0.2 0'/><axis xyz='0 1 0'/></joint><link name='wheel'>" +
              inertial +
              "</link><joint name='laser_mount' type='fixed'><parent link='base_link'/><child link='laser_link'/>"
              "<origin xyz='0.1 0 0.2'/></joint><link name='laser_link'/>" +
              markup + "</robot>",
          "scout.urdf", ""};
}

const std::string kLaser =
    "<gazebo reference='laser_link'><sensor type='ray' name='front'><pose>0 0 0.05 0 0 1.5707963267948966</pose>"
    "<update_rate>20</update_rate><ray><scan><horizontal><samples>180</samples><resolution>2</resolution>"
    "<min_angle>-1.5</min_angle><max_angle>1.5</max_angle></horizontal></scan>"
    "<range><min>0.2</min><max>12</max><resolution>0.01</resolution></range>"
    "<noise><type>gaussian</type><mean>0.0</mean><stddev>0.01</stddev></noise></ray>"
    "<plugin name='laser' filename='libgazebo_ros_laser.so'><topicName>/scout/scan</topicName>"
    "<frameName>laser_link</frameName></plugin></sensor></gazebo>";

TEST(GazeboLidars, ARaySensorWithARosPluginIsALidarWithItsMarkupsSettings) {
  const std::string velodyne =
      "<gazebo reference='base_link'><sensor type='gpu_ray' name='velo'><ray><scan><horizontal><samples>100</samples>"
      "<min_angle>-3.14</min_angle><max_angle>3.14</max_angle></horizontal><vertical><samples>16</samples>"
      "<min_angle>-0.26</min_angle><max_angle>0.26</max_angle></vertical></scan><range><min>0.3</min><max>100</max>"
      "</range></ray><plugin name='v' filename='libgazebo_ros_velodyne_gpu_laser.so'><topicName>velodyne_points"
      "</topicName><min_range>0.9</min_range><max_range>130</max_range><gaussianNoise>0.008</gaussianNoise>"
      "<organize_cloud>true</organize_cloud></plugin></sensor></gazebo><gazebo reference='base_link'><sensor "
      "type='camera' name='cam'/></gazebo>";
  const io::SceneSetup s = io::loadScene(config(""), [&] { return laserRobot(kLaser + velodyne); });
  ASSERT_EQ(s.sensors.size(), 1u);
  ASSERT_EQ(s.sensors[0].lidars.size(), 2u);
  const io::RobotLidar& laser = s.sensors[0].lidars[0];
  EXPECT_EQ(laser.link, 0);  // laser_link is lumped into base_link
  EXPECT_LT((laser.X_LS.translation - Vec3(0.1, 0.0, 0.25)).norm(), 1e-15);
  EXPECT_LT((laser.X_LS.rotation * Vec3::UnitX() - Vec3::UnitY()).norm(), 1e-15);  // turned a quarter about z
  const core::LidarSettings& l = laser.entry.settings;
  EXPECT_EQ(l.samples, 360);  // samples x resolution
  EXPECT_EQ(l.min_angle, -1.5);
  EXPECT_EQ(l.max_angle, 1.5);
  EXPECT_EQ(l.min_range, 0.2);
  EXPECT_EQ(l.max_range, 12.0);
  EXPECT_EQ(l.noise, 0.01);
  EXPECT_EQ(laser.entry.rate, 20.0);
  EXPECT_EQ(laser.entry.topic, "/scout/scan");
  EXPECT_EQ(laser.entry.frame_id, "laser_link");
  const io::LidarEntry& velo = s.sensors[0].lidars[1].entry;
  EXPECT_EQ(velo.settings.samples, 100);
  EXPECT_EQ(velo.settings.vertical_samples, 16);
  EXPECT_EQ(velo.settings.vertical_min_angle, -0.26);
  EXPECT_EQ(velo.settings.min_range, 0.9);  // the plugin's over the sensor's
  EXPECT_EQ(velo.settings.max_range, 130.0);
  EXPECT_EQ(velo.settings.noise, 0.008);
  EXPECT_EQ(velo.topic, "velodyne_points");
  EXPECT_TRUE(velo.organized);
  EXPECT_FALSE(laser.entry.organized);
  EXPECT_EQ(velo.frame_id, "");
  // The camera is named as markup nothing runs; the lidars are not.
  std::string markup;
  for (const std::string& note : s.notes) {
    if (note.find("markup for Gazebo") != std::string::npos) markup = note;
  }
  EXPECT_NE(markup.find("<sensor type=\"camera\"> ('base_link')"), std::string::npos) << markup;
  EXPECT_EQ(markup.find("ray"), std::string::npos) << markup;
}

TEST(GazeboLidars, ANumberTheMarkupCannotHoldIsRefusedNamingIt) {
  std::string bad = kLaser;
  bad.replace(bad.find("<samples>180"), 12, "<samples>many");
  try {
    io::loadScene(config(""), [&] { return laserRobot(bad); });
    ADD_FAILURE() << "accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "<gazebo reference=\"laser_link\"> <sensor name=\"front\"> <scan/horizontal/samples> = 'many'"),
              std::string::npos)
        << e.what();
  }
  // A lidar's settings it cannot have (min above max) are refused naming the markup.
  std::string wrong = kLaser;
  wrong.replace(wrong.find("<min>0.2"), 8, "<min>20");
  try {
    io::loadScene(config(""), [&] { return laserRobot(wrong); });
    ADD_FAILURE() << "accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("<sensor name=\"front\">"), std::string::npos) << e.what();
  }
}

// Counts and rates the markup gives are read as Gazebo's types and ranges,
// or refused naming the element: <samples>4294967297</samples> wrapped to one
// ray, -360 with <resolution>-1</resolution> was read as 360; a lidar's
// angles of ±1e39 and a range of 1e39 reached LaserScan as inf; a pose of
// 1e300 m was taken.
TEST(GazeboLidars, ACountRateOrRangeGazeboWouldNotHoldIsRefusedNamingIt) {
  const auto refusal = [](const std::string& from, const std::string& to) -> std::string {
    std::string markup = kLaser;
    const std::size_t at = markup.find(from);
    if (at == std::string::npos) return "(no '" + from + "' in the markup)";
    markup.replace(at, from.size(), to);
    try {
      io::loadScene(config(""), [&] { return laserRobot(markup); });
    } catch (const std::exception& e) {
      return e.what();
    }
    return "(accepted)";
  };
  const std::string sensor = "<sensor name=\"front\"> ";
  const struct {
    const char *from, *to, *why;
  } cases[] = {
      {"<samples>180", "<samples>4294967297", "<scan/horizontal/samples> = '4294967297': must be within [1, 1e+06]"},
      {"<samples>180", "<samples>-360", "<scan/horizontal/samples> = '-360'"},
      {"<samples>180", "<samples>180.5", "<scan/horizontal/samples> = '180.5': must be a whole number"},
      {"<resolution>2", "<resolution>-1", "<scan/horizontal/resolution> = '-1': must be within (0, 1e+06]"},
      {"<resolution>2", "<resolution>1e6", "x <resolution>"},
      {"<min_angle>-1.5", "<min_angle>-1e39", "min_angle and max_angle must be within [-4 pi, 4 pi]"},
      {"<max>12", "<max>1e39", "max_range must be <= 1e5 m"},
      {"<update_rate>20", "<update_rate>1e9", "<update_rate> = '1e9': must be 0"},
      {"<update_rate>20", "<update_rate>-1", "<update_rate> = '-1': must be 0"},
      {"<pose>0 0 0.05", "<pose>0 0 1e39", "the sensor is more than 1000 m from its link"},
  };
  for (const auto& c : cases) {
    const std::string got = refusal(c.from, c.to);
    EXPECT_NE(got.find(c.why), std::string::npos) << c.to << ": " << got;
    EXPECT_NE(got.find("front"), std::string::npos) << c.to << ": " << got;
  }
  EXPECT_EQ(refusal("<update_rate>20", "<update_rate>0"), "(accepted)");  // Gazebo's "every step": 10 Hz, said
  // A frame id tf2 would not take; a leading '/' is dropped, as gazebo_ros's tf::resolve drops it.
  EXPECT_NE(refusal("<frameName>laser_link", "<frameName>bad frame#!")
                .find("<plugin> <frameName>: 'bad frame#!' is no tf frame id"),
            std::string::npos);
  std::string slash = kLaser;
  slash.replace(slash.find("<frameName>laser_link"), 21, "<frameName>/laser_link");
  const io::SceneSetup s = io::loadScene(config(""), [&] { return laserRobot(slash); });
  EXPECT_EQ(s.sensors.at(0).lidars.at(0).entry.frame_id, "laser_link");
}

// A depth camera's image size is a count, its field of view SDF's range.
TEST(GazeboCameras, ASizeOrFieldOfViewGazeboWouldNotHoldIsRefusedNamingIt) {
  const auto camera = [](const std::string& fov, const std::string& width) {
    return "<gazebo reference='base_link'><sensor type='depth' name='cam'><camera><horizontal_fov>" + fov +
           "</horizontal_fov><image><width>" + width +
           "</width><height>48</height></image></camera><plugin name='k' filename='libgazebo_ros_openni_kinect.so'/>"
           "</sensor></gazebo>";
  };
  const auto refusal = [](const std::string& markup) -> std::string {
    try {
      io::loadScene(config(""), [&] { return laserRobot(markup); });
    } catch (const std::exception& e) {
      return e.what();
    }
    return "(accepted)";
  };
  EXPECT_NE(refusal(camera("1e-320", "64")).find("hfov must be within [0.001, pi)"), std::string::npos);
  EXPECT_NE(refusal(camera("1", "-64")).find("<image/width> = '-64'"), std::string::npos);
  EXPECT_NE(refusal(camera("1", "64.5")).find("must be a whole number"), std::string::npos);
  EXPECT_NE(refusal(camera("1", "1e10")).find("<image/width> = '1e10'"), std::string::npos);
  EXPECT_EQ(refusal(camera("1", "64")), "(accepted)");
}

// What the lidars and depth cameras may hold (devices.memory) is counted
// before any is built: 40 depth cameras of 2000 x 2000 once ended the node
// in std::bad_alloc naming no key; a URDF with 400 took 5.8 GB.
TEST(DeviceMemory, EachLidarAndCameraIsCountedBeforeItIsBuiltAndRefusedBeyondTheBudget) {
  std::string cameras = "[";
  for (int k = 0; k < 8; ++k) cameras += std::string(k ? ", " : "") + "{link: base_link, width: 2000, height: 2000}";
  cameras += "]";
  try {
    io::loadScene(config("depth_camera: " + cameras), [&] { return laserRobot(""); });
    ADD_FAILURE() << "eight 2000 x 2000 cameras in the default 1024 MiB";
  } catch (const io::ConfigError& e) {
    // 2000 x 2000 x 80 bytes = 306 MiB each: the fourth is beyond 1024 MiB.
    EXPECT_NE(std::string(e.what()).find("config key 'depth_camera[3]': the device would hold 306 MiB"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("devices.memory = 1024 MiB in all (916 MiB of it counted before"),
              std::string::npos)
        << e.what();
  }
  const io::SceneSetup s =
      io::loadScene(config("devices: {memory: 4096}\ndepth_camera: " + cameras), [&] { return laserRobot(""); });
  EXPECT_EQ(s.sensors.at(0).cameras.size(), 8u);
  EXPECT_EQ(s.sensors[0].bytes, 8u * core::depthCameraBytes(s.sensors[0].cameras[0].entry.settings));
  // One device beyond the budget by itself, in markup: refused naming it.
  try {
    io::loadScene(config("devices: {memory: 16}"), [&] { return laserRobot(kLaser); });
    SUCCEED();  // 360 rays: well within 16 MiB
    std::string big = kLaser;
    big.replace(big.find("<samples>180"), 12, "<samples>500000");
    io::loadScene(config("devices: {memory: 16}"), [&] { return laserRobot(big); });
    ADD_FAILURE() << "a lidar of 1e6 rays in 16 MiB";
  } catch (const io::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("<sensor name=\"front\">': the device would hold"), std::string::npos)
        << e.what();
  }
  // The key itself is checked.
  for (const char* bad :
       {"devices: {memory: 0}", "devices: {memory: 1e9}", "devices: {memory: 1.5}", "devices: {memroy: 10}"}) {
    EXPECT_THROW(config(bad), io::ConfigError) << bad;
  }
}

// TurtleBot3 waffle's depth camera (1920 x 1080 at 30 Hz) held the node at a
// third of real time without a word (bench/README.md, the robots people use).
TEST(DeviceMemory, ADeviceWhoseRaysWillNotKeepRealTimeIsSaidAtStart) {
  const auto said = [](const io::SceneSetup& s) {
    std::string all;
    for (const std::string& note : s.notes) all += note + "\n";
    return all;
  };
  // 320 x 240 at 30 Hz, 2.3 M rays a second, and the markup's 180-ray lidar: nothing said.
  const io::SceneSetup small =
      io::loadScene(config("depth_camera: {link: base_link}"), [&] { return laserRobot(kLaser); });
  EXPECT_EQ(said(small).find("rays a second"), std::string::npos) << said(small);
  const io::SceneSetup big = io::loadScene(config("depth_camera: {link: base_link, width: 1920, height: 1080}"),
                                           [&] { return laserRobot(""); });
  EXPECT_NE(said(big).find("depth camera 'depth_camera' casts 62.2 M rays a second of sim time"), std::string::npos)
      << said(big);
}

TEST(GazeboImus, AnImuSensorOrTheImuModelPluginIsAnImuWithItsMarkupsSettings) {
  const std::string sensor =
      "<gazebo reference='laser_link'><sensor type='imu' name='imu'><update_rate>50</update_rate>"
      "<pose>0 0 0 0 0 1.5707963267948966</pose><imu><angular_velocity><x><noise type='gaussian'>"
      "<stddev>0.003</stddev></noise></x></angular_velocity></imu>"
      "<plugin name='i' filename='libgazebo_ros_imu_sensor.so'><topicName>imu/data</topicName>"
      "<frameName>laser_link</frameName><updateRateHZ>100</updateRateHZ><gaussianNoise>0.004</gaussianNoise>"
      "</plugin></sensor></gazebo>";
  const std::string plugin =
      "<gazebo><plugin name='imu_plugin' filename='libgazebo_ros_imu.so'><bodyName>wheel</bodyName>"
      "<topicName>wheel_imu</topicName><gaussianNoise>0.01</gaussianNoise></plugin></gazebo>";
  const io::SceneSetup s = io::loadScene(config(""), [&] { return laserRobot(sensor + plugin); });
  ASSERT_EQ(s.sensors.size(), 1u);
  ASSERT_EQ(s.sensors[0].imus.size(), 2u);
  const io::RobotImu& imu = s.sensors[0].imus[0];  // in the markup's order
  EXPECT_EQ(imu.link, 0);                          // laser_link is lumped into base_link
  const core::ImuSettings& c = imu.entry.settings;
  EXPECT_LT((c.X_LS.translation - Vec3(0.1, 0.0, 0.2)).norm(), 1e-15);
  EXPECT_LT((c.X_LS.rotation * Vec3::UnitX() - Vec3::UnitY()).norm(), 1e-15);  // turned a quarter about z
  EXPECT_EQ(c.rate, 50.0);                                                     // the sensor's rate under the plugin's
  EXPECT_NEAR(c.gyro_noise, 0.005, 1e-15);                                     // the plugin's σ with the sensor's own
  EXPECT_NEAR(c.accel_noise, 0.005, 1e-15);
  EXPECT_EQ(c.orientation_noise, 0.004);
  EXPECT_EQ(imu.entry.topic, "imu/data");
  EXPECT_EQ(imu.entry.frame_id, "laser_link");
  const io::RobotImu& wheel = s.sensors[0].imus[1];
  EXPECT_EQ(wheel.link, 1);
  EXPECT_EQ(wheel.entry.settings.rate, 1.0 / s.scene.model().dt());  // no updateRate: every step
  EXPECT_EQ(wheel.entry.settings.gyro_noise, 0.01);
  EXPECT_EQ(wheel.entry.topic, "wheel_imu");
  EXPECT_EQ(wheel.entry.frame_id, "wheel");  // frameName's default: bodyName
}

TEST(GazeboImus, APluginGazeboWouldNotRunIsSaidAndNotRun) {
  // Gazebo logs the model plugin without its link and runs on without it: so does this.
  const io::SceneSetup s = io::loadScene(
      config(""), [&] { return laserRobot("<gazebo><plugin name='p' filename='libgazebo_ros_imu.so'/></gazebo>"); });
  EXPECT_TRUE(s.sensors.at(0).imus.empty());
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("libgazebo_ros_imu.so without <bodyName> (Gazebo does not run it)"), std::string::npos) << notes;
}

// Husky's and Jackal's IMU: hector_gazebo_ros_imu, as Husky's markup gives
// it (it was skipped: they had no IMU).
TEST(GazeboImus, HectorsImuPluginIsAnImuWithItsNoiseAndDrift) {
  const std::string husky =
      "<gazebo><plugin name='imu_controller' filename='libhector_gazebo_ros_imu.so'>"
      "<robotNamespace>/</robotNamespace><updateRate>50.0</updateRate><bodyName>base_link</bodyName>"
      "<topicName>imu/data</topicName><accelDrift>0.005 0.005 0.005</accelDrift>"
      "<accelGaussianNoise>0.005 0.005 0.005</accelGaussianNoise><rateDrift>0.005 0.005 0.005 </rateDrift>"
      "<rateGaussianNoise>0.005 0.005 0.005 </rateGaussianNoise><headingDrift>0.005</headingDrift>"
      "<headingGaussianNoise>0.005</headingGaussianNoise></plugin></gazebo>";
  const io::SceneSetup s = io::loadScene(config(""), [&] { return laserRobot(husky); });
  ASSERT_EQ(s.sensors.at(0).imus.size(), 1u);
  const io::RobotImu& imu = s.sensors[0].imus[0];
  EXPECT_EQ(imu.link, 0);
  const core::ImuSettings& c = imu.entry.settings;
  EXPECT_EQ(c.rate, 50.0);
  EXPECT_EQ(c.accel_noise, 0.005);
  EXPECT_EQ(c.gyro_noise, 0.005);
  // The Gauss-Markov drift of σ 0.005 and time constant 1 h as a random walk: 0.005 √(2/3600) per √s.
  EXPECT_NEAR(c.accel_bias_walk, 0.005 * std::sqrt(2.0 / 3600.0), 1e-18);
  EXPECT_NEAR(c.gyro_bias_walk, 0.005 * std::sqrt(2.0 / 3600.0), 1e-18);
  EXPECT_EQ(c.orientation_noise, 0.005);
  EXPECT_EQ(imu.entry.topic, "imu/data");
  EXPECT_EQ(imu.entry.frame_id, "base_link");  // frameId's default: bodyName
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("libhector_gazebo_ros_imu.so <headingDrift> (not run)"), std::string::npos) << notes;
  // hector's defaults: on the base without bodyName, topic imu, every step;
  // gaussianNoise for both; per-axis values differing: the largest, said.
  const io::SceneSetup bare = io::loadScene(config(""), [&] {
    return laserRobot(
        "<gazebo><plugin name='h' filename='libhector_gazebo_ros_imu.so'><gaussianNoise>0.02</gaussianNoise>"
        "<accelDrift>0.1 0.2 0.3</accelDrift><accelDriftFrequency>0.5</accelDriftFrequency>"
        "<randomEngineSeed>7</randomEngineSeed></plugin></gazebo>");
  });
  ASSERT_EQ(bare.sensors.at(0).imus.size(), 1u);
  const io::ImuEntry& b = bare.sensors[0].imus[0].entry;
  EXPECT_EQ(bare.sensors[0].imus[0].link, 0);
  EXPECT_EQ(b.topic, "imu");
  EXPECT_EQ(b.settings.rate, 1.0 / bare.scene.model().dt());
  EXPECT_EQ(b.settings.accel_noise, 0.02);
  EXPECT_EQ(b.settings.gyro_noise, 0.02);
  EXPECT_NEAR(b.settings.accel_bias_walk, 0.3 * std::sqrt(2.0 * 0.5), 1e-15);
  EXPECT_EQ(b.settings.seed, 7u);
  notes.clear();
  for (const std::string& n : bare.notes) notes += n;
  EXPECT_NE(notes.find("<accelDrift> per axis (the largest for all three)"), std::string::npos) << notes;
  // What no IMU can have is refused, naming the element.
  for (const auto& [element, why] :
       {std::pair{"<rateGaussianNoise>0.1 -0.1 0.1</rateGaussianNoise>", "<rateGaussianNoise> = '0.1 -0.1 0.1': each"},
        std::pair{"<accelDrift>0.1 0.1</accelDrift>", "<accelDrift> = '0.1 0.1': not the number(s)"},
        std::pair{"<updateRate>1e9</updateRate>", "<updateRate> = '1e9'"},
        std::pair{"<topicName>a b</topicName>", "<topicName> = 'a b': no ROS topic name"}}) {
    try {
      // A lambda captures no structured binding in C++17 (clang refuses it): a copy.
      const std::string markup = element;
      io::loadScene(config(""), [&] {
        return laserRobot("<gazebo><plugin name='h' filename='libhector_gazebo_ros_imu.so'>" + markup +
                          "</plugin></gazebo>");
      });
      ADD_FAILURE() << element << " was accepted";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("<plugin name=\"h\"> ") + why), std::string::npos) << e.what();
    }
  }
}

// Husky's and Jackal's GPS (hector_gazebo_ros_gps) and a magnetometer
// (hector_gazebo_ros_magnetic), as their markup gives them: both were
// skipped, so neither robot had a fix.
TEST(GazeboEarthSensors, HectorsGpsAndMagnetometerAreReadWithTheirReferencesAndErrors) {
  const std::string jackal =
      "<gazebo><plugin filename='libhector_gazebo_ros_gps.so' name='gps_controller'><updateRate>40</updateRate>"
      "<robotNamespace>/</robotNamespace><bodyName>laser_link</bodyName><frameId>base_link</frameId>"
      "<topicName>/navsat/fix</topicName><velocityTopicName>/navsat/vel</velocityTopicName>"
      "<referenceLatitude>49.9</referenceLatitude><referenceLongitude>8.9</referenceLongitude>"
      "<referenceHeading>90</referenceHeading><referenceAltitude>0</referenceAltitude>"
      "<drift>0.0001 0.0001 0.0001</drift><velocityGaussianNoise>0.05</velocityGaussianNoise>"
      "<offset>0 -1 0</offset></plugin></gazebo>"
      "<gazebo><plugin filename='libhector_gazebo_ros_magnetic.so' name='mag'><declination>2.5</declination>"
      "<magnitude>4.8e-5</magnitude><useMagneticFieldMsgs>true</useMagneticFieldMsgs>"
      "<gaussianNoise>1e-7</gaussianNoise></plugin></gazebo>";
  const io::SceneSetup s = io::loadScene(config(""), [&] { return laserRobot(jackal); });
  ASSERT_EQ(s.sensors.at(0).gnss.size(), 1u);
  const io::RobotGnss& g = s.sensors[0].gnss[0];
  EXPECT_EQ(g.link, 0);  // laser_link, lumped into base_link
  EXPECT_EQ(g.X_LS.translation, Vec3(0.1, 0.0, 0.2));
  EXPECT_EQ(g.entry.frame_id, "base_link");
  EXPECT_EQ(g.entry.topic, "/navsat/fix");
  EXPECT_EQ(g.entry.velocity_topic, "/navsat/vel");
  EXPECT_EQ(g.entry.rate, 40.0);
  EXPECT_EQ(g.entry.status, 0);
  EXPECT_EQ(g.entry.service, 1);
  const core::GnssSettings& c = g.entry.settings;
  EXPECT_EQ(c.reference.latitude, 49.9);
  EXPECT_EQ(c.reference.longitude, 8.9);
  EXPECT_EQ(c.reference.heading, 90.0);
  EXPECT_EQ(c.position.drift, Vec3::Constant(0.0001));
  EXPECT_EQ(c.position.offset, Vec3(0.0, -1.0, 0.0));  // an offset may be negative
  EXPECT_EQ(c.position.drift_frequency, Vec3::Constant(1.0 / 3600.0));
  EXPECT_EQ(c.velocity.gaussian_noise, Vec3::Constant(0.05));
  ASSERT_EQ(s.sensors[0].magnetometers.size(), 1u);
  const io::RobotMagnetometer& m = s.sensors[0].magnetometers[0];
  EXPECT_EQ(m.link, 0);  // no bodyName: the base
  EXPECT_EQ(m.entry.frame_id, "base_link");
  EXPECT_EQ(m.entry.topic, "magnetic");
  EXPECT_EQ(m.entry.rate, 0.0);  // every step
  EXPECT_TRUE(m.entry.field_message);
  EXPECT_EQ(m.entry.settings.heading, 90.0);  // hector's: x east
  EXPECT_EQ(m.entry.settings.inclination, 60.0);
  EXPECT_EQ(m.entry.settings.declination, 2.5);
  EXPECT_EQ(m.entry.settings.magnitude, 4.8e-5);
  EXPECT_EQ(m.entry.settings.error.gaussian_noise, Vec3::Constant(1e-7));
  // hector's defaults: fix and fix_velocity on the base at 4 Hz, heading 0.
  const io::SceneSetup bare = io::loadScene(config(""), [&] {
    return laserRobot(
        "<gazebo><plugin filename='libhector_gazebo_ros_gps.so' name='g'><dropoutSet>1</dropoutSet>"
        "</plugin></gazebo>");
  });
  const io::GnssEntry& b = bare.sensors.at(0).gnss.at(0).entry;
  EXPECT_EQ(b.topic, "fix");
  EXPECT_EQ(b.velocity_topic, "fix_velocity");
  EXPECT_EQ(b.rate, 4.0);
  EXPECT_EQ(b.frame_id, "base_link");
  EXPECT_EQ(b.settings.reference.heading, 0.0);
  std::string notes;
  for (const std::string& n : bare.notes) notes += n;
  EXPECT_NE(notes.find("libhector_gazebo_ros_gps.so <dropoutSet> (no dropouts or jumps here)"), std::string::npos)
      << notes;
  // What no receiver can have is refused, naming the element.
  for (const auto& [element, why] :
       {std::pair{"<referenceLatitude>95</referenceLatitude>", "<referenceLatitude> = '95'"},
        std::pair{"<drift>0.1 -0.1 0.1</drift>", "<drift> = '0.1 -0.1 0.1': each must be >= 0"},
        std::pair{"<velocityDriftFrequency>x</velocityDriftFrequency>", "<velocityDriftFrequency> = 'x'"},
        std::pair{"<status>7</status>", "<status> = '7'"},
        std::pair{"<bodyName>nowhere</bodyName>", "has no link 'nowhere'"}}) {
    try {
      // A lambda captures no structured binding in C++17 (clang refuses it): a copy.
      const std::string markup = element;
      io::loadScene(config(""), [&] {
        return laserRobot("<gazebo><plugin name='h' filename='libhector_gazebo_ros_gps.so'>" + markup +
                          "</plugin></gazebo>");
      });
      ADD_FAILURE() << element << " was accepted";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(io::loadScene(config(""),
                             [&] {
                               return laserRobot(
                                   "<gazebo><plugin name='h' filename='libhector_gazebo_ros_magnetic.so'>"
                                   "<inclination>100</inclination></plugin></gazebo>");
                             }),
               std::exception);
}

// gazebo_ros_bumper on a contact sensor (TurtleBot2's, many arms'
// grippers'): its link, topic, rate and frame; a frame not fixed to the
// link is refused, as the plugin could not express contacts in it either.
TEST(GazeboContactSensors, ABumperReadsItsLinkTopicRateAndFrame) {
  const auto bumper = [](const std::string& link, const std::string& plugin) {
    return "<gazebo reference='" + link +
           "'><sensor type='contact' name='bump'><update_rate>50</update_rate>"
           "<contact><collision>" +
           link +
           "_collision</collision></contact>"
           "<plugin name='b' filename='libgazebo_ros_bumper.so'>" +
           plugin + "</plugin></sensor></gazebo>";
  };
  const io::SceneSetup s = io::loadScene(config(""), [&] {
    return laserRobot(bumper("laser_link",
                             "<bumperTopicName>laser_bumper</bumperTopicName>"
                             "<frameName>laser_link</frameName>") +
                      bumper("wheel", ""));
  });
  ASSERT_EQ(s.sensors.at(0).contact_sensors.size(), 2u);
  const io::RobotContactSensor& a = s.sensors[0].contact_sensors[0];
  EXPECT_EQ(a.link, 0);  // laser_link is lumped into base_link: its contacts are the base's
  EXPECT_EQ(a.entry.topic, "laser_bumper");
  EXPECT_EQ(a.entry.rate, 50.0);
  EXPECT_EQ(a.entry.frame_id, "laser_link");
  EXPECT_EQ(a.X_LS.translation, Vec3(0.1, 0.0, 0.2));
  const io::RobotContactSensor& b = s.sensors[0].contact_sensors[1];
  EXPECT_EQ(b.link, 1);
  EXPECT_EQ(b.entry.topic, "bumper_states");  // the plugin's defaults: its topic, the world frame
  EXPECT_EQ(b.entry.frame_id, "");
  try {
    io::loadScene(config(""), [&] { return laserRobot(bumper("wheel", "<frameName>base_link</frameName>")); });
    ADD_FAILURE() << "a frame not fixed to the sensor's link was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("<frameName> 'base_link': not a frame of link 'wheel'"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(
      io::loadScene(config(""), [&] { return laserRobot(bumper("wheel", "<bumperTopicName>a b</bumperTopicName>")); }),
      std::exception);
}

TEST(GazeboOdometry, TheP3dPluginIsALinksOdometryWithItsNoise) {
  const std::string p3d =
      "<gazebo><plugin name='truth' filename='libgazebo_ros_p3d.so'><bodyName>base_link</bodyName>"
      "<topicName>ground_truth/state</topicName><frameName>world</frameName><updateRate>50</updateRate>"
      "<gaussianNoise>0.01</gaussianNoise></plugin></gazebo>"
      "<gazebo><plugin name='wheel' filename='libgazebo_ros_p3d.so'><bodyName>wheel</bodyName>"
      "<frameName>base_link</frameName><xyzOffsets>0 0 1</xyzOffsets></plugin></gazebo>"
      // On a link lumped into the base (as hyq's trunk and tiago's base_link
      // are): that frame's odometry. It refused the whole robot before.
      "<gazebo><plugin name='laser' filename='libgazebo_ros_p3d.so'><bodyName>laser_link</bodyName>"
      "<topicName>laser_truth</topicName></plugin></gazebo>";
  const io::SceneSetup s = io::loadScene(config(""), [&] { return laserRobot(p3d); });
  ASSERT_EQ(s.sensors.at(0).odometry.size(), 3u);
  const io::RobotOdometry& laser = s.sensors[0].odometry[2];
  EXPECT_EQ(laser.entry.link, "laser_link");
  EXPECT_EQ(laser.link, 0);
  EXPECT_EQ(laser.X_LS.translation, Vec3(0.1, 0.0, 0.2));
  EXPECT_EQ(s.sensors[0].odometry[0].X_LS.translation, Vec3::Zero());
  const io::RobotOdometry& base = s.sensors[0].odometry[0];
  EXPECT_EQ(base.link, 0);
  EXPECT_EQ(base.entry.topic, "ground_truth/state");
  EXPECT_EQ(base.entry.rate, 50.0);
  ASSERT_TRUE(base.entry.noise.has_value());
  EXPECT_EQ(base.entry.noise->position, 0.01);  // on the pose and the twist alike
  EXPECT_EQ(base.entry.noise->angular_velocity, 0.01);
  EXPECT_TRUE(base.entry.ground_truth.empty());
  const io::RobotOdometry& wheel = s.sensors[0].odometry[1];
  EXPECT_EQ(wheel.link, 1);
  EXPECT_EQ(wheel.entry.topic, "odom");
  EXPECT_EQ(wheel.entry.rate, 1.0 / s.scene.model().dt());  // no updateRate: every step
  EXPECT_FALSE(wheel.entry.noise.has_value());
  // What it does not run is said: a frame other than the world's, an offset.
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("libgazebo_ros_p3d.so <frameName> of a link (read as the world)"), std::string::npos) << notes;
  EXPECT_NE(notes.find("libgazebo_ros_p3d.so <xyzOffsets>"), std::string::npos) << notes;
}

// A drive on a joint the URDF fixes (MATLAB's and Adept's pioneer3dx): Gazebo
// lumps the joint away and the plugin fails to load; the robot runs without
// it, and that is said. It refused the whole robot before.
TEST(GazeboDrive, ADrivePluginOnAFixedJointIsSaidAndNotRun) {
  const std::string drive =
      "<gazebo><plugin name='wheels' filename='libgazebo_ros_diff_drive.so'><leftJoint>laser_mount</leftJoint>"
      "<rightJoint>axle</rightJoint></plugin></gazebo>";
  const io::SceneSetup s = io::loadScene(config(""), [&] { return laserRobot(drive); });
  EXPECT_TRUE(s.controls.empty() || s.controls[0].drives.empty());
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("gazebo_ros_skid_steer_drive) on a joint that is missing or does not move (Gazebo does not "
                       "run it) "
                       "('wheels')"),
            std::string::npos)
      << notes;
}

TEST(GazeboDrive, TheDiffDrivePluginIsADiffDriveControllerOnItsTopics) {
  // urdf/diff_drive.urdf's base with the plugin as a Gazebo user writes it.
  io::UrdfText text = io::readUrdfFile("diff_drive.urdf", kUrdf);
  const std::string plugin =
      "<gazebo><plugin name='wheels' filename='libgazebo_ros_diff_drive.so'><leftJoint>left_wheel_joint</leftJoint>"
      "<rightJoint>right_wheel_joint</rightJoint><wheelSeparation>0.4</wheelSeparation>"
      "<wheelDiameter>0.1</wheelDiameter><wheelTorque>3</wheelTorque><wheelAcceleration>2</wheelAcceleration>"
      "<commandTopic>base/cmd_vel</commandTopic><odometryTopic>/wheel_odom</odometryTopic>"
      "<robotBaseFrame>base_link</robotBaseFrame><publishOdomTF>false</publishOdomTF><updateRate>20</updateRate>"
      "</plugin></gazebo><gazebo><plugin name='gazebo_ros_control' filename='libgazebo_ros_control.so'>"
      "<robotNamespace>/scout</robotNamespace></plugin></gazebo>";
  text.xml.insert(text.xml.rfind("</robot>"), plugin);
  const io::SceneSetup s = io::loadScene(config(""), [&] { return text; });
  ASSERT_EQ(s.controls.at(0).drives.size(), 1u);
  const core::DiffDriveSpec& d = s.controls[0].drives[0].spec();
  EXPECT_EQ(d.name, "wheels");
  EXPECT_EQ(d.wheel_separation, 0.4);
  EXPECT_EQ(d.wheel_radius, 0.05);
  EXPECT_EQ(d.settings.max_wheel_torque, 3.0);
  EXPECT_EQ(d.settings.cmd_vel_timeout, std::numeric_limits<double>::infinity());  // the plugin holds it
  EXPECT_EQ(d.settings.linear.max_acceleration, 2.0);
  EXPECT_EQ(d.settings.angular.max_acceleration, 2.0 * 2.0 / 0.4);  // one wheel at +a, the other at -a
  const io::DriveTopics& t = s.controls[0].drive_topics.at(0);
  EXPECT_FALSE(t.under_controller);
  EXPECT_EQ(t.cmd_vel_topic, "base/cmd_vel");
  EXPECT_EQ(t.odom_topic, "/wheel_odom");
  EXPECT_EQ(t.odom_frame_id, "odom");
  EXPECT_EQ(t.base_frame_id, "base_link");
  EXPECT_FALSE(t.enable_odom_tf);
  EXPECT_EQ(t.publish_rate, 20.0);
  EXPECT_EQ(s.controls[0].robot_namespace, "/scout");  // gazebo_ros_control's
  // Its odometry is the wheels', not the truth the plugin's default reports: said.
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("<odometrySource> world (odometry from the wheels here)"), std::string::npos) << notes;
  // Without the sizes, the URDF's (as ros_controllers reads them), not the plugin's defaults.
  io::UrdfText bare = io::readUrdfFile("diff_drive.urdf", kUrdf);
  bare.xml.insert(bare.xml.rfind("</robot>"),
                  "<gazebo><plugin name='w' filename='libgazebo_ros_diff_drive.so'><leftJoint>left_wheel_joint"
                  "</leftJoint><rightJoint>right_wheel_joint</rightJoint></plugin></gazebo>");
  const io::SceneSetup b = io::loadScene(config(""), [&] { return bare; });
  EXPECT_NEAR(b.controls.at(0).drives.at(0).spec().wheel_separation, 0.36, 1e-12);
  EXPECT_NEAR(b.controls[0].drives[0].spec().wheel_radius, 0.06, 1e-12);
  EXPECT_EQ(b.controls[0].drives[0].spec().settings.max_wheel_torque, 5.0);  // the plugin's default
  EXPECT_EQ(b.controls[0].drive_topics.at(0).base_frame_id, "base_footprint");
  EXPECT_TRUE(b.controls[0].robot_namespace.empty());  // no gazebo_ros_control: none
  // A topic ROS cannot name is refused at load, naming the element (it once
  // reached the node's advertise, which throws).
  io::UrdfText bad = io::readUrdfFile("diff_drive.urdf", kUrdf);
  bad.xml.insert(bad.xml.rfind("</robot>"),
                 "<gazebo><plugin name='w' filename='libgazebo_ros_diff_drive.so'><leftJoint>left_wheel_joint"
                 "</leftJoint><rightJoint>right_wheel_joint</rightJoint><commandTopic>cmd vel</commandTopic>"
                 "</plugin></gazebo>");
  try {
    io::loadScene(config(""), [&] { return bad; });
    ADD_FAILURE() << "a command topic with a space was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("<plugin name=\"w\"> <commandTopic> = 'cmd vel': no ROS topic name"),
              std::string::npos)
        << e.what();
  }
}

// ROSbot's drive: gazebo_ros_skid_steer_drive, two wheels a side (ROSbot
// could not move: the plugin was skipped).
TEST(GazeboDrive, TheSkidSteerPluginIsADiffDriveControllerOfTwoWheelsASide) {
  const io::UrdfText text = io::readUrdfFile("skid_steer.urdf", std::string(RBS_SOURCE_DIR) + "/test/ros/");
  const io::SceneSetup s = io::loadScene(config(""), [&] { return text; });
  ASSERT_EQ(s.controls.at(0).drives.size(), 1u);
  const core::DiffDrive& drive = s.controls[0].drives[0];
  const core::DiffDriveSpec& d = drive.spec();
  EXPECT_EQ(d.name, "skid_steer_drive_controller");
  EXPECT_EQ(d.left.size(), 2u);
  EXPECT_EQ(d.right.size(), 2u);
  EXPECT_EQ(d.wheel_separation, 0.5);
  EXPECT_EQ(d.wheel_radius, 0.1);
  EXPECT_EQ(d.settings.max_wheel_torque, 4.0);
  EXPECT_EQ(d.settings.cmd_vel_timeout, std::numeric_limits<double>::infinity());  // the plugin holds it
  const io::DriveTopics& t = s.controls[0].drive_topics.at(0);
  EXPECT_FALSE(t.under_controller);
  EXPECT_EQ(t.cmd_vel_topic, "cmd_vel");
  EXPECT_EQ(t.base_frame_id, "chassis");
  EXPECT_TRUE(t.enable_odom_tf);  // broadcastTF
  EXPECT_EQ(t.publish_rate, 50.0);
  EXPECT_EQ(t.pose_covariance_diagonal, (std::array<double, 6>{2e-4, 3e-4, 1e12, 1e12, 1e12, 0.02}));
  EXPECT_EQ(t.twist_covariance_diagonal, t.pose_covariance_diagonal);
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("libgazebo_ros_skid_steer_drive.so odometry of the truth (odometry from the wheels here)"),
            std::string::npos)
      << notes;
  // Its defaults: broadcastTF false, torque 5 N*m; the plugin's joint
  // names, which this robot lacks: Gazebo does not load it, and that is said.
  io::UrdfText bare = text;
  bare.xml.erase(bare.xml.find("<broadcastTF>"), std::string("<broadcastTF>true</broadcastTF>").size());
  bare.xml.erase(bare.xml.find("<torque>"), std::string("<torque>4</torque>").size());
  const io::SceneSetup b = io::loadScene(config(""), [&] { return bare; });
  EXPECT_FALSE(b.controls.at(0).drive_topics.at(0).enable_odom_tf);
  EXPECT_EQ(b.controls[0].drives.at(0).spec().settings.max_wheel_torque, 5.0);
  const std::size_t from = bare.xml.find("<leftFrontJoint>"), to = bare.xml.find("<wheelSeparation>");
  bare.xml.erase(from, to - from);
  const io::SceneSetup none = io::loadScene(config(""), [&] { return bare; });
  EXPECT_TRUE(none.controls.at(0).drives.empty());
  notes.clear();
  for (const std::string& n : none.notes) notes += n;
  EXPECT_NE(notes.find("on a joint that is missing or does not move (Gazebo does not run it) "
                       "('skid_steer_drive_controller')"),
            std::string::npos)
      << notes;
  for (const auto& [element, why] : {std::pair{"<torque>-1</torque>", "<torque> = '-1': must be > 0 N*m"},
                                     std::pair{"<covariance_yaw>nan</covariance_yaw>", "<covariance_yaw> = 'nan'"}}) {
    io::UrdfText bad = text;
    const std::string plugin = "filename=\"libgazebo_ros_skid_steer_drive.so\">";
    bad.xml.insert(bad.xml.find(plugin) + plugin.size(), element);  // first: the one read
    try {
      io::loadScene(config(""), [&] { return bad; });
      ADD_FAILURE() << element << " was accepted";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
}

// ROSbot's sonars: a ray sensor with gazebo_ros_range is a range finder
// (sensor_msgs/Range of its nearest ray); it was skipped.
TEST(GazeboLidars, ARaySensorWithTheRangePluginIsARangeFinder) {
  const io::UrdfText text = io::readUrdfFile("skid_steer.urdf", std::string(RBS_SOURCE_DIR) + "/test/ros/");
  const io::SceneSetup s = io::loadScene(config(""), [&] { return text; });
  ASSERT_EQ(s.sensors.at(0).lidars.size(), 1u);
  const io::LidarEntry& l = s.sensors[0].lidars[0].entry;
  ASSERT_TRUE(l.range.has_value());
  EXPECT_EQ(l.range->field_of_view, 0.2);
  EXPECT_EQ(l.range->settings.noise, 0.005);
  EXPECT_FALSE(l.range->infrared);
  EXPECT_EQ(l.topic, "range/front");
  EXPECT_EQ(l.frame_id, "sonar_front");
  EXPECT_EQ(l.rate, 10.0);  // the plugin's updateRate under the sensor's 20 Hz
  EXPECT_EQ(l.settings.samples, 5);
  EXPECT_EQ(l.settings.max_range, 2.0);
  // The plugin's defaults: topic /range, fov 0.05; a radiation it has no type for is refused.
  io::UrdfText bare = text;
  for (const char* element : {"<topicName>range/front</topicName>", "<fov>0.2</fov>"}) {
    bare.xml.erase(bare.xml.find(element), std::string(element).size());
  }
  const io::SceneSetup b = io::loadScene(config(""), [&] { return bare; });
  EXPECT_EQ(b.sensors.at(0).lidars.at(0).entry.topic, "/range");
  EXPECT_EQ(b.sensors[0].lidars[0].entry.range->field_of_view, 0.05);
  io::UrdfText bad = text;
  bad.xml.replace(bad.xml.find("ultrasound"), 10, "ultrasonic");
  try {
    io::loadScene(config(""), [&] { return bad; });
    ADD_FAILURE() << "radiation 'ultrasonic' was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("<radiation> = 'ultrasonic': must be ultrasound or infrared"),
              std::string::npos)
        << e.what();
  }
}

// Values the plugin would take but that make no drive: refused at load,
// naming the element. wheelTorque -5 reached std::clamp(u, 5, -5) and drove
// the base at 1.8 m/s with no command; updateRate 1e-300 and 1e9 published
// odometry at every step; wheelAcceleration -1 was dropped without a word; a
// wheelSeparation of 0 was said to be "not given".
TEST(GazeboDrive, AValueNoDriveCanHaveIsRefusedNamingItsElement) {
  const auto refusal = [](const std::string& element) -> std::string {
    io::UrdfText text = io::readUrdfFile("diff_drive.urdf", kUrdf);
    text.xml.insert(text.xml.rfind("</robot>"),
                    "<gazebo><plugin name='w' filename='libgazebo_ros_diff_drive.so'><leftJoint>left_wheel_joint"
                    "</leftJoint><rightJoint>right_wheel_joint</rightJoint>" +
                        element + "</plugin></gazebo>");
    try {
      io::loadScene(config(""), [&] { return text; });
    } catch (const std::exception& e) {
      return e.what();
    }
    return "(accepted)";
  };
  const std::pair<const char*, const char*> cases[] = {
      {"<wheelTorque>-5</wheelTorque>", "<wheelTorque> = '-5': must be > 0 N*m"},
      {"<wheelTorque>0</wheelTorque>", "<wheelTorque> = '0': must be > 0 N*m"},
      {"<wheelAcceleration>-1</wheelAcceleration>", "<wheelAcceleration> = '-1': must be >= 0"},
      {"<updateRate>1e-300</updateRate>", "<updateRate> = '1e-300': must be 0 (as fast as it can) or within [0.01"},
      {"<updateRate>1e9</updateRate>", "<updateRate> = '1e9': must be 0"},
      {"<updateRate>-50</updateRate>", "<updateRate> = '-50': must be 0"},
      {"<wheelSeparation>0</wheelSeparation>", "<wheelSeparation> = '0': must be within (0, 1000] m"},
      {"<wheelSeparation>-0.3</wheelSeparation>", "<wheelSeparation> = '-0.3'"},
      {"<wheelDiameter>-0.1</wheelDiameter>", "<wheelDiameter> = '-0.1'"},
  };
  for (const auto& [element, why] : cases) {
    const std::string got = refusal(element);
    EXPECT_NE(got.find(std::string("<plugin name=\"w\"> ") + why), std::string::npos) << element << ": " << got;
  }
  EXPECT_EQ(refusal("<wheelTorque>20</wheelTorque><updateRate>0</updateRate>"), "(accepted)");
}

TEST(GazeboCameras, ADepthSensorWithTheKinectPluginIsADepthCameraWithItsMarkupsSettings) {
  const std::string kinect =
      "<gazebo reference='laser_link'><sensor type='depth' name='kinect'><update_rate>15</update_rate>"
      "<pose>0 0 0.05 0 0 0</pose><camera><horizontal_fov>1.047</horizontal_fov><image><width>160</width>"
      "<height>120</height><format>R8G8B8</format></image><clip><near>0.05</near><far>8</far></clip>"
      "<noise><type>gaussian</type><stddev>0.007</stddev></noise></camera>"
      "<plugin name='kinect' filename='libgazebo_ros_openni_kinect.so'><cameraName>kinect</cameraName>"
      "<depthImageTopicName>depth/image_raw</depthImageTopicName><pointCloudTopicName>depth/points"
      "</pointCloudTopicName><frameName>kinect_optical</frameName><pointCloudCutoff>0.3</pointCloudCutoff>"
      "</plugin></sensor></gazebo>";
  const io::SceneSetup s = io::loadScene(config(""), [&] { return laserRobot(kinect); });
  ASSERT_EQ(s.sensors.at(0).cameras.size(), 1u);
  const io::RobotCamera& c = s.sensors[0].cameras[0];
  EXPECT_EQ(c.link, 0);  // laser_link is lumped into base_link
  EXPECT_LT((c.X_LS.translation - Vec3(0.1, 0.0, 0.25)).norm(), 1e-15);
  const core::DepthCameraSettings& k = c.entry.settings;
  EXPECT_EQ(k.width, 160);
  EXPECT_EQ(k.height, 120);
  EXPECT_EQ(k.hfov, 1.047);
  EXPECT_EQ(k.min_depth, 0.3);  // the cut-off within the clip
  EXPECT_EQ(k.max_depth, 5.0);  // pointCloudCutoffMax's default within the clip
  EXPECT_EQ(k.noise, 0.007);
  EXPECT_EQ(c.entry.rate, 15.0);
  EXPECT_EQ(c.entry.topic, "kinect");
  EXPECT_EQ(c.entry.image_topic, "depth/image_raw");
  EXPECT_EQ(c.entry.info_topic, "depth/camera_info");
  EXPECT_EQ(c.entry.points_topic, "depth/points");
  EXPECT_EQ(c.entry.frame_id, "kinect_optical");
  std::string notes;
  for (const std::string& n : s.notes) notes += n;
  EXPECT_NE(notes.find("its colour or IR image (depth only here)"), std::string::npos) << notes;
  // Topics from the root, as Unitree's go1 names them, are kept there (the
  // plugin's node handle is in the camera's namespace; ROS resolves a name
  // from the root as it is). They were refused.
  std::string rooted = kinect;
  rooted.replace(rooted.find("depth/image_raw"), 15, "/camera_face/depth/image_raw");
  rooted.replace(rooted.find("depth/points"), 12, "/cam1/point_cloud_face");
  const io::SceneSetup r = io::loadScene(config(""), [&] { return laserRobot(rooted); });
  EXPECT_EQ(r.sensors.at(0).cameras.at(0).entry.image_topic, "/camera_face/depth/image_raw");
  EXPECT_EQ(r.sensors[0].cameras[0].entry.points_topic, "/cam1/point_cloud_face");
  // A size no camera can have is refused, naming the markup (as the markup's
  // reader reads the count, before any camera is mounted).
  std::string bad = kinect;
  bad.replace(bad.find("<width>160"), 10, "<width>0");
  try {
    io::loadScene(config(""), [&] { return laserRobot(bad); });
    ADD_FAILURE() << "a camera 0 pixels wide was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("<sensor name=\"kinect\"> <image/width> = '0': must be within [1, 4e+06]"),
              std::string::npos)
        << e.what();
  }
}

TEST(Transmissions, AControllerOnAJointNoTransmissionServesAsItsTypeNeedsIsSaid) {
  io::UrdfText text = io::readUrdfFile("diff_drive.urdf", kUrdf);
  const auto transmission = [](const std::string& joint, const std::string& interface) {
    return "<transmission name='" + joint + "_tr'><type>transmission_interface/SimpleTransmission</type><joint name='" +
           joint + "'><hardwareInterface>hardware_interface/" + interface +
           "</hardwareInterface></joint><actuator name='m'><mechanicalReduction>1</mechanicalReduction></actuator>"
           "</transmission>";
  };
  text.xml.insert(text.xml.rfind("</robot>"), transmission("left_wheel_joint", "VelocityJointInterface") +
                                                  transmission("right_wheel_joint", "EffortJointInterface") +
                                                  transmission("ghost_joint", "EffortJointInterface"));
  const io::SimConfig c = config(
      "controllers: {base: {type: diff_drive_controller/DiffDriveController, left_wheel: left_wheel_joint,"
      " right_wheel: right_wheel_joint}}");
  const io::SceneSetup s = io::loadScene(c, [&] { return text; });
  ASSERT_EQ(s.controls.at(0).drives.size(), 1u);  // it runs all the same
  std::string notes;
  for (const std::string& n : s.notes) notes += n + "\n";
  EXPECT_EQ(notes.find("left_wheel_joint"), std::string::npos) << notes;  // declared with the velocity interface
  EXPECT_NE(notes.find("config key 'controllers.base' (diff_drive_controller/DiffDriveController): joint "
                       "'right_wheel_joint''s <transmission name=\"right_wheel_joint_tr\"> declares no "
                       "VelocityJointInterface"),
            std::string::npos)
      << notes;
  EXPECT_NE(notes.find("<transmission name=\"ghost_joint_tr\"> drives joint 'ghost_joint', which it does not have"),
            std::string::npos)
      << notes;
  EXPECT_EQ(notes.find("<transmission>"), std::string::npos) << notes;  // read: not named as unread
  // A URDF without transmissions is not written for gazebo_ros_control: nothing to say.
  const io::SceneSetup bare = io::loadScene(c, [&] { return io::readUrdfFile("diff_drive.urdf", kUrdf); });
  for (const std::string& n : bare.notes) EXPECT_EQ(n.find("transmission"), std::string::npos) << n;
}

TEST(Transmissions, EachControllerTypeCommandsItsInterface) {
  EXPECT_EQ(io::commandedInterface("effort_controllers/JointPositionController"), "EffortJointInterface");
  EXPECT_EQ(io::commandedInterface("velocity_controllers/JointVelocityController"), "VelocityJointInterface");
  EXPECT_EQ(io::commandedInterface("position_controllers/JointTrajectoryController"), "PositionJointInterface");
  EXPECT_EQ(io::commandedInterface("diff_drive_controller/DiffDriveController"), "VelocityJointInterface");
  EXPECT_EQ(io::commandedInterface("joint_state_controller/JointStateController"), "");
}

}  // namespace
}  // namespace rigid_body_sim::test
