// A config's timeline in the node: the shipped scenarios run in lock-step
// (paused, then ~step) publish what rbsim writes for the same URDF and
// config, to the last bit (issue 57). timeline.test: the controller's
// odometry on /base_controller/odom, the IMU's samples on /imu, the noisy
// odometry on /odom and its truth on /ground_truth; timeline_lidar.test:
// the lidar's scans on /scan; timeline_effort.test: a joint effort's
// pendulum on /joint_states; timeline_trajectory.test: a trajectory
// controller's arm on /joint_states; body_devices.test: a body's IMU and
// noisy odometry among robots; body_drive.test: a body's velocity driver.
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../scratch_dir.h"
#include "node_fixture.h"
#include "rigid_body_sim/Step.h"

namespace {

using namespace rbs_test;

using Rows = std::map<long long, std::vector<double>>;

/// rbsim's run of `urdf` (under urdf/; "": the config's bodies) with
/// `config` (under config/) for 3 s into the scratch folder (one scenario
/// a test process).
std::string rbsimOut(const std::string& urdf, const std::string& config) {
  const std::string dir = rigid_body_sim::test::scratch().path().string();
  const std::string src = RBS_SOURCE_DIR;
  const std::string cmd = std::string(RBS_RBSIM) + (urdf.empty() ? "" : " --urdf " + src + "/urdf/" + urdf) +
                          " --config " + src + "/config/" + config + " --duration 3 --quiet --out " + dir +
                          " 2>/dev/null >/dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return dir;
}

/// rbsim's trajectory of `urdf` with `config` for 3 s into the scratch
/// folder: a row every `every` steps in trajectory.csv (12 digits a
/// number), its JSON line in run.json (each number to the last bit).
std::string rbsimTrajectory(const std::string& urdf, const std::string& config, int every) {
  const std::string dir = rigid_body_sim::test::scratch().path().string();
  const std::string src = RBS_SOURCE_DIR;
  const std::string cmd = std::string(RBS_RBSIM) + " --urdf " + src + "/urdf/" + urdf + " --config " + src +
                          "/config/" + config + " --duration 3 --quiet --every " + std::to_string(every) + " --csv " +
                          dir + "/trajectory.csv 2>/dev/null >" + dir + "/run.json";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return dir;
}

/// The rows of rbsim's file `name` in `dir` by their step (t / dt).
Rows rbsimRows(const std::string& dir, const std::string& name) {
  std::ifstream in(dir + "/" + name);
  std::string line;
  std::getline(in, line);
  Rows rows;
  while (std::getline(in, line)) {
    std::vector<double> x;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) x.push_back(std::strtod(cell.c_str(), nullptr));
    rows[std::llround(x.at(0) / kDt)] = x;
  }
  return rows;
}

/// The row of `rows` at a message's stamp.
const std::vector<double>& rowAt(const Rows& rows, const ros::Time& stamp) {
  static const std::vector<double> none;
  const auto it = rows.find(std::llround(stamp.toSec() / kDt));
  EXPECT_NE(it, rows.end()) << "no rbsim row at t " << stamp.toSec();
  return it == rows.end() ? none : it->second;
}

/// An odometry message against a sensor file's row t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz.
void expectOdometryRow(const nav_msgs::Odometry& m, const std::vector<double>& r) {
  ASSERT_EQ(r.size(), 14u);
  const geometry_msgs::Pose& p = m.pose.pose;
  const geometry_msgs::Twist& v = m.twist.twist;
  const std::vector<double> got{p.position.x,    p.position.y,    p.position.z, p.orientation.x, p.orientation.y,
                                p.orientation.z, p.orientation.w, v.linear.x,   v.linear.y,      v.linear.z,
                                v.angular.x,     v.angular.y,     v.angular.z};
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], r[i + 1]) << "t " << r[0] << " column " << i + 1;
}

/// An IMU message against a sensor file's row t,qx,qy,qz,qw,wx,wy,wz,ax,ay,az.
void expectImuRow(const sensor_msgs::Imu& m, const std::vector<double>& r) {
  ASSERT_EQ(r.size(), 11u);
  const std::vector<double> got{m.orientation.x,        m.orientation.y,         m.orientation.z,
                                m.orientation.w,        m.angular_velocity.x,    m.angular_velocity.y,
                                m.angular_velocity.z,   m.linear_acceleration.x, m.linear_acceleration.y,
                                m.linear_acceleration.z};
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], r[i + 1]) << "t " << r[0] << " column " << i + 1;
}

