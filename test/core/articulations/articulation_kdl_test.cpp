// An articulation's dynamics against KDL (orocos_kdl, which nobody here
// wrote): random serial chains of 2–10 joints of all three types, skew axes,
// offset centres of mass and full inertia tensors, fixed base. The mass
// matrix (ChainDynParam::JntToMass), Coriolis and gravity terms
// (JntToCoriolis, JntToGravity) and inverse dynamics (ChainIdSolver_RNE),
// with and without external wrenches on the links, within 1e-10.
#include <gtest/gtest.h>

#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <random>

#include "articulation_models.h"
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

}  // namespace
}  // namespace rigid_body_sim::core
