// A robot under attack: seeded random commands on every controller topic
// and joint_command, and random calls of the joint services, step and
// reset, at the two-link arm (robot_attack.test: a position controller on
// the shoulder, a trajectory controller on the elbow). The node must stay
// up, joint_states stay finite and within the joints' limits, and a refused
// request change nothing.
#include <gtest/gtest.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Float64.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "node_fixture.h"
#include "rigid_body_sim/ApplyJointEffort.h"
#include "rigid_body_sim/ClearJointForces.h"
#include "rigid_body_sim/GetJointProperties.h"
#include "rigid_body_sim/SetModelConfiguration.h"

namespace rbs_test {
namespace {

const std::vector<std::string> kJoints = {"shoulder", "elbow"};

/// What a seed makes of a value: ordinary, at or past a joint's range and
/// limits, huge, tiny, NaN and ±∞.
class Draw {
 public:
  explicit Draw(unsigned seed) : rng_(seed) {}
  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
  double value() {
    switch (pick(10)) {
      case 0:
        return std::numeric_limits<double>::quiet_NaN();
      case 1:
        return (pick(2) ? 1 : -1) * std::numeric_limits<double>::infinity();
      case 2:
        return (pick(2) ? 1 : -1) * 1e300;
      case 3:
        return (pick(2) ? 1 : -1) * 2.5;  // at the range's ends
      case 4:
        return (pick(2) ? 1 : -1) * 2.6;  // past them
      case 5:
        return 5e-324;
      default:
        return std::uniform_real_distribution<double>(-3.0, 3.0)(rng_);
    }
  }
  std::vector<double> values(std::size_t max) {
    std::vector<double> v(pick(max + 1));
    for (double& x : v) x = value();
    return v;
  }
  std::string joint() {
    static const std::vector<std::string> names = {"shoulder", "elbow", "arm2/elbow", "", "wrist", "arm2/", "\"\\"};
    return names[pick(names.size())];
  }
  std::vector<std::string> joints() {
    std::vector<std::string> v(pick(4));
    for (std::string& j : v) j = joint();
    return v;
  }