/// Whether the last of `messages` is stamped at or after t.
template <class M>
bool through(const std::vector<M>& messages, double t) {
  return !messages.empty() && messages.back().header.stamp.toSec() >= t;
}

/// The controller's odometry against rbsim's rows t,x,y,heading,linear,lateral,angular.
void expectDriveOdometry(const std::vector<nav_msgs::Odometry>& odom, const Rows& rows) {
  for (const nav_msgs::Odometry& m : odom) {
    const std::vector<double>& r = rowAt(rows, m.header.stamp);
    ASSERT_EQ(r.size(), 7u);
    const Eigen::Quaterniond q(Eigen::AngleAxisd(r[3], Eigen::Vector3d::UnitZ()));
    EXPECT_EQ(m.pose.pose.position.x, r[1]) << "t " << r[0];
    EXPECT_EQ(m.pose.pose.position.y, r[2]) << "t " << r[0];
    EXPECT_EQ(m.pose.pose.orientation.z, q.z()) << "t " << r[0];
    EXPECT_EQ(m.pose.pose.orientation.w, q.w()) << "t " << r[0];
    EXPECT_EQ(m.twist.twist.linear.x, r[4]) << "t " << r[0];
    EXPECT_EQ(m.twist.twist.linear.y, r[5]) << "t " << r[0];
    EXPECT_EQ(m.twist.twist.angular.z, r[6]) << "t " << r[0];
  }
}

class LockStep : public ::testing::Test {
 protected:
  /// 3 s in `batches` batches of ~step, each batch's messages in
  /// (`caught_up` at its end's sim time) before the next.
  void run(int batches, const std::vector<ros::Subscriber*>& topics, const std::function<bool(double)>& caught_up) {
    ros::ServiceClient step = nh_.serviceClient<rigid_body_sim::Step>("/sim_node/step");
    ASSERT_TRUE(step.waitForExistence(ros::Duration(30.0)));
    ASSERT_TRUE(spinUntil(
        [&] {
          for (const ros::Subscriber* s : topics) {
            if (s->getNumPublishers() == 0) return false;
          }
          return true;
        },
        30.0));
    const int steps = 3000 / batches;
    for (int batch = 1; batch <= batches; ++batch) {
      rigid_body_sim::Step srv;
      srv.request.steps = steps;
      ASSERT_TRUE(step.call(srv) && srv.response.success) << srv.response.message;
      const double t = kDt * steps * batch - 1e-9;
      ASSERT_TRUE(spinUntil([&] { return caught_up(t); }, 30.0)) << "batch " << batch;
    }
  }

  ros::NodeHandle nh_;
  template <class M>
  ros::Subscriber into(const std::string& topic, std::vector<M>& out) {
    return nh_.subscribe<M>(topic, 1000, [&out](const typename M::ConstPtr& m) { out.push_back(*m); });
  }
};

class Timeline : public LockStep {
 protected:
  /// 3 s in batches of 0.04 s (four of /odom's: its publisher queues 10;
  /// and a whole number of the controller's periods, since the node
  /// publishes its odometry after a ~step as well).
  void run() {
    LockStep::run(75, {&drive_, &imu_, &noisy_, &truth_}, [&](double t) {
      return through(odom, t) && through(imus, t) && through(truths, t) && through(noisy, t);
    });
  }

  std::vector<nav_msgs::Odometry> odom, noisy, truths;
  std::vector<sensor_msgs::Imu> imus;
  ros::Subscriber drive_ = into("/base_controller/odom", odom), imu_ = into("/imu", imus),
                  noisy_ = into("/odom", noisy), truth_ = into("/ground_truth", truths);
};

