// An articulation's dynamics against KDL (orocos_kdl, which nobody here
// wrote): random serial chains of 2–10 joints of all three types, skew axes,
// offset centres of mass and full inertia tensors, fixed base. The mass
// matrix (ChainDynParam::JntToMass), Coriolis and gravity terms
// (JntToCoriolis, JntToGravity) and inverse dynamics (ChainIdSolver_RNE),
// with and without external wrenches on the links, within 1e-10.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <random>
#include <string>
#include <vector>

#include "articulation_models.h"
#include "lone_robot.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"

namespace rigid_body_sim::core {
namespace {

KDL::Vector kdl(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

KDL::Frame kdl(const Pose& X) {
  const Quat& q = X.rotation;
  return {KDL::Rotation::Quaternion(q.x(), q.y(), q.z(), q.w()), kdl(X.translation)};
}

/// The same chain for KDL: each segment's joint sits at the URDF joint
/// origin with its axis in the parent's axes (as kdl_parser builds it), its
/// tip is the child link's frame, and its inertia is given in that frame.
KDL::Chain kdlChain(const ArticulationModel& model) {
  KDL::Chain chain;
  for (int i = 1; i <= model.jointCount(); ++i) {
    const ArticulatedLink& link = model.links[i];
    const KDL::Frame origin = kdl(link.X_PJ);
    const KDL::Vector axis = origin.M * kdl(link.axis_J);
    const KDL::Joint::JointType type = link.type == JointType::Prismatic ? KDL::Joint::TransAxis : KDL::Joint::RotAxis;
    const Mat3& I = link.mass.I_C_F;
    const KDL::RigidBodyInertia inertia(link.mass.mass, kdl(link.mass.p_FC),
                                        KDL::RotationalInertia(I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)));
    chain.addSegment(KDL::Segment(link.name, KDL::Joint(link.joint, origin.p, axis, type), origin, inertia));
  }
  return chain;
}

KDL::JntArray kdl(const Eigen::VectorXd& x) {
  KDL::JntArray out(static_cast<unsigned>(x.size()));
  out.data = x;
  return out;
}

double relativeError(const Eigen::MatrixXd& got, const Eigen::MatrixXd& want) {
  return (got - want).cwiseAbs().maxCoeff() / std::max(1.0, want.cwiseAbs().maxCoeff());
}

TEST(ArticulationAgainstKdl, MassMatrixCoriolisGravityAndInverseDynamics) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  const Vec3 g_W(0.3, -0.2, -9.81);  // not along an axis, so no term hides
  int types_seen[3] = {0, 0, 0};
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 2 + trial % 9;
    const ArticulationModel model = test::randomTree(rng, n, true, true);
    for (int i = 1; i <= n; ++i) ++types_seen[static_cast<int>(model.links[i].type)];
    const KDL::Chain chain = kdlChain(model);
    ASSERT_EQ(chain.getNrOfJoints(), static_cast<unsigned>(n));
    ArticulationState state = restState(model);
    Eigen::VectorXd qdd(n);
    for (int j = 0; j < n; ++j) {
      state.q(j) = u(rng);
      state.v(j) = u(rng);
      qdd(j) = u(rng);
    }
    const ArticulationKinematics kin = kinematics(model, state);

    KDL::ChainDynParam dyn(chain, kdl(g_W));
    KDL::JntSpaceInertiaMatrix H(n);
    ASSERT_EQ(dyn.JntToMass(kdl(state.q), H), 0);
    EXPECT_LT(relativeError(massMatrix(model, kin), H.data), 1e-10) << "trial " << trial;

    KDL::JntArray coriolis(n), gravity(n);
    ASSERT_EQ(dyn.JntToCoriolis(kdl(state.q), kdl(state.v), coriolis), 0);
    ASSERT_EQ(dyn.JntToGravity(kdl(state.q), gravity), 0);
    ArticulationState still = state;
    still.v.setZero();
    const Eigen::VectorXd our_gravity = biasForces(model, kinematics(model, still), g_W);
    const Eigen::VectorXd our_coriolis = biasForces(model, kin, Vec3::Zero());
    EXPECT_LT(relativeError(our_gravity, gravity.data), 1e-10) << "trial " << trial;
    EXPECT_LT(relativeError(our_coriolis, coriolis.data), 1e-10) << "trial " << trial;

