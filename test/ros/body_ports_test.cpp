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

/// Ports as openPorts makes them for a body of a world, without topics.
BodyPorts portsOf(const core::BodyModel& body, bool with_imu = false) {
  BodyPorts p;
  p.prefix = body.name + "/";
  p.frame = p.prefix + body.link;
  if (with_imu) {
    core::ImuSettings imu;
    p.imu = std::make_unique<core::Imu>(imu);
    p.imu_frame = p.prefix + "imu_link";
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
  ports.add(portsOf(model.body(3)), model.body(3), s.bodies[3], 2.5);
  EXPECT_EQ(ports.colours(), (std::vector<std::size_t>{0, 2, 3}));
  EXPECT_EQ(ports.directory().byName("d"), 2);
  EXPECT_EQ(ports[2].last_odom, 2.5);
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
  const double period = 0.01;
  const Vec3 g = model.gravity();
  const core::ImuReading jumped = ports[0].imu->sample(model.body(0), still.bodies[0], g, period);
  EXPECT_NEAR(jumped.f_S.x(), -1.0 / period, 1e-9);
  ports.add(portsOf(model.body(1), true), model.body(1), moving.bodies[1], 0.0);
  ports.restart(1, model.body(1), still.bodies[1]);
  const core::ImuReading restarted = ports[1].imu->sample(model.body(1), still.bodies[1], g, period);
  EXPECT_NEAR(restarted.f_S.x(), 0.0, 1e-12);
  EXPECT_NEAR(restarted.f_S.z(), 9.81, 1e-12);  // at rest: +g up
}

}  // namespace
}  // namespace rigid_body_sim::node