TEST_F(Timeline, TheNodeInLockStepPublishesRbsimsOutputsToTheLastBit) {
  run();
  const std::string out = rbsimOut("diff_drive.urdf", "diff_drive_timeline.yaml");
  // The controller's odometry: t,x,y,heading,linear,lateral,angular every 20 steps.
  const Rows rows = rbsimRows(out, "diff_drive.base_controller.odom.csv");
  ASSERT_EQ(rows.size(), 151u);
  expectDriveOdometry(odom, rows);
  EXPECT_GE(odom.size(), 150u);  // every 20 steps (the one at start may come before the subscription)
  EXPECT_GT(odom.back().pose.pose.position.x, 0.8);  // and it moved: 0.5 m/s on an arc for 2 s

  // The IMU, every 10 steps from the first period's end: t,qx,qy,qz,qw,wx,wy,wz,ax,ay,az.
  const Rows imu_rows = rbsimRows(out, "diff_drive.imu.csv");
  ASSERT_EQ(imu_rows.size(), 300u);
  EXPECT_GE(imus.size(), 299u);  // the first may come before the node counts the subscriber
  for (const sensor_msgs::Imu& m : imus) expectImuRow(m, rowAt(imu_rows, m.header.stamp));
  // The noisy odometry and its truth, every 10 steps (publish_rate 100 Hz).
  const Rows noisy_rows = rbsimRows(out, "diff_drive.odom.csv"),
             truth_rows = rbsimRows(out, "diff_drive.ground_truth.csv");
  ASSERT_EQ(noisy_rows.size(), 300u);
  ASSERT_EQ(truth_rows.size(), 300u);
  EXPECT_GE(noisy.size(), 299u);
  EXPECT_GE(truths.size(), 299u);
  for (const nav_msgs::Odometry& m : noisy) expectOdometryRow(m, rowAt(noisy_rows, m.header.stamp));
  for (const nav_msgs::Odometry& m : truths) expectOdometryRow(m, rowAt(truth_rows, m.header.stamp));
  // The noise is there: the report is not the truth.
  ASSERT_FALSE(noisy.empty());
  EXPECT_NE(noisy.back().pose.pose.position.x, truths.back().pose.pose.position.x);
}

class TimelineLidar : public LockStep {
 protected:
  /// 3 s in batches of 0.1 s: a scan and five of the controller's odometry each.
  void run() {
    LockStep::run(30, {&drive_, &scan_}, [&](double t) { return through(odom, t) && through(scans, t); });
  }

  std::vector<nav_msgs::Odometry> odom;
  std::vector<sensor_msgs::LaserScan> scans;
  ros::Subscriber drive_ = into("/base_controller/odom", odom), scan_ = into("/scan", scans);
};

TEST_F(TimelineLidar, TheNodeInLockStepPublishesRbsimsScansToTheLastBit) {
  run();
  const std::string out = rbsimOut("diff_drive_lidar.urdf", "diff_drive_lidar_timeline.yaml");
  expectDriveOdometry(odom, rbsimRows(out, "diff_drive_lidar.base_controller.odom.csv"));
  EXPECT_GE(odom.size(), 150u);
  // Every scan: t and 360 ranges (m; LaserScan's are float32 of the same doubles, REP 117's inf kept).
  const Rows rows = rbsimRows(out, "diff_drive_lidar.scan.csv");
  ASSERT_EQ(rows.size(), 30u);
  EXPECT_EQ(scans.size(), 30u);
  for (const sensor_msgs::LaserScan& m : scans) {
    const std::vector<double>& r = rowAt(rows, m.header.stamp);
    ASSERT_EQ(r.size(), 361u);
    ASSERT_EQ(m.ranges.size(), 360u);
    for (std::size_t k = 0; k < 360; ++k)
      EXPECT_EQ(m.ranges[k], static_cast<float>(r[k + 1])) << "t " << r[0] << " ray " << k;
  }
  ASSERT_FALSE(scans.empty());
  EXPECT_NEAR(scans.front().ranges[180], 1.9, 0.01);  // the wall ahead, from 0.1 m ahead of the base
}

// A joint effort from the timeline (config/pendulum_effort_timeline.yaml):
// 1 N·m on the pendulum's pivot from t = 0.2505 s for 0.5 s, in zero
// gravity. joint_states in lock-step reports rbsim's trajectory (its CSV's
// 12 digits, its final state to the last bit), and the push is
// apply_joint_effort's: at rest before it, the effort on the steps it
// covers (its first and last half a step), then τ d / I = 6 rad/s (I =
// 1/12 kg·m²).
class TimelineEffort : public LockStep {
 protected:
  void run() {
    LockStep::run(30, {&joints_}, [&](double t) { return through(states, t); });
  }
  std::vector<sensor_msgs::JointState> states;
  ros::Subscriber joints_ = into("/joint_states", states);
};

