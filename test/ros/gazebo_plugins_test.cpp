// A wheeled base described for Gazebo, run unchanged (gazebo_plugins.test):
// what a subscriber receives while geometry_msgs/Twist commands arrive on
// /gp/cmd_vel (gazebo_ros_control's robotNamespace), as gazebo_ros_diff_drive
// reads them: the base turning at the
// commanded twist on the p3d plugin's /ground_truth/state, the drive's
// odometry on /odom, and the IMU plugin's /imu reading the turn's
// centripetal acceleration and gravity as REP 145 says. And a four-wheeled
// base under gazebo_ros_skid_steer_drive (skid_steer.test): still at no
// command (its hector IMU reading +g), forward and backward at the
// commanded speed, its sonar (gazebo_ros_range) reading a crate ahead,
// its GPS (hector_gazebo_ros_gps) where the truth is, its magnetometer
// (hector_gazebo_ros_magnetic) pointing north, its wheels' contact sensors
// (gazebo_ros_bumper) bearing its weight.
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/NavSatFix.h>
#include <sensor_msgs/Range.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/Contacts.h"
#include "rigid_body_sim/SpawnBody.h"

namespace {

using namespace rbs_test;

TEST(GazeboPlugins, TheBaseDrivesByCmdVelAndItsOdometryP3dAndImuSayHow) {
  ros::NodeHandle nh;
  std::vector<nav_msgs::Odometry> odom, truth;
  std::vector<sensor_msgs::Imu> imu;
  ros::Subscriber odom_sub = nh.subscribe<nav_msgs::Odometry>(
      "/gp/odom", 1000, [&](const nav_msgs::Odometry::ConstPtr& m) { odom.push_back(*m); });
  ros::Subscriber truth_sub = nh.subscribe<nav_msgs::Odometry>(
      "/ground_truth/state", 1000, [&](const nav_msgs::Odometry::ConstPtr& m) { truth.push_back(*m); });
  ros::Subscriber imu_sub =
      nh.subscribe<sensor_msgs::Imu>("/imu", 1000, [&](const sensor_msgs::Imu::ConstPtr& m) { imu.push_back(*m); });
  sensor_msgs::JointState joints;
  ros::Subscriber joints_sub = nh.subscribe<sensor_msgs::JointState>(
      "/gp/joint_states", 10, [&](const sensor_msgs::JointState::ConstPtr& m) { joints = *m; });
  ros::Publisher cmd_vel = nh.advertise<geometry_msgs::Twist>("/gp/cmd_vel", 10);
  ASSERT_TRUE(spinUntil([&] { return cmd_vel.getNumSubscribers() > 0; }, 30.0));  // the drive listens
  ASSERT_TRUE(spinUntil([&] { return !odom.empty() && !truth.empty() && !imu.empty(); }, 30.0));
  // gazebo_ros_control's robotNamespace: the joint_states and the drive's topics under /gp.
  ASSERT_TRUE(spinUntil([&] { return !joints.name.empty(); }, 10.0));
  EXPECT_EQ(joints.name.size(), 2u);
  // 0.4 m/s and 0.5 rad/s, sent every 20 ms of wall time, for 3 s of sim time.
  geometry_msgs::Twist twist;
  twist.linear.x = 0.4;
  twist.angular.z = 0.5;
  const double until = simNow(truth.back().header.stamp.toSec()) + 3.0;
  while (ros::ok() && truth.back().header.stamp.toSec() < until) {
    cmd_vel.publish(twist);
    spinUntil([] { return false; }, 0.02);
  }
  // p3d: the truth of base_link, its twist in its own axes (nav_msgs/Odometry).
  const nav_msgs::Odometry& t = truth.back();
  EXPECT_EQ(t.child_frame_id, "base_link");
  EXPECT_NEAR(t.twist.twist.linear.x, 0.4, 0.03 * 0.4);
  EXPECT_NEAR(t.twist.twist.angular.z, 0.5, 0.03 * 0.5);
  // The drive's odometry, from the wheels, in odometryFrame and robotBaseFrame.
  const nav_msgs::Odometry& o = odom.back();
  EXPECT_EQ(o.header.frame_id, "odom");
  EXPECT_EQ(o.child_frame_id, "base_link");
  EXPECT_NEAR(o.twist.twist.linear.x, 0.4, 0.03 * 0.4);
  EXPECT_NEAR(o.twist.twist.angular.z, 0.5, 0.03 * 0.5);
  EXPECT_EQ(o.pose.covariance[0], 1e-5);  // the plugin's
  // The IMU on base_link over the last 0.5 s (its 100 Hz): the yaw rate,
  // the turn's centripetal v ω = 0.2 m/s² to the left (+y), and +g up.
  ASSERT_GE(imu.size(), 50u);
  double wz = 0.0, ay = 0.0, az = 0.0;
  for (std::size_t k = imu.size() - 50; k < imu.size(); ++k) {
    wz += imu[k].angular_velocity.z / 50.0;
    ay += imu[k].linear_acceleration.y / 50.0;
    az += imu[k].linear_acceleration.z / 50.0;
  }
  EXPECT_EQ(imu.back().header.frame_id, "base_link");  // frameName's default: bodyName
  EXPECT_NEAR(wz, 0.5, 0.03 * 0.5);
  EXPECT_NEAR(ay, 0.4 * 0.5, 0.03);
  EXPECT_NEAR(az, 9.81, 0.05);
  EXPECT_NEAR((imu.back().header.stamp - imu[imu.size() - 2].header.stamp).toSec(), 0.01, 1e-6);
  std::printf("gazebo_plugins: p3d v %.4f w %.4f; odom v %.4f w %.4f; imu w %.4f a_y %.4f a_z %.4f\n",
              t.twist.twist.linear.x, t.twist.twist.angular.z, o.twist.twist.linear.x, o.twist.twist.angular.z, wz, ay,
              az);
}

// skid_steer.test: test/ros/skid_steer.urdf, its plugin's topics at the root
// (robotNamespace '/'). It holds still with no command, then runs at +0.3
// and -0.3 m/s on /cmd_vel: its truth (p3d) within 5 % of each, its
// wheels' odometry too, and no yaw.
TEST(GazeboSkidSteer, AFourWheeledBaseHoldsStillThenDrivesForwardAndBackAtTheCommandedSpeed) {
  ros::NodeHandle nh;
  std::vector<nav_msgs::Odometry> odom, truth;
  ros::Subscriber odom_sub = nh.subscribe<nav_msgs::Odometry>(
      "/odom", 1000, [&](const nav_msgs::Odometry::ConstPtr& m) { odom.push_back(*m); });
  ros::Subscriber truth_sub = nh.subscribe<nav_msgs::Odometry>(
      "/ground_truth/state", 1000, [&](const nav_msgs::Odometry::ConstPtr& m) { truth.push_back(*m); });
  std::vector<sensor_msgs::Imu> imu;
  ros::Subscriber imu_sub = nh.subscribe<sensor_msgs::Imu>(
      "/imu/data", 1000, [&](const sensor_msgs::Imu::ConstPtr& m) { imu.push_back(*m); });
  std::vector<sensor_msgs::Range> sonar;
  ros::Subscriber sonar_sub = nh.subscribe<sensor_msgs::Range>(
      "/range/front", 1000, [&](const sensor_msgs::Range::ConstPtr& m) { sonar.push_back(*m); });
  std::vector<sensor_msgs::NavSatFix> fixes;
  ros::Subscriber fix_sub = nh.subscribe<sensor_msgs::NavSatFix>(
      "/navsat/fix", 1000, [&](const sensor_msgs::NavSatFix::ConstPtr& m) { fixes.push_back(*m); });
  std::vector<geometry_msgs::Vector3Stamped> fix_velocity, field;
  ros::Subscriber fix_velocity_sub = nh.subscribe<geometry_msgs::Vector3Stamped>(
      "/navsat/vel", 1000, [&](const geometry_msgs::Vector3Stamped::ConstPtr& m) { fix_velocity.push_back(*m); });
  ros::Subscriber field_sub = nh.subscribe<geometry_msgs::Vector3Stamped>(
      "/magnetic", 1000, [&](const geometry_msgs::Vector3Stamped::ConstPtr& m) { field.push_back(*m); });
  const char* wheels[] = {"front_left_wheel", "front_right_wheel", "rear_left_wheel", "rear_right_wheel"};
  std::vector<std::vector<rigid_body_sim::Contacts>> bumpers(4);
  std::vector<ros::Subscriber> bumper_subs;
  for (std::size_t w = 0; w < 4; ++w) {
    bumper_subs.push_back(nh.subscribe<rigid_body_sim::Contacts>(
        "/" + std::string(wheels[w]) + "/contacts", 1000,
        [&bumpers, w](const rigid_body_sim::Contacts::ConstPtr& m) { bumpers[w].push_back(*m); }));
  }
  const std::vector<rigid_body_sim::Contacts>& bumper = bumpers[0];
  std::vector<rigid_body_sim::Contacts> chassis;
  ros::Subscriber chassis_sub = nh.subscribe<rigid_body_sim::Contacts>(
      "/chassis/contacts", 1000, [&](const rigid_body_sim::Contacts::ConstPtr& m) { chassis.push_back(*m); });
  ros::Publisher cmd_vel = nh.advertise<geometry_msgs::Twist>("/cmd_vel", 10);
  ASSERT_TRUE(spinUntil([&] { return cmd_vel.getNumSubscribers() > 0; }, 30.0));  // the drive listens
  ASSERT_TRUE(spinUntil(
      [&] {
        return !odom.empty() && !truth.empty() && !sonar.empty() && !fixes.empty() && !fix_velocity.empty() &&
               !field.empty() && std::all_of(bumpers.begin(), bumpers.end(), [](const auto& b) { return !b.empty(); });
      },
      30.0));
  EXPECT_EQ(odom.back().pose.covariance[7], 3e-4);  // covariance_y
  // The sonar sees nothing yet: REP 117's +inf, with the plugin's fields.
  EXPECT_TRUE(std::isinf(sonar.back().range) && sonar.back().range > 0.0f) << sonar.back().range;
  EXPECT_EQ(sonar.back().header.frame_id, "sonar_front");
  EXPECT_EQ(sonar.back().radiation_type, sensor_msgs::Range::ULTRASOUND);
  EXPECT_FLOAT_EQ(sonar.back().field_of_view, 0.2f);
  EXPECT_FLOAT_EQ(sonar.back().min_range, 0.02f);
  EXPECT_FLOAT_EQ(sonar.back().max_range, 2.0f);
  // Settled on its wheels for 1 s of sim time, then 2 s more with no command: still.
  const auto waitFor = [&](double seconds) {
    const double until = simNow(truth.back().header.stamp.toSec()) + seconds;
    return spinUntil([&] { return truth.back().header.stamp.toSec() >= until; }, 60.0);
  };
  ASSERT_TRUE(waitFor(1.0));
  const nav_msgs::Odometry rest = truth.back();
  ASSERT_TRUE(waitFor(2.0));
  const double crept = std::hypot(truth.back().pose.pose.position.x - rest.pose.pose.position.x,
                                  truth.back().pose.pose.position.y - rest.pose.pose.position.y);
  EXPECT_LT(crept, 1e-3) << "m in 2 s with no command";
  // The wheels' contact sensors (20 Hz, in the world frame): each the
  // ground under it, pressing up; together (at one stamp) the base's
  // weight, 7.01 kg (how four wheels share it is not determined).
  {
    ASSERT_GE(bumper.size(), 2u);
    EXPECT_NEAR((bumper.back().header.stamp - bumper[bumper.size() - 2].header.stamp).toSec(), 0.05, 1e-6);
    const ros::Time at = bumper.back().header.stamp;
    double bearing = 0.0;
    for (std::size_t w = 0; w < 4; ++w) {
      ASSERT_TRUE(spinUntil([&] { return bumpers[w].back().header.stamp >= at; }, 10.0)) << wheels[w];
      const auto c = std::find_if(bumpers[w].begin(), bumpers[w].end(),
                                  [&](const rigid_body_sim::Contacts& m) { return m.header.stamp == at; });
      ASSERT_NE(c, bumpers[w].end()) << wheels[w];
      EXPECT_EQ(c->header.frame_id, "world");
      ASSERT_EQ(c->pairs.size(), 1u) << wheels[w];
      EXPECT_EQ(c->pairs[0].body, "skid_steer/" + std::string(wheels[w]));
      EXPECT_EQ(c->pairs[0].other, "scene[0]");
      EXPECT_NEAR(c->pairs[0].normal.z, 1.0, 1e-6);
      EXPECT_GT(c->pairs[0].normal_force.z, 0.0);
      bearing += c->pairs[0].normal_force.z;
    }
    EXPECT_NEAR(bearing, 7.01 * 9.81, 0.01 * 7.01 * 9.81) << "N";
    std::printf("skid_steer: the wheels' contact sensors bear %.3f N (the weight: %.3f N)\n", bearing, 7.01 * 9.81);
  }
  // Its hector IMU (50 Hz, σ 0.005) at rest, over its last second: +g up, no turn.
  ASSERT_GE(imu.size(), 50u);
  double az = 0.0, wz = 0.0;
  for (std::size_t k = imu.size() - 50; k < imu.size(); ++k) {
    az += imu[k].linear_acceleration.z / 50.0;
    wz += imu[k].angular_velocity.z / 50.0;
  }
  EXPECT_EQ(imu.back().header.frame_id, "chassis");
  EXPECT_NEAR(az, 9.81, 0.01);  // 4σ of the mean of 50 is 0.003; the drift over 3 s is 1e-4
  EXPECT_NEAR(wz, 0.0, 0.005);
  EXPECT_NEAR((imu.back().header.stamp - imu[imu.size() - 2].header.stamp).toSec(), 0.02, 1e-6);
  const auto drive = [&](double v) {
    geometry_msgs::Twist twist;
    twist.linear.x = v;
    const auto send = [&](double seconds) {
      const double until = simNow(truth.back().header.stamp.toSec()) + seconds;
      while (ros::ok() && truth.back().header.stamp.toSec() < until) {
        cmd_vel.publish(twist);
        spinUntil([] { return false; }, 0.02);
      }
    };
    send(1.5);  // up to speed
    const nav_msgs::Odometry start = truth.back();
    send(1.0);
    const nav_msgs::Odometry& end = truth.back();
    const double over = (end.header.stamp - start.header.stamp).toSec();
    const double along = (end.pose.pose.position.x - start.pose.pose.position.x) / over;
    EXPECT_NEAR(along, v, std::max(0.05 * std::abs(v), 1e-3)) << "m/s of truth";
    EXPECT_NEAR(odom.back().twist.twist.linear.x, v, std::max(0.05 * std::abs(v), 1e-3))
        << "m/s of the wheels' odometry";
    EXPECT_NEAR(end.pose.pose.position.y, 0.0, 0.01);
    EXPECT_NEAR(end.twist.twist.angular.z, 0.0, 0.02);
    std::printf("skid_steer: %+.2f m/s commanded: truth %+.4f m/s, odometry %+.4f m/s, y %.4f m\n", v, along,
                odom.back().twist.twist.linear.x, end.pose.pose.position.y);
  };
  drive(0.3);
  // The GPS (40 Hz, Husky's: heading 90°, x east) where the truth is: its
  // last fix against the truth of the same stamp, a degree being 111227.12
  // m of latitude and 71844.33 m of longitude at 49.9° (Wikipedia's
  // "Latitude" and "Longitude" series for WGS84); its velocity in hector's
  // north, west, up: the base's +0.3 m/s east is -0.3 west.
  {
    ASSERT_GE(fixes.size(), 2u);
    EXPECT_NEAR((fixes.back().header.stamp - fixes[fixes.size() - 2].header.stamp).toSec(), 0.025, 1e-6);
    EXPECT_EQ(fixes.back().header.frame_id, "chassis");
    EXPECT_EQ(fixes.back().status.service, sensor_msgs::NavSatStatus::SERVICE_GPS);
    bool compared = false;
    for (auto f = fixes.rbegin(); f != fixes.rend() && !compared; ++f) {
      for (const nav_msgs::Odometry& t : truth) {
        if (t.header.stamp != f->header.stamp) continue;
        EXPECT_NEAR((f->longitude - 8.9) * 71844.33, t.pose.pose.position.x, 0.005) << "m east";
        EXPECT_NEAR((f->latitude - 49.9) * 111227.12, t.pose.pose.position.y, 0.005) << "m north";
        EXPECT_NEAR(f->altitude, t.pose.pose.position.z, 0.005);
        std::printf("skid_steer: GPS %.4f m east, %.4f m north; truth %.4f, %.4f\n", (f->longitude - 8.9) * 71844.33,
                    (f->latitude - 49.9) * 111227.12, t.pose.pose.position.x, t.pose.pose.position.y);
        compared = true;
        break;
      }
    }
    EXPECT_TRUE(compared) << "no fix and truth of one stamp";
    EXPECT_NEAR(fix_velocity.back().vector.x, 0.0, 0.015);
    EXPECT_NEAR(fix_velocity.back().vector.y, -0.3, 0.015);
    EXPECT_EQ(fixes.back().position_covariance_type, sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN);
    EXPECT_NEAR(fixes.back().position_covariance[0], 1e-8, 1e-20);  // drift²
    // The magnetometer (10 Hz; hector's heading 90°, inclination 60°), the
    // base facing east: north is its +y, the field dipping down at 60°.
    EXPECT_NEAR((field.back().header.stamp - field[field.size() - 2].header.stamp).toSec(), 0.1, 1e-6);
    EXPECT_NEAR(field.back().vector.x, 0.0, 0.02);
    EXPECT_NEAR(field.back().vector.y, 0.5, 0.02);
    EXPECT_NEAR(field.back().vector.z, -std::sqrt(3.0) / 2.0, 0.02);
  }
  drive(-0.3);
  drive(0.0);  // the plugin holds its last command: stopped before the crate comes
  // A crate (urdf/box.urdf, 0.4 m long) put 1.5 m ahead: the sonar, 0.3 m
  // ahead of the chassis's centre at 7 cm up, reads the distance to its
  // face within its noise (σ 0.005 m), at its 10 Hz.
  ASSERT_TRUE(ros::service::waitForService("/sim_node/spawn_body", 30000));
  rigid_body_sim::SpawnBody crate;
  crate.request.name = "crate";
  crate.request.urdf_file = "package://rigid_body_sim/urdf/box.urdf";
  crate.request.pose.position.x = truth.back().pose.pose.position.x + 1.5;
  crate.request.pose.position.z = 0.05;
  crate.request.pose.orientation.w = 1.0;
  ASSERT_TRUE(ros::service::call("/sim_node/spawn_body", crate)) << "the call";
  ASSERT_TRUE(crate.response.success) << crate.response.message;
  // Readings stamped after the step that added it (on a busy machine some
  // from before it are still queued when the answer comes).
  const std::string& said = crate.response.message;
  const std::size_t at = said.find("added at t = ");
  ASSERT_NE(at, std::string::npos) << said;
  const double added = std::stod(said.substr(at + 13));
  std::vector<sensor_msgs::Range> seen;
  ASSERT_TRUE(spinUntil(
      [&] {
        for (const sensor_msgs::Range& m : sonar) {
          if (m.header.stamp.toSec() > added) seen.push_back(m);
        }
        sonar.clear();
        return seen.size() >= 20;
      },
      30.0));
  double mean = 0.0;
  for (const sensor_msgs::Range& m : seen) mean += m.range / static_cast<double>(seen.size());
  EXPECT_NEAR(mean, 1.5 - 0.2 - 0.3, 0.008) << "m, the mean of " << seen.size();
  EXPECT_NEAR((seen.back().header.stamp - seen[seen.size() - 2].header.stamp).toSec(), 0.1, 1e-6);
  std::printf("skid_steer: sonar %.4f m (face at 1.0 m)\n", mean);
  // A 1 kg box (urdf/box.urdf) put on the chassis: its contact sensor, in
  // the chassis's frame (every step), has the box pressing down with its weight.
  EXPECT_TRUE(chassis.empty() || chassis.back().pairs.empty()) << "the chassis touched something before";
  rigid_body_sim::SpawnBody load;
  load.request.name = "load";
  load.request.urdf_file = "package://rigid_body_sim/urdf/box.urdf";
  load.request.pose.position.x = truth.back().pose.pose.position.x;
  load.request.pose.position.z = truth.back().pose.pose.position.z + 0.05 + 0.05 + 0.002;
  load.request.pose.orientation.w = 1.0;
  ASSERT_TRUE(ros::service::call("/sim_node/spawn_body", load)) << "the call";
  ASSERT_TRUE(load.response.success) << load.response.message;
  // A reading 0.5 s after the step that added it: the box, dropped 2 mm, has
  // landed (on a busy machine the test may still hold older ones).
  const std::size_t load_at = load.response.message.find("added at t = ");
  ASSERT_NE(load_at, std::string::npos) << load.response.message;
  const double landed = std::stod(load.response.message.substr(load_at + 13)) + 0.5;
  ASSERT_TRUE(spinUntil([&] { return !chassis.empty() && chassis.back().header.stamp.toSec() >= landed; }, 30.0));
  const rigid_body_sim::Contacts& on = chassis.back();
  EXPECT_EQ(on.header.frame_id, "chassis");
  ASSERT_EQ(on.pairs.size(), 1u);
  EXPECT_EQ(on.pairs[0].body, "skid_steer/chassis");  // the sensor's link first, though the box's index is lower
  EXPECT_EQ(on.pairs[0].other, "load");
  EXPECT_NEAR(on.pairs[0].normal.z, -1.0, 1e-3);  // from the box toward the chassis: down
  EXPECT_NEAR(on.pairs[0].normal_force.z, -9.81, 0.02 * 9.81) << "N on the chassis";
  for (const geometry_msgs::Point& q : on.pairs[0].points) EXPECT_NEAR(q.z, 0.05, 0.003) << "its top, in its frame";
  std::printf("skid_steer: the chassis bears %.3f N of the 1 kg box\n", -on.pairs[0].normal_force.z);
}

}  // namespace
