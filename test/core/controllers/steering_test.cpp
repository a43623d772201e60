// A steered base's controller (docs/physics.md §11.14) against closed
// forms: Ackermann's linkage rolls both front wheels about one point, the
// odometry of a car and of a tricycle on a steady arc, the wheel speeds a
// command asks for (no wheel scrubs), and refusals. The base driving on the
// ground is the node's ackermann.test.
#include "rigid_body_sim/core/controllers/steering.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "../articulations/articulation_models.h"
#include "rigid_body_sim/core/controllers/diff_drive.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kH = 1e-3;
constexpr double kL = 0.6, kHalfTrack = 0.25, kRadius = 0.1;

ArticulatedLink wheel(const std::string& name, int parent, const Vec3& at) {
  ArticulatedLink w;
  w.name = name + "_wheel";
  w.joint = name + "_wheel_joint";
  w.parent = parent;
  w.type = JointType::Continuous;
  w.X_PJ.translation = at;
  w.axis_J = Vec3::UnitY();
  w.limits.effort = 5.0;
  w.limits.velocity = 50.0;
  w.mass.mass = 1.0;
  w.mass.I_C_F = Vec3(0.01, 0.02, 0.01).asDiagonal();
  return w;
}

ArticulatedLink knuckle(const std::string& name, const Vec3& at) {
  ArticulatedLink k;
  k.name = name + "_knuckle";
  k.joint = name + "_steer_joint";
  k.parent = 0;
  k.type = JointType::Revolute;
  k.X_PJ.translation = at;
  k.axis_J = Vec3::UnitZ();
  k.limits = {-0.6, 0.6, 10.0, 5.0};
  k.mass.mass = 0.2;
  k.mass.I_C_F = Vec3(1e-3, 1e-3, 1e-3).asDiagonal();
  return k;
}

/// A 20 kg car: rear wheels (links 1, 2) at x = 0, y = ±0.25; front
/// knuckles (3, 5) at x = 0.6 steering their wheels (4, 6). q: rear left,
/// rear right, left knuckle, left front wheel, right knuckle, right front wheel.
ArticulationModel car() {
  ArticulationModel model;
  model.name = "car";
  ArticulatedLink base;
  base.name = "base_link";
  base.mass = test::boxMass(20.0, Vec3(0.8, 0.5, 0.1));
  model.links = {base,
                 wheel("rear_left", 0, Vec3(0.0, kHalfTrack, 0.0)),
                 wheel("rear_right", 0, Vec3(0.0, -kHalfTrack, 0.0)),
                 knuckle("left", Vec3(kL, kHalfTrack, 0.0)),
                 wheel("front_left", 3, Vec3::Zero()),
                 knuckle("right", Vec3(kL, -kHalfTrack, 0.0)),
                 wheel("front_right", 5, Vec3::Zero())};
  checkArticulation(model);
  return model;
}

/// ackermann_steering_controller on the rear wheels, both knuckles linked.
DiffDriveSpec ackermann() {
  DiffDriveSpec s;
  s.name = "ackermann";
  s.left = {1, 2};
  s.wheel_separation = kL;
  s.wheel_radius = kRadius;
  SteeringSpec st;
  st.joints = {3, 5};
  st.joint_x = {kL, kL};
  st.joint_y = {kHalfTrack, -kHalfTrack};
  st.joint_sign = {1.0, 1.0};
  st.wheelbase = kL;
  st.wheel_x = {0.0, 0.0};
  st.wheel_y = {kHalfTrack, -kHalfTrack};
  st.wheel_steer = {-1, -1};
  s.steering = st;
  return s;
}

TEST(Steering, AckermannsLinkageRollsBothFrontWheelsAboutOnePoint) {
  for (const double delta : {0.3, -0.45, 1e-3}) {
    const double R = kL / std::tan(delta);  // the virtual middle wheel's centre of turn, on the rear axle's line
    for (const double y : {kHalfTrack, -kHalfTrack}) {
      const double a = steerAngle(delta, kL, kL, y);
      EXPECT_NEAR(y + kL / std::tan(a), R, 1e-9 * std::abs(R)) << delta << " " << y;
    }
  }
  // The inner wheel turns further: left in a left turn.
  EXPECT_GT(steerAngle(0.3, kL, kL, kHalfTrack), steerAngle(0.3, kL, kL, -kHalfTrack));
  EXPECT_DOUBLE_EQ(steerAngle(0.3, kL, kL, 0.0), 0.3);
}

ArticulationState carAt(const ArticulationModel& model, double delta, double rear_left, double rear_right) {
  ArticulationState s = restState(model);
  s.q(0) = rear_left;
  s.q(1) = rear_right;
  s.q(2) = steerAngle(delta, kL, kL, kHalfTrack);
  s.q(4) = steerAngle(delta, kL, kL, -kHalfTrack);
  return s;
}

TEST(SteeringOdometry, FollowsTheArcOfACarSteeredSteadily) {
  const ArticulationModel model = car();
  DiffDrive drive(model, ackermann());
  const double delta = 0.3, v = 0.8, w = v * std::tan(delta) / kL;  // the rear axle's centre at v
  drive.restart(carAt(model, delta, 0.4, -1.0), true);
  const int steps = 3000;
  for (int n = 1; n <= steps; ++n) {
    const double t = n * kH;
    drive.observe(
        carAt(model, delta, 0.4 + (v - w * kHalfTrack) * t / kRadius, -1.0 + (v + w * kHalfTrack) * t / kRadius), kH);
  }
  const double T = steps * kH, R = v / w, theta = w * T;
  const PlanarOdometry& o = drive.odometry();
  EXPECT_NEAR(o.heading, theta, 1e-9);
  EXPECT_NEAR(o.x, R * std::sin(theta), 1e-9);
  EXPECT_NEAR(o.y, R * (1.0 - std::cos(theta)), 1e-9);
  EXPECT_NEAR(o.linear, v, 1e-9);
  EXPECT_NEAR(o.angular, w, 1e-9);
}