TEST_F(TimelineEffort, TheNodeInLockStepSwingsAsRbsimAndTheClosedForm) {
  run();
  const std::string out = rbsimTrajectory("pendulum.urdf", "pendulum_effort_timeline.yaml", 10);
  const Rows rows = rbsimRows(out, "trajectory.csv");
  ASSERT_EQ(rows.size(), 301u);  // t 0, 0.01, ..., 3: the same times as joint_states at publish_rate 100
  EXPECT_GE(states.size(), 300u);
  const auto near = [](double got, double row) { return std::abs(got - row) <= 1e-11 * std::max(1.0, std::abs(row)); };
  for (const sensor_msgs::JointState& m : states) {
    const std::vector<double>& r = rowAt(rows, m.header.stamp);
    ASSERT_EQ(r.size(), 16u);  // t, the base's 13 columns, pivot.position, pivot.velocity
    ASSERT_EQ(m.position.size(), 1u);
    EXPECT_TRUE(near(m.position[0], r[14])) << "t " << r[0] << ": " << m.position[0] << " vs " << r[14];
    EXPECT_TRUE(near(m.velocity[0], r[15])) << "t " << r[0] << ": " << m.velocity[0] << " vs " << r[15];
    const double t = m.header.stamp.toSec();
    if (t < 0.25) EXPECT_EQ(m.velocity[0], 0.0) << "t " << t;
    if (t > 0.26 && t < 0.75) {
      EXPECT_EQ(m.effort[0], 1.0) << "t " << t;
      EXPECT_NEAR(m.velocity[0], 12.0 * (t - 0.2505), 1e-9) << "t " << t;
    }
    if (t > 0.76) {
      EXPECT_EQ(m.effort[0], 0.0) << "t " << t;
      EXPECT_NEAR(m.velocity[0], 6.0, 1e-9) << "t " << t;
    }
  }
  // The last state, to the last bit: the JSON's "position": NUMBER and "velocity": NUMBER of its joint.
  std::ifstream in(out + "/run.json");
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto field = [&](const std::string& name) {
    const std::size_t at = json.find("\"" + name + "\":", json.find("\"pivot\""));
    return at == std::string::npos ? std::nan("") : std::strtod(json.c_str() + at + name.size() + 3, nullptr);
  };
  ASSERT_FALSE(states.empty());
  ASSERT_NEAR(states.back().header.stamp.toSec(), 3.0, 1e-9);
  EXPECT_EQ(states.back().position[0], field("position")) << json;
  EXPECT_EQ(states.back().velocity[0], field("velocity")) << json;
}

// A trajectory from the timeline (config/arm2_trajectory_timeline.yaml: the
// two-link arm's trajectory controller sent through [-0.25, 0.4] to
// [-0.5, 0.8] 2 s after 0.5 s, its joints named in another order):
// joint_states in lock-step reports rbsim's trajectory (its CSV's 12
// digits, its final state to the last bit); the arm held near its start
// before 0.5 s (its sag under gravity as the PID winds up, 28 mrad,
// measured) and ends near the last waypoint.
class TimelineTrajectory : public LockStep {
 protected:
  void run() {
    LockStep::run(30, {&joints_}, [&](double t) { return through(states, t); });
  }
  std::vector<sensor_msgs::JointState> states;
  ros::Subscriber joints_ = into("/joint_states", states);
};

TEST_F(TimelineTrajectory, TheNodeInLockStepSwingsTheArmAsRbsimDoes) {
  run();
  const std::string out = rbsimTrajectory("arm2.urdf", "arm2_trajectory_timeline.yaml", 10);
  const Rows rows = rbsimRows(out, "trajectory.csv");
  ASSERT_EQ(rows.size(), 301u);  // t 0, 0.01, ..., 3
  EXPECT_GE(states.size(), 300u);
  const auto near = [](double got, double row) { return std::abs(got - row) <= 1e-11 * std::max(1.0, std::abs(row)); };
  for (const sensor_msgs::JointState& m : states) {
    const std::vector<double>& r = rowAt(rows, m.header.stamp);
    ASSERT_EQ(r.size(), 18u);  // t, the base's 13 columns, shoulder's and elbow's position and velocity
    ASSERT_EQ(m.name, (std::vector<std::string>{"shoulder", "elbow"}));
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_TRUE(near(m.position[k], r[14 + 2 * k]))
          << "t " << r[0] << ": " << m.position[k] << " vs " << r[14 + 2 * k];
      EXPECT_TRUE(near(m.velocity[k], r[15 + 2 * k]))
          << "t " << r[0] << ": " << m.velocity[k] << " vs " << r[15 + 2 * k];
    }
    if (m.header.stamp.toSec() < 0.5) EXPECT_LT(std::abs(m.position[0]) + std::abs(m.position[1]), 0.05);
  }
  ASSERT_FALSE(states.empty());
  ASSERT_NEAR(states.back().header.stamp.toSec(), 3.0, 1e-9);
  EXPECT_NEAR(states.back().position[0], -0.5, 0.01);
  EXPECT_NEAR(states.back().position[1], 0.8, 0.01);
  // The last state, to the last bit: the JSON's "position": NUMBER and "velocity": NUMBER of each joint.
  std::ifstream in(out + "/run.json");
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto field = [&](const std::string& joint, const std::string& name) {
    const std::size_t at = json.find("\"" + name + "\":", json.find("\"" + joint + "\""));
    return at == std::string::npos ? std::nan("") : std::strtod(json.c_str() + at + name.size() + 3, nullptr);
  };
  EXPECT_EQ(states.back().position[0], field("shoulder", "position")) << json;
  EXPECT_EQ(states.back().velocity[0], field("shoulder", "velocity")) << json;
  EXPECT_EQ(states.back().position[1], field("elbow", "position")) << json;
  EXPECT_EQ(states.back().velocity[1], field("elbow", "velocity")) << json;
}

