// Live tuning (no master): a ~physics request retunes the model and wakes
// every body; the model's settings go all or none, the one refused naming
// its key and every one put back to the value in force; the node's each on
// its own, checked as at start.
#include "rigid_body_sim/ros/live_tuning.h"

#include <gtest/gtest.h>

#include "../test_util.h"

namespace rigid_body_sim::node {
namespace {

using test::Vec3;

core::Simulation restingBox() {
  core::Model model(test::spec(test::boxBody(Vec3(0.1, 0.1, 0.1)), 1e-3, Vec3(0, 0, -9.81)));
  core::State state = core::restState(model);
  state.bodies[0].asleep = true;
  return core::Simulation(std::move(model), std::move(state));
}

bool mentions(const std::vector<std::string>& messages, const std::string& part) {
  for (const std::string& m : messages) {
    if (m.find(part) != std::string::npos) return true;
  }
  return false;
}

TEST(LiveTuning, ARequestRetunesTheModelAndWakesEveryBody) {
  core::Simulation sim = restingBox();
  NodeSettings settings;
  PhysicsConfig config = physicsNow(sim.model(), settings, false);
  config.gravity_z = -1.62;
  config.damping_angular = 0.5;
  config.publish_rate = 50.0;
  const TuningResult r = applyTuning(config, sim, settings, false);
  EXPECT_TRUE(r.refused.empty());
  EXPECT_TRUE(r.model);
  EXPECT_EQ(sim.model().gravity(), Vec3(0, 0, -1.62));
  EXPECT_EQ(sim.model().tuning().damping.angular, 0.5);
  EXPECT_FALSE(sim.state.bodies[0].asleep);
  EXPECT_TRUE(r.publish_rate);
  EXPECT_EQ(settings.publish_rate, 50.0);
  EXPECT_FALSE(r.realtime_factor);  // unchanged: the pacing goes on
  // What ~physics shows now is what holds.
  const PhysicsConfig shown = physicsNow(sim.model(), settings, true);
  EXPECT_EQ(shown.gravity_z, -1.62);
  EXPECT_TRUE(shown.paused);
}

TEST(LiveTuning, TheModelsSettingsGoAllOrNoneAndARefusedOneIsPutBack) {
  core::Simulation sim = restingBox();
  NodeSettings settings;
  PhysicsConfig config = physicsNow(sim.model(), settings, false);
  config.gravity_z = -5.0;
  config.damping_linear = 1e7;  // above the decay rates' bound, 1e6 1/s
  const TuningResult r = applyTuning(config, sim, settings, false);
  EXPECT_FALSE(r.model);
  ASSERT_EQ(r.refused.size(), 1u);
  EXPECT_TRUE(mentions(r.refused, "damping.linear")) << r.refused[0];
  EXPECT_EQ(sim.model().gravity(), Vec3(0, 0, -9.81));  // none: gravity too stays
  EXPECT_EQ(config.gravity_z, -9.81);
  EXPECT_EQ(config.damping_linear, 0.0);
  EXPECT_TRUE(sim.state.bodies[0].asleep);  // nothing changed, nothing woke
}

TEST(LiveTuning, TheNodesSettingsAreCheckedEachOnItsOwn) {
  core::Simulation sim = restingBox();
  NodeSettings settings;
  PhysicsConfig config = physicsNow(sim.model(), settings, false);
  config.realtime_factor = 5000.0;  // above ~realtime_factor's 1000
  config.publish_rate = 20.0;
  const TuningResult r = applyTuning(config, sim, settings, false);
  EXPECT_TRUE(mentions(r.refused, "~realtime_factor"));
  EXPECT_FALSE(r.realtime_factor);
  EXPECT_EQ(config.realtime_factor, 1.0);
  EXPECT_EQ(settings.realtime_factor, 1.0);
  EXPECT_EQ(settings.publish_rate, 20.0);  // taken all the same

  config.realtime_factor = 0.0;  // as fast as possible
  config.publish_rate = 0.0;     // below 0.01 Hz
  const TuningResult again = applyTuning(config, sim, settings, false);
  EXPECT_TRUE(again.realtime_factor);
  EXPECT_EQ(settings.realtime_factor, 0.0);
  EXPECT_TRUE(mentions(again.refused, "~publish_rate"));
  EXPECT_EQ(config.publish_rate, 20.0);
}

}  // namespace
}  // namespace rigid_body_sim::node
