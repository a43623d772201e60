// A robot's link sensors (core::LinkSensors, docs/physics.md §10.11) on a
// swinging pendulum stepped as the node and rbsim step it: each samples
// only at its rate of sim time, its sample is its device's over its own
// period at its mount, noise is seeded, a restart forgets a jump.
#include "rigid_body_sim/core/devices/link_sensors.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../controllers/controlled_robot.h"

namespace rigid_body_sim::test {
namespace {

using core::LinkSensors;
using Kind = core::LinkSensors::Kind;

const Vec3 kG(0.0, 0.0, -9.81);
const core::Pose kAtBob{Quat::Identity(), Vec3(0.0, 0.0, -0.5)};  ///< the bob, in the arm's frame

/// A swinging pendulum (1 rad from hanging) and the arm's state at it.
struct Swing : Alone {
  Swing() : Alone(pendulum(10.0), kG) { robot().q[0] = 1.0; }
  core::LinkState bob() const {
    return core::frameState(core::linkStateOf(core::kinematics(scene.robots()[0].model, state.robots[0]), 1), kAtBob);
  }
  const core::ArticulationModel& model() const { return scene.robots()[0].model; }
};

TEST(SampleClock, RoundsItsRateToWholeStepsAndCountsItsPeriods) {
  core::SampleClock clock(30.0, 0.01);
  EXPECT_EQ(clock.every(), 3);
  EXPECT_DOUBLE_EQ(clock.rate(), 1.0 / 0.03);
  EXPECT_FALSE(clock.due(4));
  EXPECT_TRUE(clock.due(6));
  EXPECT_DOUBLE_EQ(clock.elapsed(0.03), 0.03);         // the first: one period
  EXPECT_DOUBLE_EQ(clock.elapsed(0.09), 0.06);         // then since the last
  EXPECT_EQ(core::SampleClock(0.0, 0.01).every(), 1);  // 0: every step
  EXPECT_EQ(core::SampleClock(1e9, 0.01).every(), 1);  // never faster than the step
}

// An IMU at 100 Hz on 1 ms steps samples every tenth step, and its reading
// is the exact one over those ten steps at its mount on the bob.
TEST(LinkSensors, AnImuSamplesAtItsRateOverItsOwnPeriod) {
  Swing w;
  core::ImuSettings imu;
  imu.rate = 100.0;
  imu.X_LS = kAtBob;
  LinkSensors sensors(kStep);
  sensors.addImu(imu, 1, w.model(), w.robot());
  core::LinkState previous = core::linkStateOf(core::kinematics(w.model(), w.robot()), 1);
  int samples = 0;
  for (long long k = 1; k <= 100; ++k) {
    w.step({});
    const bool any = sensors.sample(w.scene, 0, w.state.bodies, w.robot(), k, static_cast<double>(k) * kStep);
    EXPECT_EQ(any, k % 10 == 0) << k;
    EXPECT_EQ(sensors.fresh(Kind::kImu, 0), k % 10 == 0) << k;
    if (!any) continue;
    const core::LinkState now = core::linkStateOf(core::kinematics(w.model(), w.robot()), 1);
    const core::ImuReading exact = core::exactImuReading(previous, now, kAtBob, kG, 0.01);
    const core::ImuReading& got = sensors.imus()[0].reading;
    EXPECT_EQ(got.w_S, exact.w_S) << k;
    EXPECT_EQ(got.f_S, exact.f_S) << k;
    previous = now;
    ++samples;
  }
  EXPECT_EQ(samples, 10);
  // It swung: the gyro reads the arm's turn about y.
  EXPECT_GT(std::abs(sensors.imus()[0].reading.w_S.y()), 0.5);
}

// Odometry reports its mount's state: exact as the truth, with noise as the
// seed draws it (the same seed, the same report); a receiver at rate 0
// fixes every step where the mount is; a magnetometer reads the field in
// its axes.
TEST(LinkSensors, OdometryReceiversAndMagnetometersReadTheirMount) {
  Swing w;
  core::OdomNoiseSettings noise;
  noise.position = 0.01;
  noise.drift_x = 0.1;
  noise.seed = 5;
  core::GnssSettings gnss;
  core::MagnetometerSettings field;
  LinkSensors a(kStep), b(kStep);
  for (LinkSensors* s : {&a, &b}) {
    s->addOdometry(std::nullopt, {1, kAtBob}, 50.0);
    s->addOdometry(noise, {1, kAtBob}, 50.0);
    s->addGnss(gnss, {1, kAtBob}, 0.0);
    s->addMagnetometer(field, {1, kAtBob}, 0.0);
  }
  for (long long k = 1; k <= 40; ++k) {
    w.step({});
    a.sample(w.scene, 0, w.state.bodies, w.robot(), k, static_cast<double>(k) * kStep);
    b.sample(w.scene, 0, w.state.bodies, w.robot(), k, static_cast<double>(k) * kStep);
    const core::LinkState bob = w.bob();
    EXPECT_TRUE(a.fresh(Kind::kGnss, 0));
    const core::GnssFix exact = core::exactGnssFix(gnss.reference, bob.p_WL, bob.v_WL);
    EXPECT_EQ(a.gnss()[0].fix.latitude, exact.latitude) << k;
    EXPECT_EQ(a.gnss()[0].fix.altitude, exact.altitude) << k;
    EXPECT_TRUE((a.magnetometers()[0].field_S - bob.q_WL.conjugate() * core::magneticField_W(field)).norm() < 1e-15);
    EXPECT_EQ(a.fresh(Kind::kOdometry, 1), k % 20 == 0) << k;
    if (k % 20 != 0) continue;
    const core::OdomReport truth = core::exactOdom(bob);
    EXPECT_EQ(a.odometry()[0].report.p_WL, truth.p_WL) << k;
    EXPECT_EQ(a.odometry()[1].truth.p_WL, truth.p_WL) << k;
    EXPECT_GT((a.odometry()[1].report.p_WL - truth.p_WL).norm(), 0.0) << k;
    EXPECT_EQ(a.odometry()[1].report.p_WL, b.odometry()[1].report.p_WL) << k;
  }
  EXPECT_NE(a.odometry()[1].noise->drift().x(), 0.0);
  a.restartNoise();
  EXPECT_EQ(a.odometry()[1].noise->drift().x(), 0.0);
}

// Put somewhere else between samples (set_model_configuration), an IMU
// restarted reads the pendulum's own motion, hanging at rest; one not
// restarted reads the jump of 1 rad as a turn in one sample (1000 rad/s).
TEST(LinkSensors, ARestartedImuReadsNoJump) {
  core::ImuSettings imu;
  imu.X_LS = kAtBob;
  imu.rate = 1000.0;
  Swing w;
  LinkSensors kept(kStep), restarted(kStep);
  kept.addImu(imu, 1, w.model(), w.robot());
  restarted.addImu(imu, 1, w.model(), w.robot());
  w.robot().q[0] = 0.0;  // hanging, at rest
  w.robot().v.setZero();
  restarted.restartImus(w.model(), w.robot());
  w.step({});
  kept.sample(w.scene, 0, w.state.bodies, w.robot(), 1, kStep);
  restarted.sample(w.scene, 0, w.state.bodies, w.robot(), 1, kStep);
  EXPECT_NEAR((restarted.imus()[0].reading.f_S - Vec3(0.0, 0.0, 9.81)).norm(), 0.0, 1e-6);
  EXPECT_NEAR(restarted.imus()[0].reading.w_S.norm(), 0.0, 1e-9);
  EXPECT_NEAR(kept.imus()[0].reading.w_S.norm(), 1000.0, 1.0);
}

/// The pendulum with a ball of 0.05 m about its bob, over the ground at height `ground`.
Scene ballOverGround(double ground) {
  ArticulationModel model = pendulum(10.0);
  core::CollisionShape ball;
  ball.kind = core::CollisionShape::Kind::kSphere;
  ball.radius = 0.05;
  ball.X_LS.translation = kAtBob.translation;
  model.links[1].collision = {ball};
  ModelSpec spec = Alone::spec(kG);
  spec.scene = {core::Sdf::plane(Vec3::UnitZ(), Vec3(0.0, 0.0, ground))};
  return Scene(spec, {{"robot", model}});
}

// A lidar on the bob, hanging at rest 0.5 m above the ground and looking
// straight down from inside the bob's own ball: it samples at its rate,
// sees the ground at 0.5 m / cos(azimuth) and not its own link; one not
// cast while nobody reads it casts the same noisy scan as one cast every
// time.
TEST(LinkSensors, ALidarCastsIntoTheWorldAtItsRateAndSkipsItsOwnLinks) {
  const Scene scene = ballOverGround(-1.0);
  const ArticulationModel& model = scene.robots()[0].model;
  SceneState state = core::sceneState(scene, {}, {core::restState(model)});
  ASSERT_EQ(scene.robots()[0].link.size(), 1u);  // the bob's ball is a body of the world
  core::LidarSettings lidar;
  lidar.samples = 3;
  lidar.min_angle = -0.2;
  lidar.max_angle = 0.2;
  lidar.noise = 0.001;
  lidar.seed = 4;
  const core::LinkMount down{1, core::Pose{Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY())), kAtBob.translation}};
  LinkSensors every(kStep), late(kStep);
  every.addLidar(lidar, std::nullopt, down, 100.0);
  late.addLidar(lidar, core::RangeFinderSettings{}, down, 100.0);
  late.want(Kind::kLidar, 0, false);
  for (long long k = 1; k <= 20; ++k) {
    if (k == 11) late.want(Kind::kLidar, 0, true);  // someone listens from the second scan on
    const double t = static_cast<double>(k) * kStep;
    EXPECT_EQ(every.sample(scene, 0, state.bodies, state.robots[0], k, t), k % 10 == 0) << k;
    late.sample(scene, 0, state.bodies, state.robots[0], k, t);
    EXPECT_EQ(every.fresh(Kind::kLidar, 0), k % 10 == 0) << k;
    if (k == 10) {
      EXPECT_TRUE(late.fresh(Kind::kLidar, 0));
      EXPECT_TRUE(late.lidars()[0].ranges.empty());  // due, but not cast
    }
  }
  const std::vector<double>& ranges = every.lidars()[0].ranges;
  ASSERT_EQ(ranges.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(ranges[i], 0.5 / std::cos(-0.2 + 0.2 * static_cast<double>(i)), 0.01) << i;
  }
  EXPECT_NE(ranges[1], 0.5);                   // with its noise
  EXPECT_EQ(late.lidars()[0].ranges, ranges);  // the second scan, as if the first had been cast
  EXPECT_EQ(late.lidars()[0].reading, *std::min_element(ranges.begin(), ranges.end()));  // no noise of its own
}

