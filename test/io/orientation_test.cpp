// The files' orientation conventions (include/rigid_body_sim/io/orientation.h).
#include "rigid_body_sim/io/orientation.h"

#include <gtest/gtest.h>

#include "../test_util.h"

namespace rigid_body_sim::test {
namespace {

TEST(Orientation, QuaternionsAreGivenXyzwAndRpyIsAboutFixedAxesXThenYThenZ) {
  const Quat q = io::quaternionFromXyzw(0.1, 0.2, 0.3, 0.9);
  EXPECT_EQ(q.w(), 0.9);
  EXPECT_EQ(q.x(), 0.1);
  // Roll then pitch then yaw about the fixed axes: R = Rz Ry Rx.
  const Vec3 rpy(0.3, -0.4, 1.2);
  const Quat expected = Quat(Eigen::AngleAxisd(1.2, Vec3::UnitZ())) * Quat(Eigen::AngleAxisd(-0.4, Vec3::UnitY())) *
                        Quat(Eigen::AngleAxisd(0.3, Vec3::UnitX()));
  EXPECT_LT(io::quaternionFromRpy(rpy).angularDistance(expected), 1e-15);
  EXPECT_LT((io::rpyFromQuaternion(io::quaternionFromRpy(rpy)) - rpy).norm(), 1e-14);  // and back
}

}  // namespace
}  // namespace rigid_body_sim::test
