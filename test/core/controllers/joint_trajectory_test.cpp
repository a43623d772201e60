// Joint trajectories through waypoints (docs/physics.md §11.11): each
// piece against its closed form (linear, cubic Hermite, quintic from rest
// to rest), the lowest common order of its ends, the switch from one
// trajectory to the next without a jump, past points dropped, a
// continuous joint's whole turns, every refusal, and a message's joint
// order put in the controller's.
#include "rigid_body_sim/core/controllers/joint_trajectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rigid_body_sim::core {
namespace {

TrajectoryPoint at(double time, std::vector<double> q, std::vector<double> v = {}, std::vector<double> a = {}) {
  return {time, std::move(q), std::move(v), std::move(a)};
}

TEST(JointTrajectory, HoldsWhereItStartsAtAnyTime) {
  const JointTrajectory hold({0.3, -1.2});
  for (const double t : {-5.0, 0.0, 7.5}) {
    EXPECT_EQ(hold.sample(t, 0).position, 0.3);
    EXPECT_EQ(hold.sample(t, 1).position, -1.2);
    EXPECT_EQ(hold.sample(t, 1).velocity, 0.0);
  }
}

// Positions alone: straight lines between the points, at rest after the last.
TEST(JointTrajectory, PositionsAloneAreLinear) {
  JointTrajectory tr({0.0});
  ASSERT_EQ(tr.follow(0.0, 0.0, {at(1.0, {1.0}), at(3.0, {-1.0})}, {0}), 0);
  EXPECT_NEAR(tr.sample(0.5, 0).position, 0.5, 1e-15);
  EXPECT_NEAR(tr.sample(0.5, 0).velocity, 1.0, 1e-15);
  EXPECT_NEAR(tr.sample(2.0, 0).position, 0.0, 1e-15);
  EXPECT_NEAR(tr.sample(2.0, 0).velocity, -1.0, 1e-15);
  EXPECT_EQ(tr.sample(3.0, 0).position, -1.0);
  EXPECT_EQ(tr.sample(9.0, 0).position, -1.0);
  EXPECT_EQ(tr.sample(9.0, 0).velocity, 0.0);
  EXPECT_EQ(tr.endTime(), 3.0);
}

// Positions and velocities: the cubic Hermite piece, its ends met and its
// middle at (q0 + q1)/2 + T (v0 − v1)/8.
TEST(JointTrajectory, VelocitiesMakeCubicPieces) {
  JointTrajectory tr({0.0});
  const double T = 2.0;
  ASSERT_EQ(tr.follow(0.0, 0.0, {at(1.0, {0.5}, {0.4}), at(1.0 + T, {2.0}, {-0.6})}, {0}), 0);
  const Setpoint s0 = tr.sample(1.0, 0), s1 = tr.sample(1.0 + T, 0), mid = tr.sample(1.0 + T / 2, 0);
  EXPECT_NEAR(s0.position, 0.5, 1e-14);
  EXPECT_NEAR(s0.velocity, 0.4, 1e-14);
  EXPECT_NEAR(s1.position, 2.0, 1e-14);
  EXPECT_NEAR(s1.velocity, -0.6, 1e-14);
  EXPECT_NEAR(mid.position, (0.5 + 2.0) / 2 + T * (0.4 + 0.6) / 8, 1e-14);
  // Its acceleration at the start: 2 (3 (q1 − q0) − (2 v0 + v1) T) / T².
  EXPECT_NEAR(s0.acceleration, 2 * (3 * (2.0 - 0.5) - (2 * 0.4 - 0.6) * T) / (T * T), 1e-14);
}

// Positions, velocities and accelerations: the quintic piece; from rest to
// rest it is the minimum-jerk curve, its middle halfway at 15/8 the mean speed.
TEST(JointTrajectory, AccelerationsMakeQuinticPieces) {
  JointTrajectory tr({1.0});
  const double T = 2.0;
  ASSERT_EQ(tr.follow(0.0, 0.0, {at(T, {3.0}, {0.0}, {0.0})}, {0}), 0);
  const Setpoint mid = tr.sample(T / 2, 0);
  EXPECT_NEAR(mid.position, 2.0, 1e-14);
  EXPECT_NEAR(mid.velocity, 15.0 / 8.0 * (3.0 - 1.0) / T, 1e-14);
  EXPECT_NEAR(mid.acceleration, 0.0, 1e-13);
  // Boundary accelerations met: a second quintic piece from (3, 0, 0) to (3.5, 0.2, −0.3).
  ASSERT_EQ(tr.follow(T, T, {at(1.0, {3.5}, {0.2}, {-0.3})}, {0}), 0);
  const Setpoint end = tr.sample(T + 1.0, 0), start = tr.sample(T, 0);
  EXPECT_NEAR(end.position, 3.5, 1e-13);
  EXPECT_NEAR(end.velocity, 0.2, 1e-13);
  EXPECT_NEAR(end.acceleration, -0.3, 1e-12);
  EXPECT_NEAR(start.position, 3.0, 1e-14);
  EXPECT_NEAR(start.acceleration, 0.0, 1e-12);
}

// A piece is of the lowest order both its ends give: velocities then
// positions alone is a straight line.
TEST(JointTrajectory, APieceTakesTheLowerOrderOfItsEnds) {
  JointTrajectory tr({0.0});
  ASSERT_EQ(tr.follow(0.0, 0.0, {at(1.0, {1.0}, {5.0}), at(2.0, {3.0})}, {0}), 0);
  EXPECT_NEAR(tr.sample(1.5, 0).position, 2.0, 1e-15);
  EXPECT_NEAR(tr.sample(1.5, 0).velocity, 2.0, 1e-15);
}

// A new trajectory mid-way takes over from where the old one is at that
// moment: no jump in position; a later start keeps the old one until then.
TEST(JointTrajectory, ANewTrajectoryTakesOverWithoutAJump) {
  JointTrajectory tr({0.0});
  ASSERT_EQ(tr.follow(0.0, 0.0, {at(2.0, {2.0})}, {0}), 0);
  const double before = tr.sample(0.8, 0).position;  // 0.8 on the old line
  ASSERT_EQ(tr.follow(0.8, 0.8, {at(1.0, {-1.0})}, {0}), 0);
  EXPECT_NEAR(tr.sample(0.8, 0).position, before, 1e-15);
  EXPECT_NEAR(tr.sample(1.3, 0).position, 0.8 + 0.5 * (-1.0 - 0.8), 1e-15);
  // Starting at 1.5 (now 1.0): the line above until 1.5, then on to 4 by 2.5.
  const double at_switch = tr.sample(1.5, 0).position;
  ASSERT_EQ(tr.follow(1.0, 1.5, {at(1.0, {4.0})}, {0}), 0);
  EXPECT_NEAR(tr.sample(1.2, 0).position, 0.8 + 0.4 * (-1.0 - 0.8), 1e-15);
  EXPECT_NEAR(tr.sample(1.5, 0).position, at_switch, 1e-15);
  EXPECT_NEAR(tr.sample(2.0, 0).position, (at_switch + 4.0) / 2, 1e-15);
  EXPECT_EQ(tr.sample(2.5, 0).position, 4.0);
}

// Points at or before now are dropped; all of them past: nothing changes.
TEST(JointTrajectory, PastPointsAreDropped) {
  JointTrajectory tr({0.0});
  EXPECT_EQ(tr.follow(5.0, 3.0, {at(1.0, {9.0}), at(2.0, {1.0}), at(4.0, {3.0})}, {0}), 2);
  EXPECT_NEAR(tr.sample(6.0, 0).position, 1.5, 1e-15);  // from 0 at 5 to 3 at 7
  const Setpoint kept = tr.sample(6.0, 0);
  EXPECT_EQ(tr.follow(20.0, 3.0, {at(1.0, {9.0})}, {0}), -1);
  EXPECT_EQ(tr.sample(6.0, 0).position, kept.position);
}

// A continuous joint goes to the nearest turn of its first point.
TEST(JointTrajectory, AContinuousJointTurnsTheShortWay) {
  const double turn = 2.0 * M_PI;
  JointTrajectory tr({3.0 * turn + 0.1, 3.0 * turn + 0.1});
  ASSERT_EQ(tr.follow(0.0, 0.0, {at(1.0, {0.2, 0.2}), at(2.0, {0.4, 0.4})}, {1, 0}), 0);
  EXPECT_NEAR(tr.sample(1.0, 0).position, 3.0 * turn + 0.2, 1e-12);
  EXPECT_NEAR(tr.sample(2.0, 0).position, 3.0 * turn + 0.4, 1e-12);
  EXPECT_EQ(tr.sample(1.0, 1).position, 0.2);  // a revolute joint goes where it is told
}

TEST(JointTrajectory, CheckNamesTheProblem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const struct {
    std::vector<TrajectoryPoint> points;
    std::string expected;
  } cases[] = {
      {{at(1.0, {0.0, 0.0}), at(1.0, {1.0, 1.0})}, "points[1].time_from_start must be after the point before's"},
      {{at(-1.0, {0.0, 0.0})}, "points[0].time_from_start must be finite and >= 0"},
      {{at(nan, {0.0, 0.0})}, "points[0].time_from_start must be finite"},
      {{at(1.0, {0.0})}, "points[0].positions has 1 values for 2 joints"},
      {{at(1.0, {0.0, 0.0}, {1.0})}, "points[0].velocities has 1 values for 2 joints"},
      {{at(1.0, {0.0, nan})}, "points[0].positions[1] is not finite"},
      {{at(1.0, {0.0, 0.0}, {0.0, INFINITY})}, "points[0].velocities[1] is not finite"},
      {{at(1.0, {0.0, 0.0}, {}, {0.0, 0.0})}, "points[0] has accelerations without velocities"},
      // Finite but absurd: their splines overflowed.
      {{at(1e300, {0.0, 0.0})}, "points[0].time_from_start must be finite and >= 0, at most 1e6 s"},
      {{at(1.0, {1e308, -1e308})}, "points[0].positions[0] is absurd"},
      {{at(1.0, {0.0, 0.0}, {0.0, 1e5})}, "points[0].velocities[1] is absurd"},
      {{at(1.0, {0.0, 0.0}, {0.0, 0.0}, {1e300, 0.0})}, "points[0].accelerations[0] is absurd"},
  };
  for (const auto& c : cases) {
    const std::string problem = JointTrajectory::check(c.points, 2);
    EXPECT_EQ(problem.rfind(c.expected, 0), 0u) << problem;
  }
  EXPECT_EQ(JointTrajectory::check({at(0.0, {1.0, 2.0}, {0.0, 0.0}, {0.0, 0.0}), at(0.5, {1.0, 2.0})}, 2), "");
}

// A message names its joints in any order: its points' fields follow the
// controller's; a field of another length is left for check to name, and a
// refused order changes nothing.
TEST(JointTrajectory, OrderTrajectoryPutsTheNamesInTheControllersOrder) {
  const std::vector<std::string> joints = {"a", "b", "c"};
  std::vector<TrajectoryPoint> points = {at(1.0, {3.0, 1.0, 2.0}, {30.0, 10.0, 20.0}, {0.3, 0.1, 0.2}),
                                         at(2.0, {6.0, 4.0, 5.0}, {1.0})};
  ASSERT_EQ(orderTrajectory(joints, {"c", "a", "b"}, points), "");
  EXPECT_EQ(points[0].position, (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_EQ(points[0].velocity, (std::vector<double>{10.0, 20.0, 30.0}));
  EXPECT_EQ(points[0].acceleration, (std::vector<double>{0.1, 0.2, 0.3}));
  EXPECT_EQ(points[1].position, (std::vector<double>{4.0, 5.0, 6.0}));
  EXPECT_EQ(points[1].velocity, (std::vector<double>{1.0}));
  EXPECT_EQ(JointTrajectory::check(points, 3).rfind("points[1].velocities has 1 values for 3 joints", 0), 0u);
  const std::vector<TrajectoryPoint> before = {at(1.0, {1.0, 2.0, 3.0})};
  for (const auto& [names, expected] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"a", "b"}, "joint_names has 2 names; the controller's 3 joints must each be named once"},
           {{"a", "b", "d"}, "joint_names[2]: 'd' is not its joint"},
           {{"a", "b", "a"}, "joint_names[2]: 'a' twice"}}) {
    std::vector<TrajectoryPoint> refused = before;
    EXPECT_EQ(orderTrajectory(joints, names, refused), expected);
    EXPECT_EQ(refused[0].position, before[0].position);
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
