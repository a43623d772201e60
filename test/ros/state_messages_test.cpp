// The node's state messages (no master): ~body_states gives each twist in
// the body's own frame or the world's axes, odometry carries the report's
// covariances or the exact state's, /tf_static gets each fixed link and
// IMU frame under the body's prefix, and ~contacts names both sides of a
// pair while ~contact_markers draws its forces to scale.
#include <gtest/gtest.h>

#include <cmath>

#include "../test_util.h"
#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/ros/drive_ports.h"
#include "rigid_body_sim/ros/robot_ports.h"
#include "rigid_body_sim/ros/state_publisher.h"

namespace rigid_body_sim::node {
namespace {

using test::Quat;
using test::Vec3;

constexpr double kPi = 3.14159265358979323846;

core::Model oneBox(bool with_fixed_link) {
  core::BodySpec b = test::boxBody(Vec3(0.1, 0.1, 0.1));
  b.name = "a";
  b.link = "base_link";
  if (with_fixed_link) b.fixed_links = {{"lidar", "base_link", core::Pose{Quat::Identity(), Vec3(0, 0, 0.3)}}};
  return core::Model(test::spec(b, 1e-3, Vec3(0, 0, -9.81)));
}

std_msgs::Header header(const std::string& frame) {
  std_msgs::Header h;
  h.frame_id = frame;
  h.stamp.fromSec(2.5);
  return h;
}

void expectVector(const geometry_msgs::Vector3& v, const Vec3& expected) {
  EXPECT_NEAR(v.x, expected.x(), 1e-12);
  EXPECT_NEAR(v.y, expected.y(), 1e-12);
  EXPECT_NEAR(v.z, expected.z(), 1e-12);
}

TEST(StateMessages, BodyStatesGiveTwistsInTheBodysFrameOrTheWorldsAxes) {
  // Turned a quarter about z, moving along world x and spinning about z:
  // in its own axes world x is −y.
  const core::Model model = oneBox(false);
  core::LinkState link;
  link.p_WL = Vec3(1, 2, 3);
  link.q_WL = Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitZ()));
  link.v_WL = Vec3(1, 0, 0);
  link.w_W = Vec3(0, 0, 2);
  core::State s;
  s.bodies = {core::bodyStateFromLink(model.body(0), link)};
  s.bodies[0].asleep = true;
  ros::CallbackQueue closer;
  PortRegistry ports(closer);
  BodyPorts p;
  p.frame = "base_link";
  ports.add(std::move(p), model.body(0), s.bodies[0], 0.0);

  const BodyStates own = bodyStatesMessage(model, s, ports, header("map"), false);
  ASSERT_EQ(own.names.size(), 1u);
  EXPECT_EQ(own.names[0], "a");
  EXPECT_EQ(own.header.frame_id, "map");
  EXPECT_EQ(own.twist_frames[0], "base_link");
  expectVector(own.twists[0].linear, Vec3(0, -1, 0));
  expectVector(own.twists[0].angular, Vec3(0, 0, 2));
  EXPECT_NEAR(own.poses[0].position.y, 2.0, 1e-12);
  EXPECT_NEAR(own.poses[0].orientation.z, std::sqrt(0.5), 1e-12);
  EXPECT_TRUE(own.asleep[0]);

  const BodyStates world = bodyStatesMessage(model, s, ports, header("map"), true);
  EXPECT_EQ(world.twist_frames[0], "map");
  expectVector(world.twists[0].linear, Vec3(1, 0, 0));
}

