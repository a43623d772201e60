// The node's per-body ports (no master): what a spawn adds and a delete
// removes goes in and out of the ports and the names together, later bodies
// move down in both, a body's colour is the order it entered in, a deleted
// body's ports are let go on the closer's queue, and a restart makes a jump
// no acceleration for the IMU.
#include "rigid_body_sim/ros/body_ports.h"

#include <gtest/gtest.h>

#include "../test_util.h"

namespace rigid_body_sim::node {
namespace {

using test::Vec3;

core::Model world(const std::vector<std::string>& names) {
  std::vector<core::BodySpec> bodies;
  for (const std::string& name : names) {
    core::BodySpec b = test::boxBody(Vec3(0.1, 0.1, 0.1));
    b.name = name;
    bodies.push_back(b);
  }
  core::ModelSpec spec = test::spec(bodies.front(), 1e-3, Vec3(0, 0, -9.81));
  spec.bodies = bodies;
  return core::Model(spec);
}

/// Ports as openPorts makes them for a body of a world, without topics:
/// with an IMU at 100 Hz, or odometry with a drift of 1 m/√s in x.
BodyPorts portsOf(const core::BodyModel& body, bool with_imu = false, bool with_drift = false) {
  BodyPorts p;
  p.prefix = body.name + "/";
  p.frame = p.prefix + body.link;
  if (with_imu || with_drift) p.sensors = std::make_unique<core::BodySensors>(1e-3);
  if (with_imu) {
    core::ImuSettings imu;
    imu.rate = 100.0;
    p.sensors->addImu(imu);
    p.imu_frame = p.prefix + "imu_link";
  }
  if (with_drift) {
    core::OdomNoiseSettings noise;
    noise.drift_x = 1.0;
    p.sensors->addOdometryNoise(noise);
  }
  return p;
}

TEST(PortRegistry, AddAndEraseKeepThePortsAndTheNamesInStep) {
  const core::Model model = world({"a", "b", "c", "d"});
  const core::State s = core::restState(model);
  ros::CallbackQueue closer;
  PortRegistry ports(closer);
  for (int i = 0; i < 3; ++i) ports.add(portsOf(model.body(i), i == 1), model.body(i), s.bodies[i], 0.0);
  ASSERT_EQ(ports.size(), 3u);
  EXPECT_EQ(ports.directory().byName("c"), 2);
  EXPECT_EQ(ports.directory().ownerOf("b/imu_link"), 1);
  EXPECT_EQ(ports.frames(), (std::vector<std::string>{"a/" + model.body(0).link, "b/" + model.body(1).link,
                                                      "c/" + model.body(2).link}));

  ports.erase(1);
  ASSERT_EQ(ports.size(), 2u);
  EXPECT_EQ(ports[1].frame, "c/" + model.body(2).link);
  EXPECT_EQ(ports.directory().byName("c"), 1);
  EXPECT_EQ(ports.directory().byFrame(ports[1].frame), 1);
  EXPECT_FALSE(ports.directory().byName("b"));
  EXPECT_FALSE(ports.directory().ownerOf("b/imu_link"));
  // Its ports wait on the closer's queue (closing a topic waits for the master).
  EXPECT_FALSE(closer.isEmpty());
  closer.callAvailable();
  EXPECT_TRUE(closer.isEmpty());

  // A body added after a delete takes the next colour, not the freed one.
  ports.add(portsOf(model.body(3), false, true), model.body(3), s.bodies[3], 2.5);
  EXPECT_EQ(ports.colours(), (std::vector<std::size_t>{0, 2, 3}));
  EXPECT_EQ(ports.directory().byName("d"), 2);
  // Its odometry's drift walks from when it was added: σ² = 1 m²/s × 1 s at 3.5 s.
  const core::OdomReport first = ports[2].sensors->report(core::linkState(model.body(3), s.bodies[3]), 3.5);
  EXPECT_DOUBLE_EQ(first.pose_variance[0], 1.0);
  EXPECT_THROW(ports.erase(3), std::out_of_range);
  EXPECT_EQ(ports.size(), 3u);
}

TEST(PortRegistry, ARestartMakesAJumpNoAcceleration) {
  // A body put at rest somewhere else (set_state, reset) after moving at
  // 1 m/s: without a restart the IMU reads the jump as a deceleration.
  const core::Model model = world({"a", "b"});
  core::State moving = core::restState(model), still = moving;
  moving.bodies[0].v_WB = Vec3(1, 0, 0);
  ros::CallbackQueue closer;
  PortRegistry ports(closer);
  ports.add(portsOf(model.body(0), true), model.body(0), moving.bodies[0], 0.0);
  const double period = 0.01;  // 10 steps of 1 ms: the IMU samples after the 10th
  const Vec3 g = model.gravity();
  core::BodySensors& a = *ports[0].sensors;
  a.sample(model.body(0), still.bodies[0], g, 9);
  EXPECT_FALSE(a.imuFresh());
  a.sample(model.body(0), still.bodies[0], g, 10);
  ASSERT_TRUE(a.imuFresh());
  EXPECT_NEAR(a.imuReading().f_S.x(), -1.0 / period, 1e-9);
  ports.add(portsOf(model.body(1), true), model.body(1), moving.bodies[1], 0.0);
  ports.restart(1, model.body(1), still.bodies[1]);
  core::BodySensors& b = *ports[1].sensors;
  b.sample(model.body(1), still.bodies[1], g, 10);
  ASSERT_TRUE(b.imuFresh());
  EXPECT_NEAR(b.imuReading().f_S.x(), 0.0, 1e-12);
  EXPECT_NEAR(b.imuReading().f_S.z(), 9.81, 1e-12);  // at rest: +g up
}

}  // namespace
}  // namespace rigid_body_sim::node