 private:
  std::mt19937_64 rng_;
};

/// A joint's position and rate, bit for bit.
std::vector<double> jointBits(const rigid_body_sim::GetJointProperties& p) {
  std::vector<double> v = p.response.position;
  v.insert(v.end(), p.response.rate.begin(), p.response.rate.end());
  return v;
}

class RobotAttack : public Node {
 protected:
  void SetUp() override {
    Node::SetUp();
    shoulder_ = nh_.advertise<std_msgs::Float64>("/shoulder_position_controller/command", 100);
    elbow_ = nh_.advertise<trajectory_msgs::JointTrajectory>("/elbow_trajectory_controller/command", 100);
    joint_command_ = nh_.advertise<sensor_msgs::JointState>("/joint_command", 100);
    joints_ = nh_.subscribe<sensor_msgs::JointState>(
        "/joint_states", 1000, [this](const sensor_msgs::JointState::ConstPtr& m) {
          ++received_;
          for (std::size_t k = 0; k < m->position.size(); ++k) {
            if (!std::isfinite(m->position[k]) || !std::isfinite(m->velocity[k]) || !std::isfinite(m->effort[k]) ||
                std::abs(m->position[k]) > 2.5 + 0.05) {
              ++bad_;
            }
          }
        });
    ASSERT_TRUE(trigger("pause"));
    // Paused, joint_states comes after each step call: one to see it arrive.
    ASSERT_TRUE(spinUntil([&] { return step(1).success && spinUntil([&] { return received_ > 0; }, 0.5); }, 30.0));
  }
  /// Both joints' positions and rates.
  std::vector<double> joints() {
    std::vector<double> out;
    for (const std::string& j : kJoints) {
      rigid_body_sim::GetJointProperties p;
      p.request.joint_name = j;
      p = call("get_joint_properties", p);
      EXPECT_TRUE(p.response.success) << p.response.status_message;
      const std::vector<double> bits = jointBits(p);
      out.insert(out.end(), bits.begin(), bits.end());
    }
    return out;
  }
  /// Calls service `name` with `srv`: whether it succeeded; `what` its answer.
  template <class Srv>
  bool ask(const std::string& name, Srv& srv, std::string& what) {
    srv = call(name, srv);
    what = name + ": " + srv.response.status_message;
    return srv.response.success;
  }
  ros::Publisher shoulder_, elbow_, joint_command_;
  ros::Subscriber joints_;
  int received_ = 0, bad_ = 0;
};

TEST_F(RobotAttack, SeededRandomJointCommandsAndCallsNeverBreakIt) {
  Draw r(34);
  int accepted = 0, refused = 0;
  for (int n = 0; n < 1200; ++n) {
    const std::vector<double> before = joints();
    bool ok = true;
    std::string what;
    switch (r.pick(9)) {
      case 0: {
        std_msgs::Float64 m;
        m.data = r.value();
        shoulder_.publish(m);
        ros::spinOnce();
        continue;  // a topic has no answer; its effect shows in the steps
      }
      case 1: {
        trajectory_msgs::JointTrajectory t;
        t.joint_names = r.pick(4) == 0 ? r.joints() : std::vector<std::string>{"elbow"};
        if (r.pick(3) == 0) t.header.stamp = ros::Time(static_cast<double>(r.pick(1000)) * 0.01);
        for (std::size_t k = r.pick(4); k > 0; --k) {
          trajectory_msgs::JointTrajectoryPoint p;
          p.positions = r.pick(4) == 0 ? r.values(2) : std::vector<double>{r.value()};
          if (r.pick(2) == 0) p.velocities = r.values(2);
          if (r.pick(3) == 0) p.accelerations = r.values(2);
          p.time_from_start = ros::Duration(0.05 * static_cast<double>(r.pick(40)));
          t.points.push_back(p);
        }
        elbow_.publish(t);
        ros::spinOnce();
        continue;
      }
      case 2: {
        sensor_msgs::JointState m;
        m.name = r.joints();
        m.position = r.values(3);
        m.velocity = r.values(3);
        m.effort = r.values(3);
        joint_command_.publish(m);
        ros::spinOnce();
        continue;
      }
      case 3: {
        rigid_body_sim::SetModelConfiguration s;
        s.request.model_name = r.pick(5) == 0 ? "nobody" : "";
        s.request.joint_names = r.joints();
        s.request.joint_positions = r.values(3);
        if (r.pick(2) == 0) s.request.joint_velocities = r.values(3);
        ok = ask("set_model_configuration", s, what);
        break;
      }
      case 4: {
        rigid_body_sim::ApplyJointEffort a;
        a.request.joint_name = r.joint();
        a.request.effort = r.value() * (r.pick(2) == 0 ? 10.0 : 1.0);
        a.request.duration = ros::Duration(r.pick(3) == 0 ? -1.0 : 0.01 * static_cast<double>(r.pick(50)));
        if (r.pick(4) == 0) a.request.start_time = ros::Time(static_cast<double>(r.pick(100)));
        ok = ask("apply_joint_effort", a, what);
        break;
      }
      case 5: {
        rigid_body_sim::ClearJointForces c;
        c.request.joint_name = r.joint();
        ok = ask("clear_joint_forces", c, what);
        break;
      }
      case 6: {
        rigid_body_sim::GetJointProperties g;
        g.request.joint_name = r.joint();
        g = call("get_joint_properties", g);
        for (const double x : jointBits(g)) EXPECT_TRUE(std::isfinite(x)) << n;
        continue;
      }
      case 7: {
        EXPECT_TRUE(step(1 + static_cast<int>(r.pick(60))).success) << n;
        continue;
      }
      default: {
        EXPECT_TRUE(trigger(r.pick(10) == 0 ? "reset" : "pause")) << n;
        continue;
      }
    }
    if (ok) {
      ++accepted;
    } else {
      ++refused;
      const std::vector<double> after = joints();
      ASSERT_EQ(before.size(), after.size());
      ASSERT_EQ(std::memcmp(before.data(), after.data(), before.size() * sizeof(double)), 0)
          << "request " << n << " was refused yet moved the arm: " << what;
    }
  }
  std::printf("robot storm: %d requests accepted, %d refused, %d joint_states received\n", accepted, refused,
              received_);
  EXPECT_GT(accepted, 30);
  EXPECT_GT(refused, 100);
  ASSERT_TRUE(step(500).success);
  ASSERT_TRUE(spinUntil([&] { return received_ > 50; }, 10.0));
  ros::spinOnce();
  EXPECT_EQ(bad_, 0) << "joint_states carried a non-finite value or a joint past its range";
  for (const double x : joints()) EXPECT_TRUE(std::isfinite(x));
}

}  // namespace
}  // namespace rbs_test