// Each robot follows the bodies by its name: a floating base's pose and
// twist in its base link's axes (or the world's), a world-fixed one where it
// is fixed, at rest, its twist in the world's axes.
TEST(StateMessages, BodyStatesCarryEachRobotsBase) {
  const std::string urdf = std::string(RBS_SOURCE_DIR) + "/urdf/";
  core::ModelSpec spec;
  spec.dt = 1e-3;
  core::Scene scene(spec, {{"rod", io::loadArticulationFile(urdf + "pendulum.urdf")},
                           {"rover", io::loadArticulationFile(urdf + "diff_drive.urdf")}});
  std::vector<core::ArticulationState> robots;
  for (const core::SceneRobot& r : scene.robots()) robots.push_back(core::restState(r.model));
  robots[1].X_WB = core::Pose{Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())), Vec3(1.0, 2.0, 0.1)};
  robots[1].V_B.head<3>() = Vec3(0.0, 0.0, 0.5);  // ω, in the base's axes
  robots[1].V_B.tail<3>() = Vec3(0.3, 0.0, 0.0);  // v, in the base's axes: forward
  const core::Simulation sim(scene, core::sceneState(scene, core::State{}, robots));
  for (const bool in_world : {false, true}) {
    BodyStates msg;
    msg.header = header("map");
    appendRobotBases(sim, in_world, msg);
    ASSERT_EQ(msg.names, (std::vector<std::string>{"rod", "rover"}));
    EXPECT_EQ(msg.twist_frames[0], "map");  // fixed to the world
    expectVector(msg.twists[0].linear, Vec3::Zero());
    EXPECT_EQ(msg.twist_frames[1], in_world ? "map" : "base_link");
    EXPECT_NEAR(msg.poses[1].position.y, 2.0, 1e-12);
    EXPECT_NEAR(msg.poses[1].orientation.z, std::sqrt(0.5), 1e-12);
    expectVector(msg.twists[1].linear, in_world ? Vec3(0.0, 0.3, 0.0) : Vec3(0.3, 0.0, 0.0));
    expectVector(msg.twists[1].angular, Vec3(0.0, 0.0, 0.5));
    EXPECT_FALSE(msg.asleep[1]);
  }
}

TEST(StateMessages, JointStatesCarryAHeldJointAtItsPosition) {
  // A pendulum with a camera on a pan joint of its own and no <inertial>:
  // the pan joint is held (physics §2.1), and robot_state_publisher still
  // needs it to place the camera's frame.
  const core::ArticulationModel model = io::loadArticulationString(
      "<robot name='r'><link name='world'/><link name='rod'><inertial><origin xyz='0 0 -0.5'/><mass value='1'/>"
      "<inertia ixx='0.1' iyy='0.1' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial></link><link name='camera'/>"
      "<joint name='pivot' type='continuous'><parent link='world'/><child link='rod'/><axis xyz='0 1 0'/></joint>"
      "<joint name='pan' type='revolute'><parent link='rod'/><child link='camera'/><axis xyz='0 0 1'/>"
      "<limit lower='0.2' upper='1' effort='1' velocity='1'/></joint></robot>",
      "test.urdf");
  core::ArticulationState state = core::restState(model);
  state.q(0) = 0.4;
  state.v(0) = -1.5;
  Eigen::VectorXd effort(1);
  effort << 0.7;
  const sensor_msgs::JointState msg = jointStateMessage(model, state, effort, ros::Time(3.0));
  EXPECT_EQ(msg.name, (std::vector<std::string>{"pivot", "pan"}));
  EXPECT_EQ(msg.position, (std::vector<double>{0.4, 0.2}));
  EXPECT_EQ(msg.velocity, (std::vector<double>{-1.5, 0.0}));
  EXPECT_EQ(msg.effort, (std::vector<double>{0.7, 0.0}));
  EXPECT_EQ(msg.header.stamp, ros::Time(3.0));
}

TEST(StateMessages, EveryBaseButTheWorldIsPlacedOnTf) {
  // A floating base, a root named `world`, and a base fixed because it has
  // no mass (pybullet_data's arms): the last is placed by the node too, or
  // no one would put it on tf.
  const std::string urdf = std::string(RBS_SOURCE_DIR) + "/urdf/";
  EXPECT_EQ(placedBase(io::loadArticulationFile(urdf + "diff_drive.urdf")), "base_link");
  EXPECT_EQ(placedBase(io::loadArticulationFile(urdf + "pendulum.urdf")), "");
  const core::ArticulationModel fixed = io::loadArticulationString(
      "<robot name='iiwa'><link name='link_0'><inertial><mass value='0'/><inertia ixx='0.05' iyy='0.06' izz='0.03' "
      "ixy='0' ixz='0' iyz='0'/></inertial></link><joint name='joint_1' type='continuous'><parent link='link_0'/>"
      "<child link='link_1'/><axis xyz='0 0 1'/></joint><link name='link_1'><inertial><origin xyz='0 -0.03 0.12'/>"
      "<mass value='4'/><inertia ixx='0.1' iyy='0.09' izz='0.02' ixy='0' ixz='0' iyz='0'/></inertial></link></robot>",
      "iiwa.urdf");
  ASSERT_TRUE(fixed.fixed_base);
  EXPECT_EQ(placedBase(fixed), "link_0");
}

