// Live tuning through ~physics (issue 14), as rqt_reconfigure or dynparam
// call it: what it shows is what is in force (the config's values, not the
// cfg's defaults), a change applies from the next step (a free fall under the
// new gravity, exactly), a refused value leaves the old one in force and in
// view, and paused and publish_rate act as their own services and parameters.
#include <dynamic_reconfigure/Config.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <nav_msgs/Odometry.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/SetState.h"

namespace rbs_test {
namespace {

class Reconfigure : public Node {
 protected:
  /// Sets the named values through ~physics/set_parameters; returns the
  /// configuration in force afterwards, by name.
  std::map<std::string, double> set(const std::map<std::string, double>& doubles,
                                    const std::map<std::string, bool>& bools = {}) {
    dynamic_reconfigure::Reconfigure srv;
    for (const auto& [name, value] : doubles) {
      dynamic_reconfigure::DoubleParameter p;
      p.name = name;
      p.value = value;
      srv.request.config.doubles.push_back(p);
    }
    for (const auto& [name, value] : bools) {
      dynamic_reconfigure::BoolParameter p;
      p.name = name;
      p.value = value;
      srv.request.config.bools.push_back(p);
    }
    EXPECT_TRUE(ros::service::call("/sim_node/physics/set_parameters", srv));
    return values(srv.response.config);
  }
  static std::map<std::string, double> values(const dynamic_reconfigure::Config& c) {
    std::map<std::string, double> out;
    for (const auto& d : c.doubles) out[d.name] = d.value;
    for (const auto& b : c.bools) out[b.name] = b.value ? 1.0 : 0.0;
    return out;
  }
  /// The body put at rest 100 m up, then `steps` steps: its vertical speed.
  double fallFor(int steps) {
    rigid_body_sim::SetState put;
    put.request.state.pose.position.z = 100.0;
    put.request.state.pose.orientation.w = 1.0;
    put = call("set_state", put);
    EXPECT_TRUE(put.response.success) << put.response.message;
    EXPECT_TRUE(step(steps).success);
    return state().twist.linear.z;
  }
};

TEST_F(Reconfigure, ShowsWhatIsInForceAndChangesItBetweenSteps) {
  ASSERT_TRUE(ros::service::waitForService("/sim_node/physics/set_parameters", 30000));
  // reconfigure.test's config: gravity z -5, friction 0.3; the cfg says -9.81 and 0.5.
  dynamic_reconfigure::Config shown;
  bool got = false;
  const ros::Subscriber sub = nh_.subscribe<dynamic_reconfigure::Config>(
      "/sim_node/physics/parameter_updates", 10, [&](const dynamic_reconfigure::Config::ConstPtr& m) {
        shown = *m;
        got = true;
      });
  // What is in force is shown: the server's first update may still carry the
  // cfg's defaults to a subscriber that connects early (seen on a busy machine).
  ASSERT_TRUE(spinUntil([&] { return got && values(shown).at("gravity_z") == -5.0; }, 10.0))
      << "gravity_z shown: " << (got ? values(shown).at("gravity_z") : NAN);
  EXPECT_EQ(values(shown).at("gravity_z"), -5.0);
  EXPECT_EQ(values(shown).at("contact_friction"), 0.3);
  // paused through ~physics is the pause service's pause: step works.
  EXPECT_EQ(set({}, {{"paused", true}}).at("paused"), 1.0);
  EXPECT_NEAR(fallFor(1000), -5.0, 1e-9);  // 1000 steps of 1 ms: v = g t
  std::map<std::string, double> now = set({{"gravity_z", -2.0}});
  EXPECT_EQ(now.at("gravity_z"), -2.0);
  EXPECT_NEAR(fallFor(1000), -2.0, 1e-9);
  // |g| > 1000 m/s^2: refused by the model's own check; the old gravity stays, in force and in view.
  now = set({{"gravity_x", 1000.0}, {"gravity_y", 1000.0}});
  EXPECT_EQ(now.at("gravity_x"), 0.0);
  EXPECT_EQ(now.at("gravity_y"), 0.0);
  EXPECT_EQ(now.at("gravity_z"), -2.0);
  EXPECT_NEAR(fallFor(1000), -2.0, 1e-9);
  // Far outside the model's range: refused too, not clamped to the range's
  // edge by dynamic_reconfigure first (-5000 became -1000 and was accepted).
  now = set({{"gravity_z", -5000.0}, {"contact_friction", 50.0}});
  EXPECT_EQ(now.at("gravity_z"), -2.0);
  EXPECT_EQ(now.at("contact_friction"), 0.3);
  EXPECT_NEAR(fallFor(1000), -2.0, 1e-9);
  // A real-time factor that would freeze the simulation: refused, 1 stays.
  EXPECT_EQ(set({{"realtime_factor", 1e-300}}).at("realtime_factor"), 1.0);
  // The pause services and ~physics agree.
  ASSERT_TRUE(trigger("unpause"));
  got = false;
  ASSERT_TRUE(spinUntil([&] { return got && values(shown).at("paused") == 0.0; }, 10.0));
  // publish_rate: odometry 20 ms of sim time apart at 50 Hz.
  EXPECT_EQ(set({{"publish_rate", 50.0}}).at("publish_rate"), 50.0);
  std::vector<ros::Time> stamps;
  const ros::Subscriber odom = nh_.subscribe<nav_msgs::Odometry>(
      "/odom", 100, [&](const nav_msgs::Odometry::ConstPtr& m) { stamps.push_back(m->header.stamp); });
  ASSERT_TRUE(spinUntil([&] { return stamps.size() > 10; }, 10.0));
  for (std::size_t k = 2; k < stamps.size(); ++k) EXPECT_NEAR((stamps[k] - stamps[k - 1]).toSec(), 0.02, 1e-9) << k;
}

}  // namespace
}  // namespace rbs_test
