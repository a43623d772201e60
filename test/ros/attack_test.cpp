// The node under attack (issue 13): accepted requests that once made the
// state NaN or crashed the node, then seeded random requests to every
// service and the ~wrench topics. The node must stay up, /odom and tf stay
// finite, and a refused request change nothing.
#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>
#include <tf2_msgs/TFMessage.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/ClearWrenches.h"
#include "rigid_body_sim/DeleteBody.h"
#include "rigid_body_sim/SetState.h"
#include "rigid_body_sim/SpawnBody.h"

namespace rbs_test {
namespace {

const std::vector<std::string> kBodies = {"box", "ball", "bunny", "bar"};

bool finite(const geometry_msgs::Pose& p) {
  return std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) &&
         std::isfinite(p.orientation.x) && std::isfinite(p.orientation.y) && std::isfinite(p.orientation.z) &&
         std::isfinite(p.orientation.w);
}

bool finite(const geometry_msgs::Twist& t) {
  return std::isfinite(t.linear.x) && std::isfinite(t.linear.y) && std::isfinite(t.linear.z) &&
         std::isfinite(t.angular.x) && std::isfinite(t.angular.y) && std::isfinite(t.angular.z);
}

/// Bit-for-bit equality of two states' poses and twists.
bool same(const BodyState& a, const BodyState& b) {
  const auto bits = [](const BodyState& s) {
    const double v[] = {s.pose.position.x,    s.pose.position.y,    s.pose.position.z,    s.pose.orientation.x,
                        s.pose.orientation.y, s.pose.orientation.z, s.pose.orientation.w, s.twist.linear.x,
                        s.twist.linear.y,     s.twist.linear.z,     s.twist.angular.x,    s.twist.angular.y,
                        s.twist.angular.z};
    return std::vector<double>(std::begin(v), std::end(v));
  };
  const auto x = bits(a), y = bits(b);
  return std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0 && a.stamp == b.stamp;
}

class Attack : public Node {
 protected:
  void SetUp() override {
    Node::SetUp();
    for (const std::string& name : kBodies) {
      odom_subs_.push_back(
          nh_.subscribe<nav_msgs::Odometry>("/" + name + "/odom", 100, [this](const nav_msgs::Odometry::ConstPtr& m) {
            ++odom_count_;
            if (!finite(m->pose.pose) || !finite(m->twist.twist)) ++non_finite_;
          }));
    }
    tf_sub_ = nh_.subscribe<tf2_msgs::TFMessage>("/tf", 100, [this](const tf2_msgs::TFMessage::ConstPtr& m) {
      for (const auto& t : m->transforms) {
        const auto& r = t.transform.rotation;
        const auto& p = t.transform.translation;
        if (!std::isfinite(p.x + p.y + p.z + r.x + r.y + r.z + r.w)) ++non_finite_;
      }
    });
    ASSERT_TRUE(trigger("pause"));
  }

  BodyState of(const std::string& body) {
    rigid_body_sim::GetState s;
    s.request.body = body;
    s = call("get_state", s);
    EXPECT_TRUE(s.response.success) << s.response.message;
    return s.response.state;
  }

  std::vector<BodyState> all() {
    std::vector<BodyState> states;
    for (const std::string& name : kBodies) states.push_back(of(name));
    return states;
  }

  void expectAllFiniteAndWithinLimits() {
    for (const BodyState& s : all()) {
      EXPECT_TRUE(finite(s.pose) && finite(s.twist)) << s.body;
      // The root link's speed is the centre of mass's plus ω × r: a little above 500 m/s at most.
      const double v = std::hypot(s.twist.linear.x, s.twist.linear.y, s.twist.linear.z);
      const double w = std::hypot(s.twist.angular.x, s.twist.angular.y, s.twist.angular.z);
      EXPECT_LE(w, 100.0 * (1 + 1e-9)) << s.body;
      EXPECT_LE(v, 500.0 + 100.0 * 1.0) << s.body;  // every link lies within 1 m of its centre of mass
    }
  }