// A robot's controllers and joint_states: under its gazebo_ros_control
// robotNamespace when it has one, else as its other topics.
TEST(StateMessages, ARobotsControlTopicsAreUnderItsRobotNamespace) {
  EXPECT_EQ(robotTopicPrefix("/rrbot", "arm/"), "/rrbot/");
  EXPECT_EQ(robotTopicPrefix("/rrbot/", ""), "/rrbot/");
  EXPECT_EQ(robotTopicPrefix("rrbot", ""), "rrbot/");
  EXPECT_EQ(robotTopicPrefix("/", "arm/"), "/");
  EXPECT_EQ(robotTopicPrefix("", "arm/"), "arm/");
}

TEST(StateMessages, OdometryCarriesTheReportsCovariancesOrTheExactOnes) {
  core::OdomReport r;
  r.v_L = Vec3(0.5, 0, 0);
  for (int k = 0; k < 6; ++k) {
    r.pose_variance[k] = 0.1 * (k + 1);
    r.twist_variance[k] = 0.01 * (k + 1);
  }
  const nav_msgs::Odometry noisy = odometryMessage(r, "a/base_link", header("odom"), std::nullopt);
  EXPECT_EQ(noisy.child_frame_id, "a/base_link");
  EXPECT_EQ(noisy.header.frame_id, "odom");
  EXPECT_EQ(noisy.header.stamp.toSec(), 2.5);
  EXPECT_EQ(noisy.pose.covariance[0], r.pose_variance[0]);
  EXPECT_EQ(noisy.pose.covariance[35], r.pose_variance[5]);
  EXPECT_EQ(noisy.twist.covariance[14], r.twist_variance[2]);
  EXPECT_EQ(noisy.pose.covariance[1], 0.0);  // off the diagonal: none
  EXPECT_EQ(noisy.twist.twist.linear.x, 0.5);
  const nav_msgs::Odometry exact = odometryMessage(r, "a/base_link", header("odom"), 1e-9);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(exact.pose.covariance[k * 7], 1e-9);
    EXPECT_EQ(exact.twist.covariance[k * 7], 1e-9);
  }
}

TEST(StateMessages, FixedFramesHangUnderTheBodysPrefix) {
  const core::Model model = oneBox(true);
  BodyPorts p;
  p.prefix = "a/";
  p.frame = "a/" + model.body(0).link;
  core::ImuSettings imu;
  imu.X_LS = core::Pose{Quat::Identity(), Vec3(0.05, 0, 0)};
  p.sensors = std::make_unique<core::BodySensors>(model.dt());
  p.sensors->addImu(imu);
  p.imu_frame = "a/imu_link";
  std::vector<geometry_msgs::TransformStamped> frames;
  appendFixedFrames(model.body(0), p, ros::Time(4.0), frames);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].header.frame_id, p.frame);
  EXPECT_EQ(frames[0].child_frame_id, "a/lidar");
  EXPECT_EQ(frames[0].transform.translation.z, 0.3);
  EXPECT_EQ(frames[0].header.stamp.toSec(), 4.0);
  EXPECT_EQ(frames[1].header.frame_id, p.frame);
  EXPECT_EQ(frames[1].child_frame_id, "a/imu_link");
  EXPECT_EQ(frames[1].transform.translation.x, 0.05);
}

