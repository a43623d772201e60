// Timed joint efforts (core/joint_effort_schedule.h): a window off the step
// grid delivers effort × duration, each step its share; clear and the end.
#include "rigid_body_sim/core/articulations/joint_effort_schedule.h"

#include <gtest/gtest.h>

namespace rigid_body_sim::core {
namespace {

constexpr double kH = 1e-3;

TEST(JointEffortSchedule, EachStepTakesItsShareOfTheWindow) {
  JointEffortSchedule s;
  s.add(0, 2, 4.0, 0.0005, 0.0025);  // robot 0's joint 2, 2 ms from half a step in
  s.add(1, 1, 9.0, 0.0, 1.0);        // another robot's: not robot 0's
  double delivered = 0.0;
  const double expected[] = {2.0, 4.0, 2.0, 0.0};
  for (int n = 0; n < 4; ++n) {
    Eigen::VectorXd effort = Eigen::VectorXd::Zero(2);
    s.addEfforts(0, n * kH, kH, effort);
    EXPECT_NEAR(effort(1), expected[n], 1e-12) << n;
    EXPECT_EQ(effort(0), 0.0);
    delivered += effort(1) * kH;
  }
  EXPECT_NEAR(delivered, 4.0 * 0.002, 1e-15);  // effort × duration
}

TEST(JointEffortSchedule, AWindowOnTheStepGridActsOnWholeStepsWhateverTheRounding) {
  // Starts and steps are n·kH, formed apart: (n − 1)·kH + kH is not always n·kH.
  for (long long n = 1; n < 100000; n += 3) {
    JointEffortSchedule s;
    s.add(0, 1, 5.0, static_cast<double>(n) * kH, static_cast<double>(n + 2) * kH);
    for (long long k = n - 1; k <= n + 2; ++k) {
      Eigen::VectorXd effort = Eigen::VectorXd::Zero(1);
      s.addEfforts(0, static_cast<double>(k) * kH, kH, effort);
      ASSERT_EQ(effort(0), k == n || k == n + 1 ? 5.0 : 0.0) << "n = " << n << ", step " << k;
    }
  }
}

TEST(JointEffortSchedule, UntilClearedAndDropped) {
  JointEffortSchedule s;
  s.add(0, 1, 1.0, 0.0);  // until cleared
  s.add(0, 1, 2.0, 0.0, 0.5);
  s.add(0, 2, 3.0, 0.0);
  s.dropFinished(0.5);  // the second ended
  EXPECT_EQ(s.size(), 2u);
  Eigen::VectorXd effort = Eigen::VectorXd::Zero(2);
  s.addEfforts(0, 100.0, kH, effort);
  EXPECT_EQ(effort(0), 1.0);
  EXPECT_EQ(effort(1), 3.0);
  EXPECT_EQ(s.clear(0, 1), 1u);
  EXPECT_EQ(s.clear(0, -1), 1u);  // every joint
  EXPECT_EQ(s.size(), 0u);
}

}  // namespace
}  // namespace rigid_body_sim::core