// A free body's devices among robots (config/robots.yaml's ball, struck by
// the pendulum: an IMU at 100 Hz, noisy odometry at publish_rate): the
// node in lock-step publishes rbsim's samples to the last bit. The node
// gave the i-th body the i-th entry's devices, the pendulum's (none) here.
class TimelineBodies : public LockStep {
 protected:
  void run() {
    LockStep::run(30, {&imu_, &noisy_, &truth_},
                  [&](double t) { return through(imus, t) && through(noisy, t) && through(truths, t); });
  }
  std::vector<nav_msgs::Odometry> noisy, truths;
  std::vector<sensor_msgs::Imu> imus;
  ros::Subscriber imu_ = into("/ball/imu", imus), noisy_ = into("/ball/odom", noisy),
                  truth_ = into("/ball/ground_truth", truths);
};

TEST_F(TimelineBodies, TheNodeInLockStepPublishesRbsimsBodySamplesToTheLastBit) {
  run();
  const std::string out = rbsimOut("", "robots.yaml");
  const Rows imu_rows = rbsimRows(out, "ball.imu.csv");
  ASSERT_EQ(imu_rows.size(), 300u);  // 0.01, ..., 3
  EXPECT_GE(imus.size(), 299u);
  for (const sensor_msgs::Imu& m : imus) expectImuRow(m, rowAt(imu_rows, m.header.stamp));
  const Rows noisy_rows = rbsimRows(out, "ball.odom.csv"), truth_rows = rbsimRows(out, "ball.ground_truth.csv");
  ASSERT_EQ(noisy_rows.size(), 301u);  // 0, 0.01, ..., 3
  ASSERT_EQ(truth_rows.size(), 301u);
  EXPECT_GE(noisy.size(), 299u);
  for (const nav_msgs::Odometry& m : noisy) expectOdometryRow(m, rowAt(noisy_rows, m.header.stamp));
  for (const nav_msgs::Odometry& m : truths) expectOdometryRow(m, rowAt(truth_rows, m.header.stamp));
  ASSERT_FALSE(truths.empty());
  EXPECT_GT(std::abs(truths.back().pose.pose.position.x - 0.15), 0.05);  // struck: it moved
  EXPECT_NE(noisy.back().pose.pose.position.x, truths.back().pose.pose.position.x);
}

// A body's velocity driver commanded by the timeline
// (config/box_cmd_vel_timeline.yaml: the box pushed ahead, then turned in
// place): the node in lock-step moves it as rbsim does, to the last bit. rbsim
// ran no body's cmd_vel; the node's driver took a command given at t from
// the step after it.
class TimelineBodyDrive : public LockStep {
 protected:
  void run() {
    LockStep::run(30, {&truth_}, [&](double t) { return through(truths, t); });
  }
  std::vector<nav_msgs::Odometry> truths;
  ros::Subscriber truth_ = into("/ground_truth", truths);
};

TEST_F(TimelineBodyDrive, TheNodeInLockStepDrivesTheBodyAsRbsimDoes) {
  run();
  const std::string out = rbsimOut("", "box_cmd_vel_timeline.yaml");
  const Rows truth_rows = rbsimRows(out, "box.ground_truth.csv");
  ASSERT_EQ(truth_rows.size(), 301u);  // 0, 0.01, ..., 3
  EXPECT_GE(truths.size(), 299u);
  for (const nav_msgs::Odometry& m : truths) expectOdometryRow(m, rowAt(truth_rows, m.header.stamp));
  ASSERT_FALSE(truths.empty());
  // Driven: 0.4 m/s for 1 s less the driver's start (0.3907 m measured),
  // then 1 rad/s in place for 1 s less its start and friction's stop (0.903 rad).
  const geometry_msgs::Pose& end = truths.back().pose.pose;
  EXPECT_NEAR(end.position.x, 0.39, 0.01);
  EXPECT_NEAR(2.0 * std::atan2(end.orientation.z, end.orientation.w), 0.9, 0.05);
}

}  // namespace