    KDL::ChainIdSolver_RNE rne(chain, kdl(g_W));
    KDL::JntArray torques(n);
    const KDL::Wrenches no_wrenches(chain.getNrOfSegments(), KDL::Wrench::Zero());
    ASSERT_EQ(rne.CartToJnt(kdl(state.q), kdl(state.v), kdl(qdd), no_wrenches, torques), 0);
    const Eigen::VectorXd tau = inverseDynamics(model, kin, qdd, g_W);
    EXPECT_LT(relativeError(tau, torques.data), 1e-10) << "trial " << trial;
    // Forward dynamics gives back the accelerations KDL's torques were for.
    EXPECT_LT(relativeError(forwardDynamics(model, state, torques.data, g_W), qdd), 1e-10) << "trial " << trial;
    // External wrenches on the links (each in its link's axes, moment about
    // its origin: KDL's f_ext on a segment's tip frame), as contacts and
    // applied wrenches will load a robot.
    KDL::Wrenches wrenches(chain.getNrOfSegments());
    std::vector<Vec6> wrench_L(model.links.size(), Vec6::Zero());
    for (int i = 1; i <= n; ++i) {
      const Vec3 force = test::randomVec(rng, 5.0), moment = test::randomVec(rng, 2.0);
      wrenches[i - 1] = KDL::Wrench(kdl(force), kdl(moment));
      wrench_L[i] << moment, force;
    }
    ASSERT_EQ(rne.CartToJnt(kdl(state.q), kdl(state.v), kdl(qdd), wrenches, torques), 0);
    EXPECT_LT(relativeError(inverseDynamics(model, kin, qdd, g_W, wrench_L), torques.data), 1e-10) << "trial " << trial;
  }
  for (const int seen : types_seen) EXPECT_GT(seen, 20);
}

/// Three continuous joints about skew axes, their frames turned, each link
/// with an offset centre of mass and a full inertia tensor.
ArticulationModel skewChain() {
  ArticulationModel model;
  model.fixed_base = true;
  ArticulatedLink world;
  world.name = "world";
  model.links.push_back(world);
  const Vec3 axes[3] = {Vec3(0.2, 1.0, 0.1), Vec3(1.0, 0.3, -0.2), Vec3(-0.1, 0.4, 1.0)};
  const Vec3 origins[3] = {Vec3(0.0, 0.0, 0.0), Vec3(0.1, 0.05, -0.4), Vec3(-0.05, 0.1, -0.35)};
  const Vec3 centres[3] = {Vec3(0.05, 0.02, -0.2), Vec3(0.03, -0.04, -0.18), Vec3(-0.02, 0.05, -0.15)};
  const double masses[3] = {2.0, 1.5, 1.0};
  Mat3 inertia;  // kg m² per kg: positive definite, no zero product
  inertia << 0.05, 0.004, -0.003, 0.004, 0.04, 0.002, -0.003, 0.002, 0.02;
  for (int i = 0; i < 3; ++i) {
    ArticulatedLink link;
    link.name = "link" + std::to_string(i + 1);
    link.joint = "joint" + std::to_string(i + 1);
    link.parent = i;
    link.type = JointType::Continuous;
    link.X_PJ.translation = origins[i];
    link.X_PJ.rotation = Quat(Eigen::AngleAxisd(0.3 * (i + 1), Vec3(1.0, 1.0, 0.0).normalized()));
    link.axis_J = axes[i].normalized();
    link.mass.mass = masses[i];
    link.mass.p_FC = centres[i];
    link.mass.I_C_F = masses[i] * inertia;
    model.links.push_back(link);
  }
  return model;
}