TEST(SteeringOdometry, ATricycleMovesAsItsSteeredWheelRolls) {
  const ArticulationModel model = car();
  DiffDriveSpec s = ackermann();  // the left knuckle alone steers, its wheel drives
  s.left = {4};
  SteeringSpec& st = *s.steering;
  st.joints = {3};
  st.joint_x = {kL};
  st.joint_y = {0.0};
  st.joint_sign = {1.0};
  st.wheel_x = {kL};
  st.wheel_y = {0.0};
  st.wheel_steer = {0};
  st.speed_at_steered_wheel = true;
  DiffDrive drive(model, s);
  const double delta = 0.5, vf = 0.6;
  ArticulationState state = restState(model);
  state.q(2) = delta;
  drive.restart(state, true);
  for (int n = 1; n <= 1000; ++n) {
    state.q(3) = vf * n * kH / kRadius;
    drive.observe(state, kH);
  }
  // The rear axle's centre at vf cos δ, turning vf sin δ / L.
  EXPECT_NEAR(drive.odometry().linear, vf * std::cos(delta), 1e-9);
  EXPECT_NEAR(drive.odometry().angular, vf * std::sin(delta) / kL, 1e-9);
}

TEST(SteeredDrive, AsksEachWheelForItsOwnPathsSpeedAndSteersTheLinkage) {
  const ArticulationModel model = car();
  DiffDriveSpec s = ackermann();
  s.gains = {{0.5, 0.0, 0.0, 0.0}, {0.5, 0.0, 0.0, 0.0}};
  DiffDrive drive(model, s);
  const double delta = 0.3;
  const ArticulationState state = carAt(model, delta, 0.0, 0.0);
  drive.restart(state, true);
  ASSERT_TRUE(drive.command(0.5, delta, 0.0));  // within the wheels' 5 N m
  Eigen::VectorXd effort = Eigen::VectorXd::Zero(6);
  drive.efforts(state, kH, kH, effort);
  // The rear wheels at rest, asked for (v ∓ ω w/2)/r: their efforts in that
  // ratio (the two answer alike); the knuckles at their angles: held.
  const double w = std::tan(delta) / kL;
  EXPECT_NEAR(effort(0) / effort(1), (1.0 - w * kHalfTrack) / (1.0 + w * kHalfTrack), 1e-12);
  EXPECT_GT(effort(0), 0.0);
  EXPECT_NEAR(effort(2), 0.0, 1e-12);
  EXPECT_NEAR(effort(4), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(effort(3), 0.0);  // the front wheels roll free
  // Straight ahead from there: both knuckles turn back toward 0.
  ASSERT_TRUE(drive.command(0.5, 0.0, 2 * kH));
  drive.efforts(state, 2 * kH, kH, effort);
  EXPECT_LT(effort(2), 0.0);
  EXPECT_LT(effort(4), 0.0);
  EXPECT_NEAR(effort(0), effort(1), 1e-12);
}

TEST(SteeredDrive, ASteeringAngleAtOrPast90DegreesAsksFiniteEfforts) {
  ArticulationModel model = car();  // no limits on the rear wheels: nothing else holds their speeds
  for (const int j : {1, 2}) model.links[j].limits = JointLimits{};
  DiffDrive drive(model, ackermann());
  const ArticulationState state = restState(model);
  drive.restart(state, true);
  for (const double delta : {0.5 * M_PI, -10.0, 1e300}) {
    ASSERT_EQ(drive.command(1.0, delta, 0.0), std::abs(delta) <= 1e4) << delta;  // ranges::kMaxCommandSpeed
    Eigen::VectorXd effort = Eigen::VectorXd::Zero(6);
    drive.efforts(state, kH, kH, effort);
    EXPECT_TRUE(effort.allFinite()) << delta;
    // The rear wheels asked for tan 80° = 5.7 of the turn, not tan 90°, 1.6e16.
    EXPECT_LE(effort.cwiseAbs().maxCoeff(), 1e3) << delta;  // about 290 N m
  }
  EXPECT_NEAR(steerable(ackermann().steering.value(), 2.0), 80.0 * M_PI / 180.0, 1e-15);
}

TEST(SteeredDrive, RefusesASteeringJointThatIsAWheelOrMissing) {
  const ArticulationModel model = car();
  DiffDriveSpec s = ackermann();
  s.steering->joints = {1, 5};
  EXPECT_THROW(DiffDrive(model, s), std::invalid_argument);
  s = ackermann();
  s.steering->joints.clear();
  EXPECT_THROW(DiffDrive(model, s), std::invalid_argument);
  s = ackermann();
  s.right = {2};
  EXPECT_THROW(DiffDrive(model, s), std::invalid_argument);
  s = ackermann();
  s.steering->wheelbase = 0.0;
  EXPECT_THROW(DiffDrive(model, s), std::invalid_argument);
}

}  // namespace
}  // namespace rigid_body_sim::core