TEST(StateMessages, ContactsNameBothSidesAndDrawEachForce) {
  // Body a on the scene's item 0 (the ground) with 9.81 N up and 2 N of
  // friction along x, touching at two points.
  const core::Model model = oneBox(false);
  core::ContactPairReport p;
  p.body = 0;
  p.item = 0;
  p.points_W = {Vec3(-0.1, 0, 0), Vec3(0.1, 0, 0)};
  p.depth = 1e-4;
  p.normal_force_W = Vec3(0, 0, 9.81);
  p.friction_force_W = Vec3(2, 0, 0);
  const Contacts msg = contactsMessage(model, {p}, header("map"));
  ASSERT_EQ(msg.pairs.size(), 1u);
  EXPECT_EQ(msg.pairs[0].body, "a");
  EXPECT_EQ(msg.pairs[0].other, "scene[0]");
  EXPECT_EQ(msg.pairs[0].points.size(), 2u);
  EXPECT_EQ(msg.pairs[0].normal_force.z, 9.81);
  EXPECT_EQ(msg.pairs[0].depth, 1e-4);

  const visualization_msgs::MarkerArray drawn = contactMarkers(msg);
  ASSERT_EQ(drawn.markers.size(), 4u);  // clear, two arrows, the points
  EXPECT_EQ(drawn.markers[0].action, visualization_msgs::Marker::DELETEALL);
  const visualization_msgs::Marker& normal = drawn.markers[1];
  EXPECT_EQ(normal.ns, "a scene[0]");
  EXPECT_EQ(normal.points[0].x, 0.0);  // from the pair's centre
  EXPECT_NEAR(normal.points[1].z, kContactForceScale * 9.81, 1e-15);
  EXPECT_NEAR(drawn.markers[2].points[1].x, kContactForceScale * 2.0, 1e-15);
  EXPECT_EQ(drawn.markers[3].points.size(), 2u);
  EXPECT_EQ(drawn.markers[3].header.frame_id, "map");
}

// A DiffDriveController's odometry as nav_msgs/Odometry and on tf: the pose
// in the odom frame turned by its heading, the twist in the base's axes, the
// covariance diagonals at 0, 7, ..., 35.
TEST(DriveMessages, CarryTheOdometryInItsFrames) {
  const core::ArticulationModel model = io::loadArticulationFile(std::string(RBS_SOURCE_DIR) + "/urdf/diff_drive.urdf");
  core::DiffDriveSpec spec;
  spec.name = "base_controller";
  spec.left = {1};
  spec.right = {2};
  spec.wheel_separation = 0.36;
  spec.wheel_radius = 0.06;
  core::DiffDrive drive(model, spec);
  core::ArticulationState state = core::restState(model);
  drive.restart(state, true);
  // The right wheel alone turns 0.36 / 0.06 / 2 rad: the base turns about the left wheel by 0.5 rad.
  state.q(1) = 3.0;
  drive.observe(state, 0.5);
  io::DriveTopics topics;
  topics.pose_covariance_diagonal = {1, 2, 3, 4, 5, 6};
  topics.twist_covariance_diagonal = {7, 8, 9, 10, 11, 12};
  const DriveFrames frames{"rover/odom", "rover/base_link"};
  const nav_msgs::Odometry m = odometryMessage(drive, topics, frames, ros::Time(12, 5));
  EXPECT_EQ(m.header.stamp, ros::Time(12, 5));
  EXPECT_EQ(m.header.frame_id, "rover/odom");
  EXPECT_EQ(m.child_frame_id, "rover/base_link");
  // An arc of radius 0.18 m about the left wheel: x = 0.18 sin 0.5, y = 0.18 (1 - cos 0.5).
  EXPECT_NEAR(m.pose.pose.position.x, 0.18 * std::sin(0.5), 1e-15);
  EXPECT_NEAR(m.pose.pose.position.y, 0.18 * (1.0 - std::cos(0.5)), 1e-15);
  EXPECT_NEAR(m.pose.pose.orientation.z, std::sin(0.25), 1e-15);
  EXPECT_NEAR(m.pose.pose.orientation.w, std::cos(0.25), 1e-15);
  EXPECT_NEAR(m.twist.twist.linear.x, 0.09 / 0.5, 1e-15);
  EXPECT_NEAR(m.twist.twist.angular.z, 1.0, 1e-15);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(m.pose.covariance[7 * k], k + 1.0);
    EXPECT_EQ(m.twist.covariance[7 * k], k + 7.0);
  }
  EXPECT_EQ(m.pose.covariance[1], 0.0);
  const geometry_msgs::TransformStamped t = odometryTransform(drive, frames, ros::Time(12, 5));
  EXPECT_EQ(t.header.frame_id, "rover/odom");
  EXPECT_EQ(t.child_frame_id, "rover/base_link");
  EXPECT_EQ(t.transform.translation.x, m.pose.pose.position.x);
  EXPECT_EQ(t.transform.rotation.z, m.pose.pose.orientation.z);
}

}  // namespace
}  // namespace rigid_body_sim::node