  /// Counts request n's answer; a refused request must have changed no body
  /// (`before`: every body's state before it).
  void judge(int n, bool ok, const std::vector<BodyState>& before, const std::string& what) {
    ros::spinOnce();
    if (ok) {
      ++accepted_;
      return;
    }
    ++refused_;
    const std::vector<BodyState> after = all();
    for (std::size_t i = 0; i < after.size(); ++i) {
      ASSERT_TRUE(same(before[i], after[i]))
          << "request " << n << " was refused yet changed '" << kBodies[i] << "': " << what;
    }
  }

  std::vector<ros::Subscriber> odom_subs_;
  ros::Subscriber tf_sub_;
  int accepted_ = 0, refused_ = 0;
  int odom_count_ = 0;
  int non_finite_ = 0;
};

TEST_F(Attack, TheTorqueThatSegfaultedTheNodeIsHeldToTheLimits) {
  // world.launch, paused: the bunny moved off the others, a torque of
  // 990,000 N·m left on, ten steps: NaN, then SIGSEGV in its distance grid.
  rigid_body_sim::SetState set;
  set.request.body = "bunny";
  set.request.state = of("bunny");
  set.request.state.pose.position.x = 10.0;
  set.request.state.pose.position.y = 10.0;
  set.request.state.pose.position.z = 0.5;
  ASSERT_TRUE(call("set_state", set).response.success);
  rigid_body_sim::ApplyWrench w;
  w.request.body = "bunny";
  w.request.frame = "world";
  w.request.torque = vec(990000.0, 9900.0, 0.0);
  w.request.duration = ros::Duration(-1.0);
  ASSERT_TRUE(call("apply_wrench", w).response.success);
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(step(10).success);
  expectAllFiniteAndWithinLimits();
  const BodyState bunny = of("bunny");
  // Held to 100 rad/s where the torque acts; the free rotation of the step then moves |ω| by rounding-size amounts
  // (Euler keeps energy and |L|, not |ω|).
  EXPECT_NEAR(std::hypot(bunny.twist.angular.x, bunny.twist.angular.y, bunny.twist.angular.z), 100.0, 1e-3);
  rigid_body_sim::ClearWrenches clear;
  ASSERT_TRUE(call("clear_wrenches", clear).response.success);
}

TEST_F(Attack, AForceThroughAHugeLeverStaysFinite) {
  // 999,999 N at 999,999 m: 1e12 N·m, accepted, NaN within 20 steps before.
  rigid_body_sim::ApplyWrench w;
  w.request.body = "box";
  w.request.frame = "world";
  w.request.force = vec(0.0, 999999.0, 0.0);
  w.request.point.x = 999999.0;
  w.request.duration = ros::Duration(0.5);
  ASSERT_TRUE(call("apply_wrench", w).response.success);
  for (int k = 0; k < 10; ++k) ASSERT_TRUE(step(100).success);
  expectAllFiniteAndWithinLimits();
}

/// A random number of the kinds an attacker tries: ordinary, near and just
/// beyond the request limits, huge, tiny, NaN and ±∞.
class Values {
 public:
  explicit Values(unsigned seed) : rng_(seed) {}

  double any(double limit) {
    switch (pick(9)) {
      case 0:
        return std::numeric_limits<double>::quiet_NaN();
      case 1:
        return (pick(2) ? 1 : -1) * std::numeric_limits<double>::infinity();
      case 2:
        return (pick(2) ? 1 : -1) * limit * 0.999;  // near the limit, accepted
      case 3:
        return (pick(2) ? 1 : -1) * limit * 1.001;  // just beyond, refused
      case 4:
        return (pick(2) ? 1 : -1) * 1e300;
      case 5:
        return 5e-324;
      default:
        return std::uniform_real_distribution<double>(-10.0, 10.0)(rng_);
    }
  }
  geometry_msgs::Vector3 vector(double limit) { return vec(any(limit), any(limit), any(limit)); }
  std::string body() {
    static const std::vector<std::string> names = {"box", "ball",   "bunny",         "bar",
                                                   "",    "nobody", "box/base_link", "\"\\"};
    return names[pick(names.size())];
  }
  std::string frame() {
    static const std::vector<std::string> frames = {"world", "", "base_link", "ball/ball", "box/base_link", "nowhere"};
    return frames[pick(frames.size())];
  }
  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }

 private:
  std::mt19937_64 rng_;
};

TEST_F(Attack, SeededRandomRequestsNeverBreakIt) {
  Values r(13);
  std::vector<ros::Publisher> wrench_pubs;
  for (const std::string& name : kBodies) {
    wrench_pubs.push_back(nh_.advertise<geometry_msgs::WrenchStamped>("/sim_node/" + name + "/wrench", 10));
  }
  for (int n = 0; n < 1500; ++n) {
    const std::vector<BodyState> before = all();
    bool ok = true;
    std::string what;
    switch (r.pick(8)) {
      case 0: {
        rigid_body_sim::ApplyWrench w;
        w.request.body = r.body();
        w.request.frame = r.frame();
        w.request.force = r.vector(1e6);
        w.request.torque = r.vector(1e6);
        w.request.point.x = r.any(1e6);
        w.request.duration = ros::Duration(r.pick(3) == 0 ? -1.0 : 0.001 * static_cast<double>(r.pick(100)));
        w = call("apply_wrench", w);
        ok = w.response.success;
        what = "apply_wrench: " + w.response.message;
        break;
      }
      case 1: {
        rigid_body_sim::ApplyImpulse i;
        i.request.body = r.body();
        i.request.frame = r.frame();
        i.request.linear = r.vector(1e5);
        i.request.angular = r.vector(1e5);
        i.request.point.y = r.any(1e6);
        i = call("apply_impulse", i);
        ok = i.response.success;
        what = "apply_impulse: " + i.response.message;
        break;
      }
      case 2: {
        rigid_body_sim::SetState s;
        s.request.body = r.body();
        s.request.state.pose.position.x = r.any(1e6);
        s.request.state.pose.position.z = 1.0 + std::abs(r.any(3.0));
        s.request.state.pose.orientation.w = r.pick(5) == 0 ? r.any(1.0) : 1.0;
        s.request.state.twist.linear = r.vector(500.0);
        s.request.state.twist.angular = r.vector(100.0);
        s.request.state.twist_frame = r.frame();
        s = call("set_state", s);
        ok = s.response.success;
        what = "set_state: " + s.response.message;
        break;
      }
      case 3: {
        rigid_body_sim::ClearWrenches c;
        c.request.body = r.body();
        c = call("clear_wrenches", c);
        ok = c.response.success;
        what = "clear_wrenches: " + c.response.message;
        break;
      }
      case 4: {
        const int steps =
            static_cast<int>(r.pick(4)) == 0 ? -static_cast<int>(r.pick(10)) : static_cast<int>(r.pick(50));
        rigid_body_sim::Step s;
        s.request.steps = steps;
        s = call("step", s);
        ok = s.response.success;
        what = "step: " + s.response.message;
        for (const BodyState& b : s.response.states) EXPECT_TRUE(finite(b.pose) && finite(b.twist)) << n;
        break;
      }
      case 5: {
        geometry_msgs::WrenchStamped m;
        m.header.frame_id = r.frame();
        m.wrench.force = r.vector(1e6);
        m.wrench.torque = r.vector(1e6);
        wrench_pubs[r.pick(wrench_pubs.size())].publish(m);
        ros::spinOnce();
        continue;  // a topic has no answer; its effect shows in the steps
      }
      case 6: {
        rigid_body_sim::GetState g;
        g.request.body = r.body();
        g.request.frame = r.frame();
        g = call("get_state", g);
        if (g.response.success) EXPECT_TRUE(finite(g.response.state.pose) && finite(g.response.state.twist)) << n;
        continue;
      }
      default: {
        if (r.pick(20) == 0) {
          EXPECT_TRUE(trigger("reset")) << n;
        } else {
          EXPECT_TRUE(trigger("pause")) << n;  // already paused: nothing changes
        }
        continue;
      }
    }
    judge(n, ok, before, what);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(refused_, 200);
  EXPECT_GT(accepted_, 200);
  ASSERT_TRUE(step(200).success);
  expectAllFiniteAndWithinLimits();
  ros::spinOnce();
  EXPECT_GT(odom_count_, 0);
  EXPECT_EQ(non_finite_, 0);
}

TEST_F(Attack, SeededRandomSpawnsAndDeletesNeverBreakIt) {
  // Spawns of bodies s0..s4 with random names, URDFs, poses and twists, and
  // deletes of them: the world's four bodies are never named for deletion,
  // so a refused spawn or delete must leave them bit for bit as they were.
  Values r(14);
  const std::vector<std::string> names = {"s0", "s1", "s2", "s3", "s4", "box", "", "two words", "s/x", "\"\\"};
  const std::vector<std::string> files = {"package://rigid_body_sim/urdf/ball.urdf",
                                          "package://rigid_body_sim/urdf/box.urdf",
                                          "package://rigid_body_sim/urdf/x",
                                          "relative.urdf",
                                          "/dev/null",
                                          ""};
  for (int n = 0; n < 300; ++n) {
    const std::vector<BodyState> before = all();
    bool ok = true;
    std::string what;
    const std::size_t kind = r.pick(5);
    if (kind < 3) {
      rigid_body_sim::SpawnBody s;
      s.request.name = names[r.pick(3) == 0 ? r.pick(names.size()) : r.pick(5)];
      s.request.urdf_file = files[r.pick(3) == 0 ? r.pick(files.size()) : r.pick(2)];
      // Issue 31's cases too: URDFs urdfdom half-read or leaked, and devices
      // that once ended the node or overflowed a counter.
      const std::vector<std::string> xmls = {
          "<robot name='r'><link name='l'/></robot>",
          "<robot name='r'><link name='l'><inertial><mass value='1kg'/><inertia ixx='1' iyy='1' izz='1' ixy='0' "
          "ixz='0' iyz='0'/></inertial></link></robot>",
          "<robot name='c'><link name='a'/><link name='b'/><joint name='j1' type='fixed'><parent link='a'/><child "
          "link='b'/></joint><joint name='j2' type='fixed'><parent link='b'/><child link='a'/></joint></robot>"};
      if (r.pick(6) == 0) s.request.urdf_xml = xmls[r.pick(xmls.size())];
      const std::vector<std::string> imus = {"{link: nope}", "{rate: 1e-300}", "{rate: 100, rate: 200}", "{rate: 100}"};
      if (r.pick(6) == 0) s.request.imu = imus[r.pick(imus.size())];
      s.request.pose.position.x = r.pick(3) == 0 ? r.any(1e6) : 3.0 + 0.5 * static_cast<double>(n % 7);
      s.request.pose.position.z = 1.0 + std::abs(r.any(3.0));
      s.request.pose.orientation.w = r.pick(5) == 0 ? r.any(1.0) : 1.0;
      s.request.twist.linear = r.pick(3) == 0 ? r.vector(500.0) : vec(0, 0, 0);
      s.request.frame = r.pick(4) == 0 ? r.frame() : "";
      s.request.own_friction = r.pick(3) == 0;
      s.request.friction = r.any(10.0);
      s = call("spawn_body", s);
      ok = s.response.success;
      what = "spawn_body: " + s.response.message;
    } else if (kind == 3) {
      rigid_body_sim::DeleteBody d;
      d.request.name = std::vector<std::string>{"s0", "s1", "s2", "s3", "s4", "nobody", ""}[r.pick(7)];
      d = call("delete_body", d);
      ok = d.response.success;
      what = "delete_body: " + d.response.message;
    } else {
      ASSERT_TRUE(step(1 + static_cast<int>(r.pick(50))).success);
      continue;
    }
    judge(n, ok, before, what);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(refused_, 50);
  EXPECT_GT(accepted_, 20);
  ASSERT_TRUE(step(200).success);
  expectAllFiniteAndWithinLimits();
  for (const std::string name : {"s0", "s1", "s2", "s3", "s4"}) {
    rigid_body_sim::GetState g;
    g.request.body = name;
    g = call("get_state", g);
    if (g.response.success) EXPECT_TRUE(finite(g.response.state.pose) && finite(g.response.state.twist)) << name;
  }
  ros::spinOnce();
  EXPECT_EQ(non_finite_, 0);
}

}  // namespace
}  // namespace rbs_test
