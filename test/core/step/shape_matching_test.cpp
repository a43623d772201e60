#include "rigid_body_sim/core/step/shape_matching.h"

#include <gtest/gtest.h>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/step.h"

namespace rigid_body_sim::test {
namespace {

void expectProperRotation(const Mat3& R) {
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
  EXPECT_LT((R.transpose() * R - Mat3::Identity()).norm(), 1e-12);
}

TEST(Polar, RecoversAKnownRotationExactly) {
  const Mat3 R = Quat(Eigen::AngleAxisd(2.1, Vec3(0.3, -1, 0.5).normalized())).toRotationMatrix();
  Mat3 S;
  S << 1.2, 0.1, 0.0,  //
      0.1, 0.9, 0.2,   //
      0.0, 0.2, 1.5;   // symmetric positive definite: a stretch
  EXPECT_LT((core::polarRotation(R * S) - R).norm(), 1e-12);
  EXPECT_LT((core::polarRotation(R) - R).norm(), 1e-14);
}

TEST(Polar, ReflectedOrDegenerateInputStillGivesAProperRotation) {
  const Mat3 R = Quat(Eigen::AngleAxisd(0.8, Vec3::UnitX())).toRotationMatrix();
  const Mat3 mirror = Vec3(1, 1, -1).asDiagonal();
  expectProperRotation(core::polarRotation(R * mirror));                                 // det A < 0
  expectProperRotation(core::polarRotation(Vec3(1, 2, 0).asDiagonal()));                 // rank 2
  expectProperRotation(core::polarRotation(Vec3(1, 0, 0) * Vec3(0, 1, 1).transpose()));  // rank 1
  expectProperRotation(core::polarRotation(Mat3::Zero()));
}

TEST(ShapeMatching, FreeFlightIsTheRigidMotion) {
  // Without contact every vertex moves rigidly: the step is the rigid one.
  core::ContactSettings c;
  c.method = core::ContactMethod::kShapeMatching;
  core::ModelSpec ms = onGround(boxBody(Vec3(0.2, 0.1, 0.05)), c);
  const core::Model model(ms);
  core::LinkState link;
  link.p_WL = Vec3(0, 0, 5);
  link.v_WL = Vec3(1, 0, 2);
  core::State s = stateOf(model, link);
  for (int n = 0; n < 500; ++n) core::step(model, s);
  EXPECT_LT((s.bodies[0].p_WB - Vec3(0.5, 0, 5 + 1.0 - 0.5 * 9.81 * 0.25 - 0.5 * 9.81 * 1e-3 * 0.5)).norm(), 1e-9);
}

/// The box with the ground far below and gravity off: free flight.
core::ModelSpec shapeMatchingInTheAir(core::ContactMethod method) {
  core::ContactSettings c;
  c.method = method;
  core::ModelSpec ms = onGround(boxBody(Vec3(0.2, 0.1, 0.05)), c);
  ms.gravity_W = Vec3::Zero();
  return ms;
}

TEST(ShapeMatching, AppliesDragAsTheRigidStepDoes) {
  // Explicit drag on a body in free flight, gravity off: v_{n+1} = v_n (1 − σh/M).
  core::ModelSpec ms = shapeMatchingInTheAir(core::ContactMethod::kShapeMatching);
  ms.damping.linear_drag = 0.5;  // N·s/m on 1 kg
  const core::Model model(ms);
  core::LinkState link;
  link.p_WL = Vec3(0, 0, 50);
  link.v_WL = Vec3(2, 0, 0);
  core::State s = stateOf(model, link);
  for (int n = 0; n < 1000; ++n) core::step(model, s);
  EXPECT_NEAR(s.bodies[0].v_WB.x(), 2.0 * std::pow(1.0 - 0.5 * 1e-3 / model.body(0).mass, 1000), 1e-12);
}

TEST(ShapeMatching, TumblesWithTheGyroscopicTermAsTheImpulseMethodDoes) {
  // A box spinning near its intermediate axis flips (Dzhanibekov): without
  // the −ω × Iω term it would not. In free flight shape matching takes the
  // rigid step, so the two methods agree bit for bit.
  const core::Model sm(shapeMatchingInTheAir(core::ContactMethod::kShapeMatching));
  const core::Model im(shapeMatchingInTheAir(core::ContactMethod::kImpulse));
  core::LinkState link;
  link.p_WL = Vec3(0, 0, 100);
  link.w_W = Vec3(0.01, 3.0, 0.0);
  core::State a = stateOf(sm, link), b = stateOf(im, link);
  double lowest_wy = 3.0;
  for (int n = 0; n < 8000; ++n) {  // the first flip comes after about 3.4 s
    core::step(sm, a);
    core::step(im, b);
    ASSERT_EQ(a.bodies[0].q_WB.coeffs(), b.bodies[0].q_WB.coeffs()) << "step " << n;
    ASSERT_EQ(a.bodies[0].w_B, b.bodies[0].w_B) << "step " << n;
    lowest_wy = std::min(lowest_wy, a.bodies[0].w_B.y());  // about the body's own intermediate axis
  }
  EXPECT_LT(lowest_wy, -2.9);  // it flipped
}

TEST(ShapeMatching, DroppedBoxComesToRestOnTheGround) {
  core::ContactSettings c;
  c.method = core::ContactMethod::kShapeMatching;
  c.friction = 0.5;
  const core::Model model(onGround(boxBody(Vec3(0.2, 0.1, 0.05)), c));
  core::LinkState link;
  link.p_WL = Vec3(0, 0, 0.5);
  link.q_WL = Quat(Eigen::AngleAxisd(0.3, Vec3(1, 1, 0).normalized()));
  core::State s = stateOf(model, link);
  core::Workspace ws;
  double deepest = 0.0;
  for (int n = 0; n < 5000; ++n) {
    core::step(model, s, {}, &ws);
    deepest = std::max(deepest, ws.deepest_penetration);
  }
  EXPECT_TRUE(core::atRest(model, s.bodies[0]));
  EXPECT_LT(deepest, 2e-3);
  const Mat3 R = s.bodies[0].q_WB.toRotationMatrix();
  EXPECT_GT(R.row(2).cwiseAbs().maxCoeff(), std::cos(2 * M_PI / 180));  // on a face
}

}  // namespace
}  // namespace rigid_body_sim::test