/// KDL's motion of `chain` released at rest from q0 under g_W, at the
/// given times: q̈ = M⁻¹ (−C − G) from ChainDynParam, integrated by the
/// classical Runge-Kutta at 20 µs (its error, ~h⁴, is below 1e-12 rad).
std::vector<Eigen::VectorXd> kdlMotion(const KDL::Chain& chain, const Vec3& g_W, const Eigen::VectorXd& q0,
                                       const std::vector<int>& at_steps) {
  KDL::ChainDynParam dyn(chain, kdl(g_W));
  const int n = static_cast<int>(q0.size());
  const auto acceleration = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    KDL::JntSpaceInertiaMatrix M(n);
    KDL::JntArray coriolis(n), gravity(n);
    dyn.JntToMass(kdl(q), M);
    dyn.JntToCoriolis(kdl(q), kdl(v), coriolis);
    dyn.JntToGravity(kdl(q), gravity);
    return Eigen::VectorXd(M.data.llt().solve(-coriolis.data - gravity.data));
  };
  const double h = 2e-5;
  Eigen::VectorXd q = q0, v = Eigen::VectorXd::Zero(n);
  std::vector<Eigen::VectorXd> out;
  for (int step = 1, next = 0; next < static_cast<int>(at_steps.size()); ++step) {
    const Eigen::VectorXd a1 = acceleration(q, v);
    const Eigen::VectorXd v2 = v + 0.5 * h * a1, a2 = acceleration(q + 0.5 * h * v, v2);
    const Eigen::VectorXd v3 = v + 0.5 * h * a2, a3 = acceleration(q + 0.5 * h * v2, v3);
    const Eigen::VectorXd v4 = v + h * a3, a4 = acceleration(q + h * v3, v4);
    q += h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4);
    v += h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    if (step == at_steps[next]) {
      out.push_back(q);
      ++next;
    }
  }
  return out;
}

// The step's trajectories against KDL's dynamics (§11.5): the skew chain
// released at rest, its joints within 0.002 rad of KDL's at 0.5 s and 1 s
// at 1 ms, the error falling as h² between 2, 1 and 0.5 ms (measured
// order ≥ 1.9). The symplectic Euler step (the setting's other choice) is
// printed beside it.
TEST(ArticulationAgainstKdl, TheStepIsSecondOrderAlongKdlsTrajectory) {
  const ArticulationModel model = skewChain();
  const Vec3 g_W(0.3, -0.2, -9.81);
  Eigen::VectorXd q0(3);
  q0 << 0.3, -0.5, 0.8;
  const std::vector<Eigen::VectorXd> kdl_q = kdlMotion(kdlChain(model), g_W, q0, {25000, 50000});
  const auto errors = [&](double h, ArticulationIntegrator integrator) {
    ModelSpec spec;
    spec.articulation_integrator = integrator;
    test::LoneRobot alone(model, g_W, h, {}, spec);
    ArticulationState state = restState(model);
    state.q = q0;
    const int steps = static_cast<int>(std::lround(1.0 / h));
    std::array<double, 2> e{};
    for (int n = 1; n <= steps; ++n) {
      alone.step(state);
      if (2 * n == steps) e[0] = (state.q - kdl_q[0]).cwiseAbs().maxCoeff();
    }
    e[1] = (state.q - kdl_q[1]).cwiseAbs().maxCoeff();
    return e;
  };
  const std::array<double, 2> e2 = errors(2e-3, ArticulationIntegrator::kVerlet);
  const std::array<double, 2> e1 = errors(1e-3, ArticulationIntegrator::kVerlet);
  const std::array<double, 2> e05 = errors(5e-4, ArticulationIntegrator::kVerlet);
  const std::array<double, 2> euler = errors(1e-3, ArticulationIntegrator::kSymplecticEuler);
  std::printf(
      "skew chain against KDL, max |q - q_KDL| at 0.5 s / 1 s: 2 ms %.3g / %.3g, 1 ms %.3g / %.3g, "
      "0.5 ms %.3g / %.3g rad; symplectic Euler at 1 ms %.3g / %.3g\n",
      e2[0], e2[1], e1[0], e1[1], e05[0], e05[1], euler[0], euler[1]);
  EXPECT_LT(e1[0], 0.002);
  EXPECT_LT(e1[1], 0.002);
  for (int k = 0; k < 2; ++k) {
    const double order_coarse = std::log2(e2[k] / e1[k]), order_fine = std::log2(e1[k] / e05[k]);
    std::printf("  order at %s: %.3f (2 to 1 ms), %.3f (1 to 0.5 ms)\n", k == 0 ? "0.5 s" : "1 s", order_coarse,
                order_fine);
    EXPECT_GE(order_coarse, 1.9);
    EXPECT_GE(order_fine, 1.9);
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