// The force sensors, from what a step left, on the pendulum hanging at
// rest with its bob's ball on the ground: a contact sensor on the bob
// reports that one pair, the ground's normal up, in the world or in the
// bob's frame; the hinge's force-torque sensor (gazebo_ros_ft_sensor's:
// the joint's load on its child, in the child's axes) reads the rest of
// the bob's weight, so the two hold it up together, and no moment about
// the hinge; without the step's contacts a due force sensor is refused,
// not read as nothing.
TEST(LinkSensors, ForceSensorsReadTheStepsLoadsAndContacts) {
  const Scene scene = ballOverGround(-0.549);  // 1 mm into the ball
  const ArticulationModel& model = scene.robots()[0].model;
  SceneState state = core::sceneState(scene, {}, {core::restState(model)});
  SceneWorkspace ws;
  core::ContactLedger ledger;
  LinkSensors sensors(kStep);
  sensors.addForceTorque({}, 1, 0.0);
  sensors.addContactSensor({1, core::Pose{}}, true, 0.0);
  // In the bob's frame: the hinge's, here the world's turned by q.
  sensors.addContactSensor({1, core::Pose{}}, false, 0.0);
  sensors.addContactSensor({0, core::Pose{}}, true, 0.0);  // on the fixed base, which has no collision shape
  const ArticulationLoads none;
  for (long long k = 1; k <= 3; ++k) {
    sensors.before(scene.robots()[0].model, state.robots[0]);
    core::stepScene(scene, state, {{}, {none}}, ws);
    ledger.update(state.bodies, ws.bodies.contacts);
    core::StepContacts contacts(scene.model(), state.bodies, ledger, ws.bodies.contacts);
    EXPECT_TRUE(sensors.sample(scene, 0, state.bodies, state.robots[0], k, static_cast<double>(k) * kStep,
                               core::StepForces{&none, &contacts}));
  }
  ASSERT_EQ(sensors.contactSensors()[0].pairs.size(), 1u);
  const core::ContactPairReport& pair = sensors.contactSensors()[0].pairs[0];
  const core::Vec6& w = sensors.forceTorques()[0].wrench;
  EXPECT_NEAR(w.tail<3>().z() + pair.normal_force_W.z(), 9.81, 0.05);  // 1 kg held up by the hinge and the ground
  EXPECT_NEAR(w.tail<3>().x(), 0.0, 0.05);
  EXPECT_NEAR(w.head<3>().norm(), 0.0, 0.05);
  EXPECT_EQ(pair.body, scene.robots()[0].first_body);
  EXPECT_EQ(pair.other, -1);
  EXPECT_EQ(pair.item, 0);
  EXPECT_NEAR((pair.normal_W - Vec3::UnitZ()).norm(), 0.0, 1e-9);
  for (const Vec3& p : pair.points_W) EXPECT_NEAR(p.z(), -0.549, 2e-3);
  const core::Quat q_WL = core::linkStateOf(core::kinematics(scene.robots()[0].model, state.robots[0]), 1).q_WL;
  const core::ContactPairReport& in_bob = sensors.contactSensors()[1].pairs.at(0);
  EXPECT_NEAR((in_bob.normal_W - q_WL.conjugate() * Vec3::UnitZ()).norm(), 0.0, 1e-9);
  for (const Vec3& p : in_bob.points_W) EXPECT_NEAR(p.z(), -0.549, 3e-3);  // from the hinge, hanging nearly straight
  // The base touches nothing: the bob's pair with the ground (its `other` -1) is not the base's.
  EXPECT_TRUE(sensors.contactSensors()[2].pairs.empty());
  EXPECT_THROW(sensors.sample(scene, 0, state.bodies, state.robots[0], 4, 4 * kStep), std::invalid_argument);
}

}  // namespace
}  // namespace rigid_body_sim::test
