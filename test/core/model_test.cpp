// Model validation: each bad value is refused with its field and value.
#include "rigid_body_sim/core/model.h"

#include <gtest/gtest.h>

#include <limits>

#include "../test_util.h"

namespace rigid_body_sim::test {
namespace {

core::ModelSpec good() { return spec(shippedBox(), 1e-3, Vec3(0, 0, -9.81)); }

void expectRefused(const core::ModelSpec& s, std::initializer_list<std::string> parts) {
  expectThrowsWith<std::invalid_argument>([&] { core::Model m(s); }, parts);
}

TEST(ModelValidation, AcceptsTheShippedBox) { EXPECT_NO_THROW(core::Model m(good())); }

TEST(ModelValidation, Mass) {
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    core::ModelSpec s = good();
    s.bodies[0].mass = bad;
    expectRefused(s, {"body 'box': mass = ", "must be finite and > 0 kg"});
  }
  core::ModelSpec s = good();
  s.bodies[0].mass = -2.5;
  expectRefused(s, {"mass = -2.5"});
}

TEST(ModelValidation, Inertia) {
  core::ModelSpec s = good();
  s.bodies[0].I_C_L = Vec3(1.0, 1.0, 3.0).asDiagonal();
  expectRefused(s, {"body 'box': inertia = (ixx=1, iyy=1, izz=3", "triangle inequality"});
  s.bodies[0].I_C_L = Vec3(1.0, 0.0, 1.0).asDiagonal();
  expectRefused(s, {"body 'box': inertia", "positive definite"});
  s.bodies[0].I_C_L(0, 2) = 0.5;
  expectRefused(s, {"body 'box': inertia", "symmetric"});
}

TEST(ModelValidation, CentreOfMass) {
  core::ModelSpec s = good();
  s.bodies[0].p_LC.x() = std::numeric_limits<double>::infinity();
  expectRefused(s, {"body 'box': centre of mass = [inf, 0, 0]", "finite"});
}

TEST(ModelValidation, TimeStep) {
  for (double bad : {0.0, -1e-3, std::numeric_limits<double>::quiet_NaN()}) {
    core::ModelSpec s = good();
    s.dt = bad;
    expectRefused(s, {"dt = ", "must be finite and > 0 s"});
  }
}

TEST(ModelValidation, Gravity) {
  core::ModelSpec s = good();
  s.gravity_W.z() = std::numeric_limits<double>::quiet_NaN();
  expectRefused(s, {"gravity = [0, 0, nan]", "must be finite"});
}

TEST(ModelValidation, Damping) {
  core::ModelSpec s = good();
  s.damping.linear_rate = -0.5;
  expectRefused(s, {"damping.linear = -0.5", ">= 0 1/s"});
  s = good();
  s.damping.angular_rate = std::numeric_limits<double>::infinity();
  expectRefused(s, {"damping.angular = inf"});
  s = good();
  s.damping.linear_drag = 2000.0;  // σ Δt / M = 2
  expectRefused(s, {"damping.linear_drag = 2000", "sigma*dt/mass = 2", "damping.linear"});
  s = good();
  s.damping.angular_drag = 10.0;  // σ Δt / I_min = 10·1e-3/0.0041667 = 2.4
  expectRefused(s, {"damping.angular_drag = 10", "sigma*dt/I_min"});
}

TEST(ModelValidation, NoBodies) {
  core::ModelSpec s = good();
  s.bodies.clear();
  expectRefused(s, {"bodies = []", "at least one body"});
}

TEST(Model, PrincipalFrameOfANonDiagonalInertia) {
  core::ModelSpec s = good();
  const Quat q(Eigen::AngleAxisd(0.4, Vec3::UnitZ()));
  const Mat3 R = q.toRotationMatrix();
  s.bodies[0].I_C_L = R * Vec3(0.1, 0.2, 0.25).asDiagonal() * R.transpose();
  const core::Model m(s);
  const Mat3 P = m.body(0).q_LB.toRotationMatrix();
  EXPECT_LT((P * m.body(0).inertia_B.asDiagonal() * P.transpose() - s.bodies[0].I_C_L).norm(), 1e-14);
}

}  // namespace
}  // namespace rigid_body_sim::test
